// Solving a whole problem: split it into connected components (components.hpp), solve each
// (component.hpp) — in parallel on `threads` workers, largest first, with results that do not
// depend on the thread count — merge the flows, verify the result against the original problem
// and collect statistics. Both public solvers (bimdf/solve.hpp) are thin layers over this.
#pragma once

#include <functional>
#include <limits>

#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"
#include "solve/component.hpp"

namespace bimdf::detail {

struct SolverConfig {
  ComponentConfig component;
  int threads = 1;
  // Wall-clock budget for the refinement of all components together; components that run out
  // keep their best flow (status Feasible).
  double time_limit_s = std::numeric_limits<double>::infinity();
  // Solver::progress: calls serialized, component numbers and elapsed time filled in.
  std::function<void(const SolveProgress&)> progress;
};

// Throws SolverError (bimdf/solve.hpp) on internal failures, std::overflow_error for values
// beyond 64-bit sums.
Solution solve_problem(const Problem& problem, const SolverConfig& config);

}  // namespace bimdf::detail
