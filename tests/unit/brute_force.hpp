// The brute-force oracle for tiny problems: enumerates every integer flow within bounds (an
// infinite bound is replaced by a window of ±`window`), so it shares no code or idea with the
// solvers. Exact for problems whose bounds are all finite and inside the window; otherwise it
// answers for the flows inside the window only (`exhaustive` says which).
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::testing {

struct BruteForceResult {
  bool feasible = false;
  double optimum = 0;         // when feasible
  std::vector<int64_t> flow;  // an optimal flow, when feasible
  bool exhaustive = true;     // every bound was finite and inside the window
  int64_t flows_checked = 0;
};

BruteForceResult brute_force(const Problem& problem, int64_t window = 24);

}  // namespace bimdf::testing
