// Linearizing a Bi-MDF around an integer guess g into a Bi-MCF (paper §3.5, §3.6.3). The flow
// is split as x = g + Σ forward pieces − Σ backward pieces; each piece is an arc of the Bi-MCF
// with lower bound 0, a capacity and a per-unit cost, and the residual demand is b − σ·g.
//
// Forward pieces of edge e sample its cost at g, g+s, g+2s, … (s = `step`) up to deviation D,
// the largest multiple of s not above `max_deviation` that the upper bound allows: piece k has
// capacity s and cost (c(g+ks) − c(g+(k−1)s))/s per unit, so the model is exact at every sample
// point, and convexity orders the pieces so that a min-cost flow fills them in turn. Beyond D a
// tail piece (when `tails`) keeps the whole feasible region: capacity u − g − D (unbounded if
// u = ∞) at the slope of the next step — exact at g+D+s — or, when less than one step remains,
// the secant to u. Backward pieces mirror this downwards, towards the lower bound (tail
// capacity g − l − D). Adjacent pieces with equal cost are merged (absolute deviation costs need
// only a few). An unbounded tail's cost is clamped at ≥ 0: the edge's cost attains its minimum
// on that half-line, so beyond it the true cost never decreases, and a negative unbounded arc
// could only make the min-cost flow unbounded.
//
// Backward pieces are the edge with both ends' head flags inverted, so that their flow enters
// the conservation constraints with the opposite sign.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"
#include "reduce/bimcf.hpp"

namespace bimdf::detail {

struct LinearizeOptions {
  int max_deviation = 5;  // U
  int step = 2;           // s: 2 for the double cover, 1 for exact refinement
  bool tails = true;      // keep the full feasible region with tail pieces beyond D
  // Tails that never over-estimate the cost at integers (for lower bounds, lower_bound.hpp):
  // the slope of the first step beyond D, c(g+D+1) − c(g+D) for step 1, on the whole tail —
  // by convexity that line stays below c — and on an unbounded tail whose slope is negative,
  // only up to the cost's minimizer m, then the slope c(m+1) − c(m) ≥ 0 from there.
  bool underestimating_tails = false;
  // U per edge, in place of max_deviation where not empty.
  std::span<const int> edge_max_deviation;
};

struct Linearization {
  BiMcf mcf;
  std::vector<int> arc_edge;          // Bi-MCF arc → Bi-MDF edge
  std::vector<int8_t> arc_direction;  // +1 forward piece, −1 backward piece
  std::vector<int64_t> guess;         // g

  // x = g + Σ forward − Σ backward arc flows.
  std::vector<int64_t> lift(std::span<const int64_t> arc_flow) const;
};

// The cost of edge e at deviation d ≥ 0 from g in `direction` (+1 up, −1 down): c(g ± d).
struct CostAlong {
  const Cost& cost;
  int64_t g;
  int direction;
  double operator()(int64_t d) const { return cost(g + direction * d); }
};

// How far edge e's flow may move from g in `direction` (+1 towards its upper bound, −1 towards
// its lower one): kInfinity when that bound is.
int64_t deviation_room(const Problem& problem, int e, int64_t g, int direction);

// The per-unit cost of the piece from deviation d to d + s: (c(g ± (d+s)) − c(g ± d)) / s. The
// price of every non-tail piece; refinement's persistent slots (persistent_rounds.cpp) use it
// too, so that both price a step alike.
inline double piece_cost(const CostAlong& at, int64_t d, int64_t s) {
  return (at(d + s) - at(d)) / static_cast<double>(s);
}

// Requires a problem without outer edges and g within bounds. Throws std::overflow_error if a
// residual demand leaves ±2^62.
Linearization linearize(const Problem& problem, std::span<const int64_t> guess,
                        const LinearizeOptions& options);

}  // namespace bimdf::detail
