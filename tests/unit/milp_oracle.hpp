// The MILP oracle for problems of up to a few hundred edges: the same problem as an integer
// program solved by CBC (coinor-libcbc), sharing no code or idea with the solvers. Each edge's
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
  double objective = 0;       // Σ c(x) recomputed in double from the integer flow
  std::vector<int64_t> flow;
  int64_t window_lower = 0, window_upper = 0;  // the window used for infinite bounds
};

MilpResult solve_milp(const Problem& problem, int64_t window_lower = -40,
                      int64_t window_upper = 60);

}  // namespace bimdf::testing
