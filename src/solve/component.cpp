#include "solve/component.hpp"

#include <chrono>

#include "bimdf/flow.hpp"
#include "core/stopwatch.hpp"
#include "solve/lower_bound.hpp"
#include "solve/simplify.hpp"
#include "solve/special_structure.hpp"

namespace bimdf::detail {
ComponentResult solve_component(const Problem& component, const ComponentConfig& config) {
  ComponentResult r;
  auto t = std::chrono::steady_clock::now();
  const SimplifiedComponent simplified(component, config.collapse_chains);
  r.time_simplify_s = seconds_since(t);
  if (simplified.empty_chain_edge() >= 0) {
    r.proof = {InfeasibilityProof::Kind::EmptyChain, -1, simplified.empty_chain_edge()};
    return r;
  }
  const Problem& p = simplified.problem();
  r.nodes_solved = p.num_nodes();
  r.edges_solved = p.num_edges();

  // A component that a dedicated algorithm solves outright (a directed min-cost flow or a
  // perfect matching written as Bi-MDF) skips the double cover and refinement. Tried as given
  // (outer edges are sources and sinks of a directed flow, but their elimination adds a loop)
  // and simplified (fixed edges gone into the demands can leave a perfect matching).
  if (config.exact) {
    t = std::chrono::steady_clock::now();
    std::optional<SpecialStructureSolution> special = solve_special_structure(component);
    if (!special && (special = solve_special_structure(p)))
      special->flow = simplified.lift(std::move(special->flow));
    if (special) {
      r.time_mcf_s = seconds_since(t);
      r.path = special->path;
      r.status = SolveStatus::Optimal;
      r.flow = std::move(special->flow);
      r.approximate_objective = objective(component, r.flow);
      if (config.lower_bound) r.lower_bound = r.approximate_objective;
      // Reported as an approximation that one round proves optimal, as refinement would.
      r.rounds = 1;
      if (config.progress) {
        SolveProgress solved;
        solved.objective = r.approximate_objective;
        config.progress(solved);
        solved.event = SolveProgress::Event::RefinementRound;
        solved.round = 1;
        config.progress(solved);
      }
      return r;
    }
  }

  const bool unchained = config.approximate.unchained;
  ApproximateOutcome approx =
      approximate(unchained ? simplified.unchained_problem() : p, config.approximate);
  if (approx.status == SolveStatus::Feasible && unchained) {
    approx.flow = simplified.project_unchained(approx.flow);
    approx.potential = simplified.project_unchained_potential(approx.potential);
  }
  r.path = approx.path;
  r.min_cost_flows = approx.min_cost_flows;
  r.attempts = approx.attempts;
  r.time_lp_guess_s = approx.time_lp_guess_s;
  r.time_parity_s = approx.time_parity_s;
  r.time_linearize_s = approx.time_linearize_s;
  r.time_mcf_s = approx.time_mcf_s;
  if (approx.status == SolveStatus::Infeasible) {
    r.proof = approx.proof;
    if (r.proof.kind == InfeasibilityProof::Kind::OddParity)
      r.proof.node = simplified.component_node(r.proof.node, unchained);
    return r;
  }
  r.approximate_objective = objective(component, simplified.lift(approx.flow));
  std::vector<int64_t> flow = std::move(approx.flow);
  r.status = SolveStatus::Feasible;
  RefineOptions refine_options = config.refine;
  if (config.progress) {
    SolveProgress approximated;
    approximated.objective = r.approximate_objective;
    config.progress(approximated);
    // The simplified problem lacks the fixed edges and closed chain cycles, whose cost does
    // not change: the component's objective is the simplified one plus theirs.
    const double fixed_cost = r.approximate_objective - objective(p, flow);
    refine_options.on_round = [&config, fixed_cost](int64_t rounds, double obj, bool improved) {
      SolveProgress round;
      round.event = SolveProgress::Event::RefinementRound;
      round.round = rounds;
      round.objective = obj + fixed_cost;
      round.improved = improved;
      config.progress(round);
    };
  }
  if (config.exact) {
    RefineResult refined = refine(p, std::move(flow), refine_options, approx.potential);
    flow = std::move(refined.flow);
    r.rounds = refined.rounds;
    r.matchings = refined.matchings;
    r.time_pruning_s = refined.time_pruning_s;
    r.matching_nodes = refined.matching_nodes;
    r.matching_edges = refined.matching_edges;
    r.matching_free_vertices = refined.matching_free_vertices;
    r.lemon_fallbacks = refined.lemon_fallbacks;
    r.resumed_matchings = refined.resumed_matchings;
    r.persistent_fallbacks = refined.persistent_fallbacks;
    r.min_cost_flows.add(refined.lps);
    r.time_refine_build_s = refined.time_build_s;
    r.time_matching_s = refined.time_matching_s;
    if (refined.converged) r.status = SolveStatus::Optimal;
  }
  r.flow = simplified.lift(flow);
  if (config.lower_bound && r.status == SolveStatus::Optimal) {
    // Refinement proved the flow optimal: its cost is the best bound, and the LP is skipped.
    r.lower_bound = objective(component, r.flow);
  } else if (config.lower_bound) {
    t = std::chrono::steady_clock::now();
    // The simplified problem lacks the fixed edges and closed chain cycles, whose flow is
    // known: their cost is the difference between the two objectives.
    r.lower_bound =
        relaxation_lower_bound(p, flow) + objective(component, r.flow) - objective(p, flow);
    r.time_lower_bound_s = seconds_since(t);
  }
  return r;
}

}  // namespace bimdf::detail
