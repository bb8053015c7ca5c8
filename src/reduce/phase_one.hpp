// Phase 1: a problem that is always feasible and whose optimum is 0 exactly when the original
// problem is feasible. Every edge keeps its bounds but costs nothing; every node whose residual
// b − σ·g is non-zero gets an artificial loop (head–head for a positive residual, tail–tail
// for a negative one) with cost 1 per unit, so that g plus |residual|/2 on the loop is a
// feasible start (the residuals must be even: repair parity first). Refining that start exactly
// (refine.hpp) either drives every artificial loop to 0 — a feasible flow of the original — or
// proves that no such flow exists. This is the last resort of the approximation when no double
// cover is feasible (bimdf/solve.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct PhaseOne {
  Problem problem;               // the original edges (cost zero), then the artificial loops
  std::vector<int64_t> start;    // feasible for `problem`
  int num_original_edges = 0;

  // Total flow on artificial loops (0 iff the first num_original_edges values are feasible
  // for the original problem).
  int64_t artificial_flow(std::span<const int64_t> flow) const;
  std::vector<int64_t> lift(std::span<const int64_t> flow) const;
};

// Requires no outer edges, `guess` within bounds and b − σ·guess even at every node. Throws
// std::overflow_error if a residual leaves ±2^62.
PhaseOne build_phase_one(const Problem& problem, std::span<const int64_t> guess);

}  // namespace bimdf::detail
