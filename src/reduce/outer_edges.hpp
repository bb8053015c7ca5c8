// Eliminating outer edges (paper §3.2.1). Every outer edge gets a head at a new boundary node ∂,
// and ∂ gets a tail–tail loop with unbounded flow (−∞..∞) and zero cost, so ∂ absorbs any even
// amount. Why this is exact: for any flow, Σ_v b[v] ≡ Σ_outer x[e] (mod 2), because every
// two-ended edge adds an even amount to the sum of all node balances; so setting ∂'s demand to
// the parity of Σ_v b[v] lets the loop take (Σ_outer x − b[∂]) / 2 — an integer — for exactly
// the flows that were feasible before. The reduced problem has no outer edges; its flows lift
// back by dropping the loop (the last edge). Without outer edges the problem is returned as is.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct OuterEdgeElimination {
  Problem reduced;  // nodes 0..n−1 as before, then ∂; edges as before, then ∂'s loop
  int boundary_node = -1;  // −1 when the problem had no outer edge
  int num_original_edges = 0;

  std::vector<int64_t> lift(std::span<const int64_t> reduced_flow) const;
};

// Takes the problem by value: a caller done with it moves it in (solve/simplify.cpp), which
// saves a copy of every edge.
OuterEdgeElimination eliminate_outer_edges(Problem problem);

}  // namespace bimdf::detail
