// Collapsing chains of pass-through nodes (paper §3.10). A node with demand 0 and exactly two
// edge ends, one head and one tail, on two different edges forces both edges to carry the same
// flow. A maximal chain of such nodes with its edges e1..ek therefore becomes one edge between
// the chain's two terminal ends, with bounds [max lower, min upper] and cost Σ c_ei (a Sum, so
// every term stays exact). Terminal nodes keep their demands — the reference implementation
// drops them (../shared/reference/libsatsuma.md §2.9). A closed cycle of pass-through nodes has
// no terminal: its common flow is free within the intersected bounds, so it is fixed here at
// the cost's minimizer and needs no edge at all.
//
// Collapsing may prove the problem infeasible: if a chain's bounds do not intersect, no flow
// exists. That case is reported through `empty_chain_edge`.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct ChainCollapse {
  Problem reduced;               // the non-pass-through nodes (renumbered) and one edge per chain
  std::vector<int> reduced_edge; // original edge → its chain's reduced edge, −1 on closed cycles
  std::vector<int> reduced_node; // original node → reduced node, −1 for pass-through nodes
  std::vector<int64_t> cycle_flow;  // original edge → its flow when on a closed cycle
  int collapsed_nodes = 0;
  // ≥ 0: an edge of a chain whose bounds do not intersect (the problem is infeasible).
  int empty_chain_edge = -1;

  std::vector<int64_t> lift(std::span<const int64_t> reduced_flow) const;
};

// Requires a problem without outer edges (eliminate_outer_edges first).
ChainCollapse collapse_chains(const Problem& problem);

}  // namespace bimdf::detail
