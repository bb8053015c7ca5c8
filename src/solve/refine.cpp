#include "solve/refine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>

#include "backend/blossom_matching.hpp"
#include "backend/perfect_matching.hpp"
#include "bimdf/flow.hpp"
#include "core/deep_stack.hpp"
#include "core/stopwatch.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/linearize.hpp"
#include "reduce/matching_gadgets.hpp"
#include "solve/persistent_rounds.hpp"
#include "solve/residual_pruning.hpp"

namespace bimdf::detail {
namespace {

constexpr int kDeviation = 2;  // U = 2, paper §3.9 (the throughflow limits: bmatching.hpp)
constexpr int kMaxDeviation = 64;

// Windows that widen where a round used all of one. Any U ≥ 2 (and K ≥ 2) per edge keeps Thm
// 3.8, but an edge far from its optimum crawls towards it by U a round: on the generated
// 10^6-edge instance a loop at the border node 41 units off took a round for every 1–2 units.
// So an edge that moved by its whole window has it doubled (up to kMaxDeviation), and its ends
// get a throughflow limit of at least that (twice for a loop, which takes two units of its
// node per unit), in their parts too when they have tiers — otherwise the node would hold the
// edge back instead. Off (U = 2 everywhere) when `enabled` is false, the paper's rounds.
struct RefinementWindows {
  std::vector<int> deviation;    // U per edge
  std::vector<int> throughflow;  // K per node at least, for its widened edges
  const Problem& p;
  bool enabled;

  RefinementWindows(const Problem& problem, bool on)
      : deviation(problem.num_edges(), kDeviation),
        throughflow(problem.num_nodes(), 2),
        p(problem),
        enabled(on) {}

  // Returns how many windows it widened.
  int widen(std::span<const int64_t> flow, std::span<const int64_t> next) {
    int widened = 0;
    if (!enabled) return widened;
    for (int e = 0; e < p.num_edges(); ++e) {
      if (deviation[e] >= kMaxDeviation || std::abs(next[e] - flow[e]) < deviation[e]) continue;
      ++widened;
      deviation[e] *= 2;
      const int a = p.end_a[e].node, b = p.end_b[e].node;
      const int need = a == b ? 2 * deviation[e] : deviation[e];
      throughflow[a] = std::max(throughflow[a], need);
      throughflow[b] = std::max(throughflow[b], need);
    }
    return widened;
  }
};

// The round's perfect matching by our blossom solver, warm-started from the pruning LP: its
// integer costs (doubled) are the matching weights, so its duals carry over exactly (see
// residual_pruning.hpp and matching_gadgets.hpp). LEMON answers instead when asked to, when
// the input exceeds the solver's overflow bounds, and when the solver reports anything but an
// optimum (the all-slack matching always exists, so "no perfect matching" would be our bug) or
// fails an internal check; all but the first are counted in lemon_fallbacks.
std::optional<std::vector<char>> solve_round_matching(const BMatchingReduction& red,
                                                      const MatchingReduction& mm,
                                                      const ResidualPruning& pruned,
                                                      const RefineOptions& options,
                                                      RefineResult& r) {
  if (options.matching == MatchingBackend::Lemon) return max_weight_perfect_matching(mm.graph);
  const BMatching& bm = red.bmatching;
  const std::vector<int>& arc_of_edge = red.arc_of_edge;
  const MatchingGraph& g = mm.graph;
  // The LP's integral part: one unit on each reduced arc it fills (2y = 2); gadget_matching
  // uses it on capacitated b-edges only (uncapacitated ones get slack pairs).
  std::vector<int> used(bm.num_edges(), 0);
  for (int e = 0; e < bm.num_edges(); ++e)
    if (arc_of_edge[e] >= 0) used[e] = static_cast<int>(pruned.twice_flow[arc_of_edge[e]] / 2);
  try {
    const std::vector<int64_t> bedge_weight =
        doubled_matching_weights(bm.weight, pruned.cost_scale);
    BlossomMatching solver(g.num_nodes, g.end_a, g.end_b,
                           doubled_matching_weights(g.weight, pruned.cost_scale));
    solver.initial_duals(round_matching_duals(red, mm, pruned.node_dual, bedge_weight))
        .initial_matching(gadget_matching(bm, mm, used));
    // Augmenting through nested blossoms recurses once per nesting level below the path's
    // own (rotate_to): the same headroom as for LEMON (backend/perfect_matching.cpp).
    BlossomMatching::Status status = BlossomMatching::Status::NotRun;
    run_with_stack(matching_stack_bytes(g.num_nodes), [&] { status = solver.run(); });
    if (status == BlossomMatching::Status::Optimal) {
      r.matching_free_vertices += solver.free_after_start();
      return solver.matched_edges();
    }
  } catch (const std::logic_error&) {
    // Inputs beyond the overflow bounds (std::invalid_argument), or a broken invariant or
    // certificate: a bug of ours, never a wrong answer.
  }
  ++r.lemon_fallbacks;  // counted in the statistics; the tests require 0
  return max_weight_perfect_matching(mm.graph);
}

}  // namespace

std::vector<int64_t> doubled_matching_weights(std::span<const double> weights, double cost_scale) {
  std::vector<int64_t> doubled(weights.size());
  for (size_t k = 0; k < weights.size(); ++k)
    doubled[k] = doubled_matching_weight(weights[k], cost_scale);
  return doubled;
}

std::vector<int64_t> round_matching_duals(const BMatchingReduction& red,
                                          const MatchingReduction& mm,
                                          std::span<const int64_t> node_dual,
                                          std::span<const int64_t> bedge_weight) {
  const BMatching& bm = red.bmatching;
  std::vector<int64_t> bnode_dual(bm.num_nodes());
  for (int b = 0; b < bm.num_nodes(); ++b) {
    const int s = red.side_of_bnode[b];
    bnode_dual[b] = s % 2 == 0 ? node_dual[s / 2] : -node_dual[s / 2];
  }
  return gadget_duals(bm, mm, bnode_dual, bedge_weight);
}

RefineResult refine(const Problem& p, std::vector<int64_t> flow, const RefineOptions& options,
                    std::vector<double> start_potential) {
  const auto start = std::chrono::steady_clock::now();
  RefineResult r;
  r.flow = std::move(flow);
  r.objective = objective(p, r.flow);
  LinearizeOptions unit_pieces = refinement_pieces();
  RefinementWindows windows(p, options.hub_throughflow);
  // Strict improvement beyond rounding noise; otherwise x is optimal (Thm 3.8).
  auto improves = [&](double next_objective) {
    return next_objective < r.objective - 1e-12 * std::max(1.0, std::fabs(r.objective));
  };
  auto round_done = [&](bool improved) {
    if (options.on_round) options.on_round(r.rounds, r.objective, improved);
  };
  // The two ends of a round: no improving circulation (x is optimal; the caller returns r),
  // or `next`, which lowers the objective to `next_objective`, becomes x.
  auto proven_optimal = [&] {
    r.converged = true;
    round_done(false);
  };
  auto accept = [&](std::vector<int64_t> next, double next_objective) {
    r.flow = std::move(next);
    r.objective = next_objective;
    round_done(true);
  };
  std::vector<double> lp_potential = std::move(start_potential);
  std::optional<PersistentRounds> kept;
  if (options.matching == MatchingBackend::Persistent) kept.emplace(p, options.hub_throughflow);
  while (true) {
    if (r.rounds >= options.max_rounds || seconds_since(start) > options.time_limit_s) return r;
    if (kept) {
      std::optional<PersistentRound> round;
      try {
        round = kept->round(r.flow, lp_potential);
      } catch (const std::logic_error&) {
        // A weight beyond the solver's bound (or a bug of ours, never a wrong answer): this
        // and the later rounds are solved afresh.
        kept.reset();
        ++r.persistent_fallbacks;
        continue;
      }
      ++r.rounds;
      r.time_pruning_s += round->time_lp_s;
      r.time_build_s += round->time_build_s;
      r.time_matching_s += round->time_matching_s;
      if (round->lp_solved) {
        r.lps.add(round->lp_method);
        lp_potential = std::move(round->lp_potential);
      }
      if (round->proves_optimal) {
        proven_optimal();
        return r;
      }
      ++r.matchings;
      r.resumed_matchings += round->resumed;
      r.matching_free_vertices += round->free_vertices;
      r.matching_nodes = std::max(r.matching_nodes, round->matching_nodes);
      r.matching_edges = std::max(r.matching_edges, round->matching_edges);
      r.max_throughflow = std::max(r.max_throughflow, round->max_throughflow);
      const double next_objective = objective(p, round->next_flow);
      if (!improves(next_objective)) {
        proven_optimal();
        return r;
      }
      accept(std::move(round->next_flow), next_objective);
      continue;
    }
    auto t = std::chrono::steady_clock::now();
    unit_pieces.edge_max_deviation = windows.deviation;
    const Linearization lin = linearize(p, r.flow, unit_pieces);
    r.time_build_s += seconds_since(t);
    t = std::chrono::steady_clock::now();
    ResidualPruning pruned = prune_residual(lin.mcf, lp_potential, windows.throughflow);
    lp_potential = std::move(pruned.potential);
    r.lps.add(pruned.lp_method);
    r.time_pruning_s += seconds_since(t);
    ++r.rounds;
    if (pruned.proves_optimal) {
      proven_optimal();
      return r;
    }
    if (!pruned.integral_circulation.empty()) {
      std::vector<int64_t> next = lin.lift(pruned.integral_circulation);
      const double next_objective = objective(p, next);
      if (improves(next_objective)) {
        r.widened_windows += windows.widen(r.flow, next);
        accept(std::move(next), next_objective);
        continue;
      }
    }
    t = std::chrono::steady_clock::now();
    Throughflow throughflow;
    if (options.hub_throughflow) {
      // What the nodes' widened edges need (the windows are on only with hub_throughflow).
      std::vector<int> need(pruned.reduced.num_nodes());
      for (int v = 0; v < pruned.reduced.num_nodes(); ++v)
        need[v] = windows.throughflow[pruned.residual_node[v]];
      throughflow = refinement_throughflow(pruned.reduced, need);
    } else {
      throughflow.limit.assign(pruned.reduced.num_nodes(), 2);
    }
    for (int k : throughflow.limit) r.max_throughflow = std::max(r.max_throughflow, k);
    const BMatchingReduction bm = reduce_to_bmatching(pruned.reduced, throughflow);
    const MatchingReduction mm = reduce_to_perfect_matching(bm.bmatching);
    r.matching_nodes = std::max<int64_t>(r.matching_nodes, mm.graph.num_nodes);
    r.matching_edges = std::max<int64_t>(r.matching_edges, mm.graph.num_edges());
    r.time_build_s += seconds_since(t);
    t = std::chrono::steady_clock::now();
    const std::optional<std::vector<char>> matched =
        solve_round_matching(bm, mm, pruned, options, r);
    r.time_matching_s += seconds_since(t);
    ++r.matchings;
    if (!matched)
      throw std::logic_error("refinement: the residual matching has no perfect matching");
    t = std::chrono::steady_clock::now();
    const std::vector<int> values = mm.lift(*matched, bm.bmatching.num_edges());
    const std::vector<int64_t> reduced_flow = bm.lift(values, pruned.reduced.num_arcs());
    std::vector<int64_t> next = lin.lift(pruned.lift(reduced_flow, lin.mcf.num_arcs()));
    const double next_objective = objective(p, next);
    r.time_build_s += seconds_since(t);
    if (!improves(next_objective)) {
      proven_optimal();
      return r;
    }
    r.widened_windows += windows.widen(r.flow, next);
    accept(std::move(next), next_objective);
  }
}

LinearizeOptions refinement_pieces() {
  LinearizeOptions unit_pieces;
  unit_pieces.max_deviation = kDeviation;
  unit_pieces.step = 1;
  unit_pieces.tails = false;
  return unit_pieces;
}

}  // namespace bimdf::detail
