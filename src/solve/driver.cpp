#include "solve/driver.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>

#include "bimdf/flow.hpp"
#include "bimdf/solve.hpp"
#include "core/stopwatch.hpp"
#include "reduce/components.hpp"

namespace bimdf::detail {
namespace {

std::string describe_proof(const InfeasibilityProof& proof, const std::vector<int>& edge_original,
                           const std::vector<int>& node_original) {
  using Kind = InfeasibilityProof::Kind;
  const std::string component = "the component containing node " + std::to_string(node_original[0]);
  switch (proof.kind) {
    case Kind::OddParity: {
      const std::string where = proof.node < 0
                                    ? std::string("the set of nodes with outer edges")
                                    : "node " + std::to_string(node_original[proof.node]);
      return "parity: " + where +
             " belongs to a set of nodes whose total demand must be changed by an odd amount, "
             "but every edge that can carry a different flow changes it by an even amount";
    }
    case Kind::EmptyChain:
      return "chain: edge " + std::to_string(edge_original[proof.edge]) +
             " lies on a chain of nodes with demand 0 that forces equal flow on all its edges, "
             "and the bounds of those edges do not intersect";
    case Kind::Relaxation:
      return "relaxation: the LP relaxation of " + component +
             " is infeasible: its demands cannot be met within the bounds even fractionally";
    case Kind::PhaseOne:
      return "phase 1: " + component +
             " has no flow: exact phase-1 refinement could not remove the artificial flow "
             "needed to meet its demands within the bounds";
    case Kind::None:
      break;
  }
  return "unknown";
}

}  // namespace

Solution solve_problem(const Problem& problem, const SolverConfig& config) {
  const auto start = std::chrono::steady_clock::now();
  Solution solution;
  auto& stats = solution.stats;

  const ComponentSplit split = split_components(problem);
  const int parts = static_cast<int>(split.parts.size());
  std::vector<std::vector<int>> edge_original(parts), node_original(parts);
  for (int e = 0; e < problem.num_edges(); ++e) edge_original[split.part_of_edge[e]].push_back(e);
  for (int v = 0; v < problem.num_nodes(); ++v) node_original[split.part_of_node[v]].push_back(v);

  // Largest components first, so that the last ones to finish are short.
  std::vector<int> order(parts);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return split.parts[a].num_edges() > split.parts[b].num_edges();
  });
  std::vector<ComponentResult> results(parts);
  std::vector<std::exception_ptr> errors(parts);
  std::atomic<int> next{0};
  // Progress calls are serialized. The first exception a callback throws cancels the solve: it
  // is what run() throws, no call follows it, and every component still running stops at its
  // next report (by a Cancelled exception, dropped below) and none begins.
  struct Cancelled {};
  std::mutex progress_mutex;
  std::exception_ptr cancellation;
  std::atomic<bool> cancelled{false};
  auto worker = [&] {
    for (int i = next++; i < parts && !cancelled; i = next++) {
      const int k = order[i];
      ComponentConfig c = config.component;
      c.refine.time_limit_s = config.time_limit_s - seconds_since(start);
      if (config.progress)
        c.progress = [&, i](const SolveProgress& event) {
          SolveProgress report = event;
          report.component = i;
          report.components = parts;
          const std::lock_guard<std::mutex> lock(progress_mutex);
          if (cancelled) throw Cancelled{};
          report.elapsed_s = seconds_since(start);
          try {
            config.progress(report);
          } catch (...) {
            cancellation = std::current_exception();
            cancelled = true;
            throw Cancelled{};
          }
        };
      try {
        results[k] = solve_component(split.parts[k], c);
      } catch (const Cancelled&) {
        // run() throws `cancellation` once the workers are done
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  const int threads = std::max(1, std::min(config.threads, parts));
  if (threads == 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
  }
  if (cancellation) std::rethrow_exception(cancellation);
  for (int k = 0; k < parts; ++k) {
    if (!errors[k]) continue;
    try {
      std::rethrow_exception(errors[k]);
    } catch (const SolverError& e) {
      throw SolverError("component containing node " + std::to_string(node_original[k][0]) + ": " +
                        e.what());
    }
  }

  // Merge, in component order so that statistics do not depend on the thread count.
  std::map<std::string, int> paths;
  std::set<std::string> uncovered_paths;
  int64_t attempts = 0, nodes_solved = 0, edges_solved = 0, rounds = 0, rounds_max = 0,
          matchings = 0;
  int64_t matching_nodes = 0, matching_edges = 0, matching_free_vertices = 0, lemon_fallbacks = 0,
          resumed_matchings = 0, persistent_fallbacks = 0;
  MinCostFlowTally min_cost_flows;
  double approximate_objective = 0, lower_bound = 0;
  double t_simplify = 0, t_lp_guess = 0, t_parity = 0, t_linearize = 0, t_mcf = 0, t_build = 0,
         t_pruning = 0, t_matching = 0, t_bound = 0;
  solution.status = SolveStatus::Optimal;
  std::vector<std::vector<int64_t>> flows(parts);
  for (int k = 0; k < parts; ++k) {
    ComponentResult& c = results[k];
    attempts += c.attempts;
    nodes_solved += c.nodes_solved;
    edges_solved += c.edges_solved;
    rounds += c.rounds;
    rounds_max = std::max(rounds_max, c.rounds);
    matchings += c.matchings;
    matching_nodes = std::max(matching_nodes, c.matching_nodes);
    matching_edges = std::max(matching_edges, c.matching_edges);
    matching_free_vertices += c.matching_free_vertices;
    lemon_fallbacks += c.lemon_fallbacks;
    resumed_matchings += c.resumed_matchings;
    persistent_fallbacks += c.persistent_fallbacks;
    min_cost_flows.add(c.min_cost_flows);
    t_simplify += c.time_simplify_s;
    t_lp_guess += c.time_lp_guess_s;
    t_parity += c.time_parity_s;
    t_linearize += c.time_linearize_s;
    t_mcf += c.time_mcf_s;
    t_build += c.time_refine_build_s;
    t_pruning += c.time_pruning_s;
    t_matching += c.time_matching_s;
    t_bound += c.time_lower_bound_s;
    if (c.status == SolveStatus::Infeasible) {
      if (solution.status != SolveStatus::Infeasible)
        stats["infeasible_reason"] = describe_proof(c.proof, edge_original[k], node_original[k]);
      solution.status = SolveStatus::Infeasible;
      continue;
    }
    if (c.status == SolveStatus::Feasible && solution.status == SolveStatus::Optimal)
      solution.status = SolveStatus::Feasible;
    ++paths[c.path];
    // A component that took no double cover (a dedicated algorithm solved it) fell back from
    // nothing.
    if (c.attempts == 0) uncovered_paths.insert(c.path);
    approximate_objective += c.approximate_objective;
    lower_bound += c.lower_bound;
    flows[k] = std::move(c.flow);
  }

  const auto& cc = config.component;
  stats["components"] = int64_t{parts};
  stats["threads"] = int64_t{threads};
  stats["nodes_solved"] = nodes_solved;
  stats["edges_solved"] = edges_solved;
  stats["double_covers_solved"] = attempts;
  stats["time_simplify_s"] = t_simplify;
  stats["time_lp_guess_s"] = t_lp_guess;
  stats["time_parity_s"] = t_parity;
  stats["time_linearize_s"] = t_linearize;
  stats["time_min_cost_flow_s"] = t_mcf;
  std::string path_text;
  int64_t fallbacks = 0;
  const std::string primary =
      parity_mode_name(cc.approximate.parity) + "+" + cover_kind_name(cc.approximate.cover);
  for (const auto& [path, count] : paths) {
    path_text += (path_text.empty() ? "" : ", ") + path + " (" + std::to_string(count) +
                 (count == 1 ? " component)" : " components)");
    if (path != primary && !uncovered_paths.count(path)) fallbacks += count;
  }
  stats["approximation_path"] = path_text;
  stats["fallbacks"] = fallbacks;
  stats["min_cost_flows_cold"] = min_cost_flows.cold;
  stats["min_cost_flows_warm"] = min_cost_flows.warm;
  stats["min_cost_flows_warm_abandoned"] = min_cost_flows.warm_abandoned;
  if (cc.exact) {
    stats["refinement_rounds"] = rounds;
    stats["refinement_rounds_max"] = rounds_max;
    stats["matchings_solved"] = matchings;
    stats["matching_nodes_max"] = matching_nodes;
    stats["matching_edges_max"] = matching_edges;
    stats["matching_free_after_warm_start"] = matching_free_vertices;
    stats["matching_lemon_fallbacks"] = lemon_fallbacks;
    stats["matchings_resumed"] = resumed_matchings;
    stats["matching_persistent_fallbacks"] = persistent_fallbacks;
    stats["time_refine_build_s"] = t_build;
    stats["time_pruning_s"] = t_pruning;
    stats["time_matching_s"] = t_matching;
  }

  if (solution.status == SolveStatus::Infeasible) {
    solution.objective = std::numeric_limits<double>::quiet_NaN();
  } else {
    solution.flow = split.lift(flows);
    const FlowCheck check = check_flow(problem, solution.flow);
    if (!check.feasible())
      throw SolverError("internal error: the computed flow violates " +
                        std::to_string(check.bound_violations.size()) + " bounds and " +
                        std::to_string(check.conservation_violations.size()) +
                        " conservation constraints");
    solution.objective = check.objective;
    stats["approximate_objective"] = approximate_objective;
    if (cc.lower_bound) {
      stats["lower_bound"] = lower_bound;
      stats["relative_gap"] =
          (solution.objective - lower_bound) / std::max(std::fabs(solution.objective), 1e-9);
      stats["time_lower_bound_s"] = t_bound;
    }
  }
  stats["time_total_s"] = seconds_since(start);
  return solution;
}

}  // namespace bimdf::detail
