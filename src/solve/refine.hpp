// Exact iterative refinement (paper §3.7–3.9). From a feasible flow x, one round linearizes the
// costs around x with unit pieces up to deviation 2 in each direction (the residual Bi-MCF,
// zero demands) and looks for its cheapest circulation. First the residual's LP relaxation
// (residual_pruning.hpp): optimum 0 ends the loop at once, an integral optimum is applied as
// it is, and otherwise its duals fix at 0 every arc no improving circulation can use. Only the
// remaining arcs go to the paper's reduction: a perfect b-matching with throughflow limit 2
// (bmatching.hpp), then a perfect matching (matching_gadgets.hpp) solved by our blossom
// solver warm-started from the LP's duals and integral flow (or by LEMON from scratch), whose
// circulation is applied. A round that does not lower the true objective — recomputed in
// double from the integer flow — ends the loop: by the paper's Theorem 3.8 no improving
// circulation of any size then exists, so x is optimal (up to the integer scaling of costs,
// min_cost_flow.hpp, for costs that differ by less than its resolution).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "backend/min_cost_flow.hpp"
#include "bimdf/problem.hpp"
#include "bimdf/solve.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/linearize.hpp"
#include "reduce/matching_gadgets.hpp"

namespace bimdf::detail {

struct RefineOptions {
  MatchingBackend matching = MatchingBackend::Blossom;
  int64_t max_rounds = std::numeric_limits<int64_t>::max();
  double time_limit_s = std::numeric_limits<double>::infinity();
  // Throughflow limits above 2 at hubs, in tiers (bmatching.hpp: refinement_throughflow), and
  // windows that widen where a round used all of one (refine.cpp: RefinementWindows); false:
  // K = 2 at every node and U = 2 on every edge, the paper's rounds (for comparisons). Exact
  // either way.
  bool hub_throughflow = true;
  // Called at the end of every round with the rounds done, the objective of the problem's
  // current flow, and whether the round lowered it (false: the last round, which proves the
  // flow optimal). Not called when a limit stops refinement.
  std::function<void(int64_t rounds, double objective, bool improved)> on_round;
};

struct RefineResult {
  std::vector<int64_t> flow;
  double objective = 0;
  int64_t rounds = 0;      // residual problems examined (the last one finds no improvement)
  int64_t matchings = 0;   // of them, those that needed a perfect matching
  bool converged = false;  // false: stopped by max_rounds or time_limit_s
  double time_build_s = 0, time_pruning_s = 0, time_matching_s = 0;
  int64_t matching_nodes = 0, matching_edges = 0;  // of the largest round
  int64_t matching_free_vertices = 0;  // vertices the warm start left free, summed over rounds
  int max_throughflow = 0;             // the largest throughflow limit of any round's b-matching
  int64_t widened_windows = 0;         // edges whose window a round widened, counted per round
  int64_t lemon_fallbacks = 0;    // rounds our solver left to LEMON (weights too large, or a bug)
  int64_t resumed_matchings = 0;  // matchings started from the previous round's (persistent)
  int64_t persistent_fallbacks = 0;  // persistent rounds that handed over to fresh ones
  MinCostFlowTally lps;              // how the rounds' LPs were solved
};

// The residual pieces of every refinement round: unit pieces up to deviation U = 2 each way,
// no tails (paper §3.9; linearize.hpp). Persistent rounds price their slots the same way.
LinearizeOptions refinement_pieces();

// A round's matching weight w in the blossom solver's integers: 2·llround(w·S), with S the
// cost scale of the round's LP (residual_pruning.hpp), so that the LP's integer duals carry
// over exactly and the gadgets' half units stay integral. Throws std::invalid_argument when
// w·S leaves ±2^61 (the solver's own bound is lower; its callers fall back).
inline int64_t doubled_matching_weight(double w, double cost_scale) {
  const double scaled = w * cost_scale;
  if (!(std::fabs(scaled) < 0x1p61))
    throw std::invalid_argument("refinement: a matching weight beyond the cost scale");
  return 2 * static_cast<int64_t>(std::llround(scaled));
}

// doubled_matching_weight of every weight in `weights` (a matching graph's or a b-matching's).
std::vector<int64_t> doubled_matching_weights(std::span<const double> weights, double cost_scale);

// The blossom solver's start duals for a round's matching: the LP's node dual d(v)
// (`node_dual`) on v's b-nodes, +d(v) on its heads side and −d(v) on its tails side (a tier's
// parts too, bmatching.hpp: side_of_bnode), spread over the gadgets by gadget_duals. A tier's
// weight-0 edges between the sides are then tight. No conversion is needed: the two
// arcs of a b-edge's relaxation double cover have reduced costs that add up to 2·c·S less the
// b-node duals at its ends, so these are already in the doubled weights' unit (1/S).
std::vector<int64_t> round_matching_duals(const BMatchingReduction& bmatching,
                                          const MatchingReduction& reduction,
                                          std::span<const int64_t> node_dual,
                                          std::span<const int64_t> bedge_weight);

// Requires a problem without outer edges and a flow feasible for it. Throws std::logic_error if
// a round's matching has no perfect matching (the zero circulation always is one: a bug).
// `start_potential` (per double-cover node v⁺ = 2v, v⁻ = 2v + 1, in units of cost; may be
// empty) warm-starts the first round's LP: the approximation's last cover gives them, and each
// later round starts from the previous round's LP (min_cost_flow.hpp).
RefineResult refine(const Problem& problem, std::vector<int64_t> flow,
                    const RefineOptions& options = {}, std::vector<double> start_potential = {});

}  // namespace bimdf::detail
