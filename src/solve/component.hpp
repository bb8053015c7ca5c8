// Solving one connected component: simplify (simplify.hpp), approximate (approximate.hpp),
// optionally refine to the optimum (refine.hpp) and bound it from below (lower_bound.hpp), then
// lift the flow back to the component. Internal: driver.hpp runs it on every component.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "solve/approximate.hpp"
#include "solve/refine.hpp"

namespace bimdf::detail {

struct ComponentConfig {
  bool collapse_chains = true;
  ApproximateOptions approximate;
  bool exact = false;        // refine the approximation to the optimum
  RefineOptions refine;      // round and time limits of the refinement
  bool lower_bound = false;  // compute the relaxation's lower bound
  // Told of the approximation and of each refinement round (event, round, objective and
  // improved filled in; the caller adds the rest). May be empty.
  std::function<void(const SolveProgress&)> progress;
};

struct ComponentResult {
  SolveStatus status = SolveStatus::Infeasible;  // Optimal, Feasible or Infeasible
  std::vector<int64_t> flow;                     // the component's edges
  InfeasibilityProof proof;                      // component ids (node −1: the boundary)
  std::string path;                              // of the approximation
  double approximate_objective = 0;              // Σ cost of the approximation's flow
  double lower_bound = 0;
  int64_t rounds = 0, matchings = 0;
  int nodes_solved = 0, edges_solved = 0;
  int attempts = 0;
  int64_t matching_nodes = 0, matching_edges = 0;
  int64_t matching_free_vertices = 0, lemon_fallbacks = 0;  // refine.hpp
  int64_t resumed_matchings = 0, persistent_fallbacks = 0;  // refine.hpp
  MinCostFlowTally min_cost_flows;  // of the approximation and refinement's LPs
  double time_simplify_s = 0, time_lp_guess_s = 0, time_parity_s = 0, time_linearize_s = 0,
         time_mcf_s = 0;
  double time_refine_build_s = 0, time_pruning_s = 0, time_matching_s = 0, time_lower_bound_s = 0;
};

ComponentResult solve_component(const Problem& component, const ComponentConfig& config);

}  // namespace bimdf::detail
