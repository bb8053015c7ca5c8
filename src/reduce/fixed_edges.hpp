// Moving fixed edges (lower = upper) into the demands. A fixed edge's flow is known, so it only
// shifts the demand of its ends: b[v] −= σ(v,e)·lower[e] (twice for a loop). The reduced problem
// has the same nodes and the remaining edges; its flows lift back by re-inserting the fixed
// values. This keeps parity repair and linearization free of edges that cannot move (the
// reference implementation rejects them, ../shared/reference/libsatsuma.md §2.3).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct FixedEdgeElimination {
  Problem reduced;                 // solve/simplify.cpp moves it on to outer-edge elimination
  std::vector<int> original_edge;  // reduced edge → original edge
  std::vector<int> reduced_edge;   // original edge → reduced edge, or −1 when fixed
  std::vector<int64_t> fixed_flow; // original edge → its flow when fixed (else 0)

  std::vector<int64_t> lift(std::span<const int64_t> reduced_flow) const;
};

// Throws std::overflow_error if a shifted demand leaves ±2^62.
FixedEdgeElimination eliminate_fixed_edges(const Problem& problem);

}  // namespace bimdf::detail
