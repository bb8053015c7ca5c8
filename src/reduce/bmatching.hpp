// Bi-MCF with zero demands → capacitated perfect b-matching (paper §3.7, after Edmonds 1967 and
// Lawler 1976). Every node v becomes v_in (where heads attach) and v_out (where tails attach),
// both of degree K, the throughflow limit, joined by a slack edge of capacity K and weight 0.
// Each Bi-MCF arc becomes an edge between the sides its ends attach to, with weight −cost, so
// a maximum-weight perfect b-matching is a minimum-cost Bi-MCF flow: at each node the head-side
// flow plus the slack equals K, and so does the tail-side flow plus the slack — conservation —
// and no node carries more than K. A ±2 loop becomes a b-edge from v_in (or v_out) to itself,
// which uses two of its degree per unit. The all-slack matching (flow 0) is always perfect.
//
// Refinement needs K ≥ 2 only: every improving circulation decomposes into circuits of
// throughflow at most 2 (paper Thm 3.8), so K = 2 loses nothing; larger K lets one round move
// more (refinement_throughflow below).
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

// Requires all demands zero. `throughflow` gives K per node (each ≥ 1). Capacities above what
// K allows (the smaller K of the arc's ends; half its node's K for a loop) are clamped, so
// kInfinity is fine.
BMatchingReduction reduce_to_bmatching(const BiMcf& bimcf, std::span<const int> throughflow);

// K per node for refinement. K = 2 everywhere would be exact and keeps the matching smallest,
// but then a round moves at most 2 units through any node, and at hubs — nodes with many arcs,
// like the border node that collects every strip ending at a mesh boundary — refinement crawls
// towards the optimum over dozens of rounds (generated QuadWild-like 10^5 edges, border node of
// degree 401: 40 rounds; K = 32 there: 5). Any K ≥ 2 keeps Thm 3.8, so a hub gets
// K = 2·⌊arcs / kArcsPerThroughflowPair⌋, at most kMaxThroughflow; ordinary nodes keep 2.
// The cap because each unit piece at a hub becomes a gadget joined to all K copies of it: at
// 10^6 edges (border degree 3,715) K = 120 cut the rounds from 39 to 26 but made each matching
// 2.5× slower.
inline constexpr int kArcsPerThroughflowPair = 64;
inline constexpr int kMaxThroughflow = 32;
std::vector<int> refinement_throughflow(const BiMcf& bimcf);

}  // namespace bimdf::detail
