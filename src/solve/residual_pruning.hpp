// Reduced-cost fixing for one exact refinement round (paper §3.7–3.9, made cheaper). The round
// looks for the cheapest circulation of the residual Bi-MCF (unit pieces around the current
// flow, zero demands); the paper solves a perfect matching over the whole residual for it. Its
// LP relaxation — the relaxation double cover (double_cover.hpp), a directed min-cost flow —
// bounds every integer circulation from below, and the LP's duals bound each arc separately:
// with optimal value z ≤ 0 (the zero circulation is feasible) and reduced costs r ≥ 0 on the
// directed copies the LP leaves empty, any integer circulation y with y_a ≥ 1 maps to a
// directed flow of cost 2·cost(y) ≥ z + Σ_copies r·(copy flow), copy flow = y_a (2·y_a for a
// ±2 loop, whose single copy carries twice its flow). When that bound is ≥ 0, no improving
// circulation uses arc a and it is fixed at 0. On refinement rounds close to the optimum z is
// tiny, so nearly every arc is fixed and the matching shrinks to the few nodes the remaining
// arcs touch. Two shortcuts come with the same LP: z = 0 proves that no improving circulation
// exists (Theorem 3.8's test without any matching), and an integral LP optimum is itself an
// optimal integer circulation.
//
// All of this is exact for the scaled integer costs (backend/min_cost_flow.hpp). So that no
// arc is fixed on the strength of rounding, the test carries a margin of one scaled unit per
// unit of residual capacity, an upper bound on the rounding error of any circulation.
//
// The LP also warm-starts the perfect matching that follows: its integer costs (scale S, with
// 2^lp_scale_log2(residual) in place of 2^60 so that the matching solver has headroom) and, per
// node v, d(v) = π(v⁻) − π(v⁺) from the double cover's potentials. A bidirected arc's two directed
// copies have reduced costs summing to 2c + σ_a·d(a) + σ_b·d(b) (σ = +1 at a head, −1 at a
// tail), so the b-matching duals σ·d/2 on the sides of each node make every arc the LP leaves
// empty feasible and every arc it uses tight (matching_gadgets.hpp: gadget_duals).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "backend/min_cost_flow.hpp"
#include "reduce/bimcf.hpp"

namespace bimdf::detail {

struct ResidualPruning {
  // The LP optimum is 0: no circulation, integer or not, lowers the cost.
  bool proves_optimal = false;
  // The LP optimum when it is integral and negative (per residual arc), else empty.
  std::vector<int64_t> integral_circulation;
  // The arcs not fixed at 0, as a Bi-MCF (zero demands) on the nodes they touch.
  BiMcf reduced;
  std::vector<int> arc_of;         // reduced arc → residual arc
  std::vector<int> residual_node;  // reduced node → residual node
  int64_t fixed_arcs = 0;
  // The LP's integer cost scale S, d(v) per node of `reduced` (in units of 1/S), and the LP's
  // flow per arc of `reduced`, doubled (2y: 1 where the LP splits a unit).
  double cost_scale = 1;
  std::vector<int64_t> node_dual;
  std::vector<int64_t> twice_flow;
  // The LP's optimal potentials per double-cover node (v⁺ = 2v, v⁻ = 2v + 1 of the residual),
  // in units of cost: the next round's LP starts from them (min_cost_flow.hpp).
  std::vector<double> potential;
  MinCostFlowMethod lp_method = MinCostFlowMethod::NetworkSimplex;  // how the LP was solved

  // A circulation of `reduced` as one of the residual (fixed arcs 0).
  std::vector<int64_t> lift(std::span<const int64_t> reduced_flow, int num_residual_arcs) const;
};

// The LP's cost bound 2^L (min_cost_flow.hpp: max |cost|·S ≤ 2^L / (LP nodes + 1)): 52, or
// less when the largest perfect matching this residual can lead to — 2K copies per node for
// its throughflow limit K (refinement_throughflow) and at most 2 gadget nodes per unit of arc
// capacity (bmatching.hpp, matching_gadgets.hpp) — would
// push the doubled integer costs past the blossom solver's bound |w|·(nodes + 1) < 2^58.
int lp_scale_log2(const BiMcf& residual, std::span<const int> min_throughflow = {});

// The residual's LP relaxation alone, for every node and arc (no fixing): what persistent
// refinement rounds (persistent_rounds.hpp) start their matching from. `residual` must have
// zero demands (std::invalid_argument otherwise) and finite capacities; std::logic_error if the
// LP is not optimal.
struct ResidualLp {
  bool proves_optimal = false;                // the LP optimum is 0
  std::vector<int64_t> integral_circulation;  // as in ResidualPruning
  double cost_scale = 1;
  std::vector<int64_t> node_dual;   // d(v) per residual node, units of 1/S
  std::vector<int64_t> twice_flow;  // 2y per residual arc
  std::vector<double> potential;    // per double-cover node, units of cost
  MinCostFlowMethod lp_method = MinCostFlowMethod::NetworkSimplex;
};
// `scale_log2` plays the role of lp_scale_log2(residual), which callers whose matching is
// larger than that bound assumes (or who want headroom) lower.
ResidualLp solve_residual_lp(const BiMcf& residual, const std::vector<double>& start_potential,
                             int scale_log2);

// `residual` must have zero demands and finite capacities. Throws std::logic_error if its LP
// relaxation is not optimal (the zero circulation is feasible and capacities are finite).
// `start_potential`, when not empty, are potentials per double-cover node to warm-start the LP
// from (a previous round's `potential`). `min_throughflow`, when not empty, are throughflow
// limits per node that the round's b-matching raises refinement_throughflow's to (and its
// parts' degrees, at tiered nodes), for the scale bound.
ResidualPruning prune_residual(const BiMcf& residual,
                               const std::vector<double>& start_potential = {},
                               std::span<const int> min_throughflow = {});

}  // namespace bimdf::detail
