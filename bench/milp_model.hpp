// A Bi-MDF problem as a mixed-integer linear program solved by CBC (coinor-libcbc): the test
// oracle for problems of up to a few hundred edges, sharing no code or idea with the solvers,
// and the generic-solver baseline of the benchmarks (with a time limit). Each edge's
// convex cost becomes an epigraph variable t_e ≥ c(k) + (c(k+1) − c(k))·(x_e − k) for every
// integer k of its (windowed) range — exact at integers by convexity — and conservation rows
// are equalities. Infinite bounds are replaced by a window; `window_binding` reports whether
// the oracle's flow touches it (then the true optimum may lie outside).
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::testing {

struct MilpResult {
  bool feasible = false;
  bool proven = true;    // false: the time limit stopped CBC (objective: best found, if any)
  double objective = 0;  // Σ c(x) recomputed in double from the integer flow
  std::vector<int64_t> flow;
  int64_t window_lower = 0, window_upper = 0;  // the window used for infinite bounds
};

// Infinite bounds become [window_lower, window_upper]. With `radius` > 0 an edge whose cost
// needs more than 2·radius+1 pieces over that range (a curved cost) is limited to its cost's
// minimizer ± radius (the benchmark baseline: real instances are too large otherwise). With
// `time_limit_s` > 0 CBC stops there and reports the best flow found (proven = false); without it,
// a result that CBC cannot prove optimal throws std::runtime_error.
MilpResult solve_milp(const Problem& problem, int64_t window_lower = -40, int64_t window_upper = 60,
                      double time_limit_s = 0, int64_t radius = 0);

}  // namespace bimdf::testing
