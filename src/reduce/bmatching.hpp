// Bi-MCF with zero demands → capacitated perfect b-matching (paper §3.7, after Edmonds 1967 and
// Lawler 1976). Every node v becomes v_in (where heads attach) and v_out (where tails attach),
// both of degree K, the throughflow limit, joined by a slack edge of capacity K and weight 0.
// Each Bi-MCF arc becomes an edge between the sides its ends attach to, with weight −cost, so
// a maximum-weight perfect b-matching is a minimum-cost Bi-MCF flow: at each node the head-side
// flow plus the slack equals K, and so does the tail-side flow plus the slack — conservation —
// and no node carries more than K. A ±2 loop becomes a b-edge from v_in (or v_out) to itself,
// which uses two of its degree per unit. The all-slack matching (flow 0) is always perfect.
//
// Refinement uses K = 2: every improving circulation decomposes into circuits of throughflow at
// most 2 (paper Thm 3.8), so K = 2 loses nothing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "reduce/bimcf.hpp"

namespace bimdf::detail {

// Maximum-weight perfect b-matching with edge capacities. An edge whose ends coincide is a loop
// that takes two of its node's degree per unit.
struct BMatching {
  std::vector<int> degree;  // per node
  std::vector<int> end_a;   // per edge
  std::vector<int> end_b;
  std::vector<int> capacity;  // ≥ 1
  std::vector<double> weight;

  int num_nodes() const { return static_cast<int>(degree.size()); }
  int num_edges() const { return static_cast<int>(end_a.size()); }
};

struct BMatchingReduction {
  BMatching bmatching;
  std::vector<int> arc_of_edge;  // b-edge → Bi-MCF arc, −1 for slack edges

  // Bi-MCF arc flows from b-edge values.
  std::vector<int64_t> lift(std::span<const int> edge_value, int num_arcs) const;
};

// Requires all demands zero. Capacities above what K allows (K per arc, K/2 for loops) are
// clamped, so kInfinity is fine.
BMatchingReduction reduce_to_bmatching(const BiMcf& bimcf, int throughflow);

}  // namespace bimdf::detail
