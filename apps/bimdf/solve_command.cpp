#include "solve_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"

namespace bimdf::cli {
namespace {

std::string stat_text(const Solution& s, const std::string& key) {
  const auto it = s.stats.find(key);
  if (it == s.stats.end()) return "";
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) return v;
        else if constexpr (std::is_same_v<T, double>) return shortest_decimal(v);
        else return std::to_string(v);
      },
      it->second);
}

double stat_seconds(const Solution& s, const std::string& key) {
  const auto it = s.stats.find(key);
  return it == s.stats.end() ? 0 : std::get<double>(it->second);
}

std::string ms(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f ms", seconds * 1e3);
  return buf;
}

std::string human_report(const Solution& s, bool verbose) {
  std::string t;
  auto line = [&](const std::string& key, const std::string& value) {
    t += key + std::string(key.size() < 14 ? 14 - key.size() : 1, ' ') + value + "\n";
  };
  line("status", std::string(status_name(s.status)) +
                     (s.status == SolveStatus::Feasible ? " (approximation)" : ""));
  if (s.status == SolveStatus::Infeasible) {
    line("reason", stat_text(s, "infeasible_reason"));
  } else {
    line("objective", shortest_decimal(s.objective));
    line("path", stat_text(s, "approximation_path"));
  }
  line("time", ms(stat_seconds(s, "time_total_s")) + " (read " + ms(stat_seconds(s, "time_read_s")) +
                   ", solve " + ms(stat_seconds(s, "time_solve_s")) + ")");
  if (verbose) {
    line("components", stat_text(s, "components"));
    line("solved size", stat_text(s, "nodes_solved") + " nodes, " + stat_text(s, "edges_solved") +
                            " edges after simplification");
    line("stages", "simplify " + ms(stat_seconds(s, "time_simplify_s")) + ", parity " +
                       ms(stat_seconds(s, "time_parity_s")) + ", linearize " +
                       ms(stat_seconds(s, "time_linearize_s")) + ", min-cost flow " +
                       ms(stat_seconds(s, "time_min_cost_flow_s")));
    line("covers", stat_text(s, "double_covers_solved") + " solved, " + stat_text(s, "fallbacks") +
                       " components needed a fallback");
  }
  return t;
}

}  // namespace

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "solve", "Solve a problem: a verified integer flow and its objective (JSON solution)");
  cmd->add_option("PROBLEM", o.problem, "Problem file (.bimdf or .json)")->required();
  cmd->add_flag("--approx", o.approximate,
                "Fast approximation only (double cover, paper §3.6); required until the exact "
                "solver lands");
  cmd->add_option("--max-deviation", o.max_deviation,
                  "U: deviation from the guess modelled exactly at even points")
      ->default_val(5)
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--parity", o.parity, "Parity repair: tjoin (spanning-tree T-join) or round-to-even")
      ->default_val("tjoin")
      ->check(CLI::IsMember({"tjoin", "round-to-even"}));
  cmd->add_option("--cover", o.cover, "Double cover to start with: asymmetric or symmetric")
      ->default_val("asymmetric")
      ->check(CLI::IsMember({"asymmetric", "symmetric"}));
  cmd->add_flag("--no-simplify", o.no_simplify, "Do not collapse chains of pass-through nodes");
  cmd->add_flag("-v,--verbose", o.verbose, "Print sizes and the time of every stage");
  add_output_options(cmd, o.out);
  return cmd;
}

int run_solve(const SolveCommandOptions& o) {
  if (!o.approximate)
    throw UsageError{
        "the exact solver is not available yet in this version; pass --approx for the "
        "approximation"};
  const auto start = std::chrono::steady_clock::now();
  const Problem problem = read_problem_file(o.problem);
  const double read_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  ApproximateSolver solver(problem);
  solver.max_deviation(o.max_deviation)
      .parity_repair(o.parity == "tjoin" ? ParityRepairMode::SpanningTreeTJoin
                                         : ParityRepairMode::RoundToEven)
      .double_cover(o.cover == "asymmetric" ? DoubleCoverMode::Asymmetric
                                            : DoubleCoverMode::Symmetric)
      .collapse_chains(!o.no_simplify);
  const SolveStatus status = solver.run();
  Solution s = solver.solution();
  s.stats["time_read_s"] = read_s;
  s.stats["time_solve_s"] = std::get<double>(s.stats["time_total_s"]);
  s.stats["time_total_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.stats["solver"] = std::string("approximate");
  deliver(o.out, human_report(s, o.verbose), to_json_solution(s), {o.problem});
  return status == SolveStatus::Infeasible ? kNoSolution : kOk;
}

}  // namespace bimdf::cli
