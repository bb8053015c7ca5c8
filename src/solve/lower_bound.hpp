// A lower bound on the optimum (the certificate of bimdf/solve.hpp): the LP relaxation of the
// problem, which the double cover without halving solves exactly (double_cover.hpp, kind
// Relaxation; paper §3.6: its solutions are the half-integral points). Costs are linearized
// around `center` with unit pieces, exact at every integer within `max_deviation`, and tails
// that never over-estimate (linearize.hpp), so the LP's optimum is at most the integer optimum.
// The reference implementation's bound exceeds the optimum with self-loops because it gives a
// loop half its capacity in the relaxation (../shared/reference/libsatsuma.md §2.11); the
// relaxation cover here doubles it.
//
// The value is computed in double from the min-cost flow, minus a margin for the integer
// rounding of costs inside the solver (min_cost_flow.hpp); it is a bound up to that rounding
// (relative 1e-12 on real instances).
#pragma once

#include <cstdint>
#include <span>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

// Requires a simplified problem (no outer edges) and a center within bounds. −infinity if the
// relaxation is unbounded (impossible for validated problems), +infinity if it is infeasible.
double relaxation_lower_bound(const Problem& problem, std::span<const int64_t> center,
                              int max_deviation = 8);

}  // namespace bimdf::detail
