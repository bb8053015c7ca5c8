#include "solve_command.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>

#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"
#include "memory_setup.hpp"
#include "number_checks.hpp"

namespace bimdf::cli {
namespace {

std::string stat_text(const Solution& s, const std::string& key) {
  const auto it = s.stats.find(key);
  if (it == s.stats.end()) return "";
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          return v;
        else if constexpr (std::is_same_v<T, double>)
          return shortest_decimal(v);
        else
          return std::to_string(v);
      },
      it->second);
}

double stat_seconds(const Solution& s, const std::string& key) {
  const auto it = s.stats.find(key);
  return it == s.stats.end() ? 0 : std::get<double>(it->second);
}

// Peak resident memory of this process image in MiB (Linux VmHWM; 0 where unavailable). Unlike
// getrusage's ru_maxrss, it does not include what the parent held before exec.
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0;
}

// One line per progress event, on stderr (stdout carries the result), e.g.
//   progress 0.392 s: component 1 of 2: round 1, objective 27.443912861937058 (lowered)
void print_progress(const SolveProgress& p) {
  char head[96];
  std::snprintf(head, sizeof head, "progress %.3f s: component %d of %d: ", p.elapsed_s,
                p.component + 1, p.components);
  std::string what;
  if (p.event == SolveProgress::Event::Approximated)
    what = "approximation, objective " + shortest_decimal(p.objective);
  else
    what = "round " + std::to_string(p.round) + ", objective " + shortest_decimal(p.objective) +
           (p.improved ? " (lowered)" : " (no improvement: optimal)");
  std::cerr << head << what << std::endl;
}

std::string human_report(const Solution& s, bool exact, bool verbose) {
  std::string t;
  auto line = [&](const std::string& key, const std::string& value) {
    t += key + std::string(key.size() < 14 ? 14 - key.size() : 1, ' ') + value + "\n";
  };
  line("status", std::string(status_name(s.status)) +
                     (!exact && s.status == SolveStatus::Feasible ? " (approximation)" : ""));
  if (s.status == SolveStatus::Infeasible) {
    line("reason", stat_text(s, "infeasible_reason"));
  } else {
    line("objective", shortest_decimal(s.objective));
    if (exact) {
      line("approximation",
           stat_text(s, "approximate_objective") + " (" + stat_text(s, "approximation_path") + ")");
      // Proven optimal: the bound is the objective itself, nothing to report.
      if (s.status != SolveStatus::Optimal && s.stats.count("lower_bound"))
        line("lower bound",
             stat_text(s, "lower_bound") + " (relative gap " + stat_text(s, "relative_gap") + ")");
      line("rounds", stat_text(s, "refinement_rounds") + " refinement rounds (at most " +
                         stat_text(s, "refinement_rounds_max") + " in one component), " +
                         stat_text(s, "matchings_solved") + " needed a matching");
    } else {
      line("path", stat_text(s, "approximation_path"));
    }
  }
  line("time", ms(stat_seconds(s, "time_total_s"), 3) + " (read " +
                   ms(stat_seconds(s, "time_read_s"), 3) + ", solve " +
                   ms(stat_seconds(s, "time_solve_s"), 3) + ")");
  if (s.status != SolveStatus::Infeasible) {
    const double approx_s = stat_seconds(s, "time_simplify_s") +
                            stat_seconds(s, "time_lp_guess_s") + stat_seconds(s, "time_parity_s") +
                            stat_seconds(s, "time_linearize_s") +
                            stat_seconds(s, "time_min_cost_flow_s");
    std::string stages = "approximation " + ms(approx_s, 3);
    if (exact)
      stages += ", refinement " +
                ms(stat_seconds(s, "time_refine_build_s") + stat_seconds(s, "time_pruning_s") +
                       stat_seconds(s, "time_matching_s"),
                   3) +
                " (matching " + ms(stat_seconds(s, "time_matching_s"), 3) + ")" +
                (s.status == SolveStatus::Optimal
                     ? ""
                     : ", lower bound " + ms(stat_seconds(s, "time_lower_bound_s"), 3));
    line("stages", stages);
  }
  if (verbose) {
    line("components", stat_text(s, "components") + " (" + stat_text(s, "threads") + " threads)");
    line("solved size", stat_text(s, "nodes_solved") + " nodes, " + stat_text(s, "edges_solved") +
                            " edges after simplification");
    std::string stages = "simplify " + ms(stat_seconds(s, "time_simplify_s"), 3) + ", LP guess " +
                         ms(stat_seconds(s, "time_lp_guess_s"), 3) + ", parity " +
                         ms(stat_seconds(s, "time_parity_s"), 3) + ", linearize " +
                         ms(stat_seconds(s, "time_linearize_s"), 3) + ", min-cost flow " +
                         ms(stat_seconds(s, "time_min_cost_flow_s"), 3);
    if (exact)
      stages += ", refinement build " + ms(stat_seconds(s, "time_refine_build_s"), 3) +
                ", pruning LP " + ms(stat_seconds(s, "time_pruning_s"), 3) + ", matching " +
                ms(stat_seconds(s, "time_matching_s"), 3) + ", lower bound " +
                ms(stat_seconds(s, "time_lower_bound_s"), 3);
    line("stage detail", stages + " (summed over components)");
    line("covers", stat_text(s, "double_covers_solved") + " solved, " + stat_text(s, "fallbacks") +
                       " components needed a fallback");
    line("flow solves", stat_text(s, "min_cost_flows_warm") + " warm-started (" +
                            stat_text(s, "min_cost_flows_warm_abandoned") +
                            " of them handed to the network simplex), " +
                            stat_text(s, "min_cost_flows_cold") + " from scratch");
    if (exact)
      line("matching",
           "largest " + stat_text(s, "matching_nodes_max") + " nodes, " +
               stat_text(s, "matching_edges_max") + " edges; " +
               stat_text(s, "matching_free_after_warm_start") +
               " vertices left free by the warm starts, " +
               stat_text(s, "matching_lemon_fallbacks") + " fallbacks to LEMON" +
               (stat_text(s, "matchings_resumed") != "0" ||
                        stat_text(s, "matching_persistent_fallbacks") != "0"
                    ? "; " + stat_text(s, "matchings_resumed") +
                          " resumed from the previous round's, " +
                          stat_text(s, "matching_persistent_fallbacks") + " persistent fallbacks"
                    : ""));
  }
  return t;
}

}  // namespace

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "solve", "Solve a problem: a verified integer flow and its objective (JSON solution)");
  cmd->add_option("PROBLEM", o.problem, "Problem file (.bimdf or .json)")->required();
  CLI::Option* approx =
      cmd->add_flag("--approx", o.approximate,
                    "Fast approximation only (double cover, paper §3.6) instead of the optimum");
  cmd->add_option("--max-deviation", o.max_deviation,
                  "U: deviation from the guess modelled exactly at even points")
      ->default_val(5)
      ->check(whole_number_from(0, 1000));
  cmd->add_option("--parity", o.parity,
                  "Parity repair: tjoin (spanning-tree T-join) or round-to-even")
      ->default_val("tjoin")
      ->check(CLI::IsMember({"tjoin", "round-to-even"}));
  cmd->add_option("--cover", o.cover, "Double cover to start with: asymmetric or symmetric")
      ->default_val("asymmetric")
      ->check(CLI::IsMember({"asymmetric", "symmetric"}));
  cmd->add_flag("--no-simplify", o.no_simplify, "Do not collapse chains of pass-through nodes");
  cmd->add_option("--threads", o.threads, "Worker threads for independent components")
      ->default_val(1)
      ->check(whole_number_from(1, 256));
  cmd->add_option("--max-rounds", o.max_rounds,
                  "Refinement rounds per component before returning the best flow as feasible")
      ->check(positive_whole_number());
  cmd->add_option("--time-limit", o.time_limit,
                  "Seconds before refinement stops and returns the best flow as feasible")
      ->check(positive_number());
  cmd->add_flag("--no-lower-bound", o.no_lower_bound, "Skip the LP-relaxation lower bound");
  add_matching_option(cmd, o.matching,
                      "Perfect matching solver of the refinement: blossom (bimdf's own, "
                      "warm-started), lemon (LEMON's, from scratch; a cross-check) or "
                      "persistent (experimental: one blossom matching kept across rounds; "
                      "slower so far)");
  cmd->add_flag("-v,--verbose", o.verbose, "Print sizes and the time of every stage");
  cmd->add_flag("--progress", o.progress,
                "Print a line on standard error after each component's approximation and each "
                "refinement round (exact solves)")
      ->excludes(approx);
  add_output_options(cmd, o.out);
  return cmd;
}

void add_matching_option(CLI::App* cmd, MatchingBackend& backend, const std::string& description) {
  cmd->add_option_function<std::string>(
         "--matching",
         [&backend](const std::string& name) {
           backend = name == "lemon"        ? MatchingBackend::Lemon
                     : name == "persistent" ? MatchingBackend::Persistent
                                            : MatchingBackend::Blossom;
         },
         description)
      ->check(CLI::IsMember({"blossom", "lemon", "persistent"}))
      ->default_str(backend == MatchingBackend::Blossom ? "blossom" : "lemon");
}

int run_solve(const SolveCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const HeapPrefault prefault(solve_heap_estimate(o.problem, !o.approximate));
  const Problem problem = read_problem_file(o.problem);
  const double read_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const ParityRepairMode parity =
      o.parity == "tjoin" ? ParityRepairMode::SpanningTreeTJoin : ParityRepairMode::RoundToEven;
  const DoubleCoverMode cover =
      o.cover == "asymmetric" ? DoubleCoverMode::Asymmetric : DoubleCoverMode::Symmetric;
  Solution s;
  if (o.approximate) {
    ApproximateSolver solver(problem);
    solver.max_deviation(o.max_deviation).parity_repair(parity).double_cover(cover);
    solver.collapse_chains(!o.no_simplify).run();
    s = solver.solution();
  } else {
    Solver solver(problem);
    solver.max_deviation(o.max_deviation).parity_repair(parity).double_cover(cover);
    solver.collapse_chains(!o.no_simplify).threads(o.threads).lower_bound(!o.no_lower_bound);
    if (o.max_rounds > 0) solver.max_rounds(o.max_rounds);
    if (o.time_limit > 0) solver.time_limit(o.time_limit);
    solver.matching(o.matching);
    if (o.progress) solver.progress(print_progress);
    solver.run();
    s = solver.solution();
  }
  s.stats["time_read_s"] = read_s;
  s.stats["time_solve_s"] = std::get<double>(s.stats["time_total_s"]);
  s.stats["time_total_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.stats["solver"] = std::string(o.approximate ? "approximate" : "exact");
  s.stats["peak_memory_mb"] = peak_memory_mb();
  deliver(o.out, human_report(s, !o.approximate, o.verbose), to_json_solution(s), {o.problem});
  return s.status == SolveStatus::Infeasible ? kNoSolution : kOk;
}

}  // namespace bimdf::cli
