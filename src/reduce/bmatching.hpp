// Bi-MCF with zero demands → capacitated perfect b-matching (paper §3.7, after Edmonds 1967 and
// Lawler 1976). Every node v becomes v_in (where heads attach) and v_out (where tails attach),
// both of degree K, the throughflow limit, joined by a slack edge of capacity K and weight 0.
// Each Bi-MCF arc becomes an edge between the sides its ends attach to, with weight −cost, so
// a maximum-weight perfect b-matching is a minimum-cost Bi-MCF flow: at each node the head-side
// flow plus the slack equals K, and so does the tail-side flow plus the slack — conservation —
// and no node carries more than K. A ±2 loop becomes a b-edge from v_in (or v_out) to itself,
// which uses two of its degree per unit. The all-slack matching (flow 0) is always perfect.
// A hub can instead get tiers (Throughflow below): the same conservation through parts, with
// far fewer matching edges for a large K.
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
  std::vector<int> arc_of_edge;  // b-edge → Bi-MCF arc, −1 for slack and tier edges
  // Per b-node: the node side (v_in = 2v, v_out = 2v + 1) it stands for, whose dual it takes.
  std::vector<int> side_of_bnode;

  // Bi-MCF arc flows from b-edge values.
  std::vector<int64_t> lift(std::span<const int> edge_value, int num_arcs) const;
};

// Refinement's limits per node: K, the throughflow, and how a node is represented. With
// part_degree 0 a node is one b-node per side (v_in = 2v, v_out = 2v + 1) of degree K, joined
// by the slack edge. That costs K matching copies per side, each joined to every unit of every
// arc there — too many at a hub. With part_degree P > 0 the node gets tiers: each side's arc
// ends, in arc order, fall into m = max(1, min(⌈K/P⌉, E)) parts of degree P (E the larger
// side's end count; the i-th of a side's E' ends into part ⌊i·m/E'⌋; a loop's two ends stay
// together; part 0 is the side's own b-node, the others follow the 2n side b-nodes), and every
// head-side part is joined to every tail-side part by a weight-0 edge of capacity P, which
// pairs what one leaves unused with what the other does: the two sides' unused degrees are
// equal, so their flows are — conservation — with at most P units per part and m·P in all, at
// (m·P)² + P·(units) matching edges instead of K·(units).
struct Throughflow {
  std::vector<int> limit;        // K per node, ≥ 1
  std::vector<int> part_degree;  // P per node, 0 for one b-node per side; may be empty (all 0)
};

// Requires all demands zero. Capacities above what the limits allow (the smaller degree of the
// b-nodes an arc joins; half the degree for a loop) are clamped, so kInfinity is fine.
BMatchingReduction reduce_to_bmatching(const BiMcf& bimcf, const Throughflow& throughflow);

// Matching copies a node's b-nodes can have at most (both sides, all parts): what
// residual_pruning.hpp's scale bound counts.
int64_t matching_copies_bound(int limit, int part_degree);

// Limits for refinement. K = 2 everywhere would be exact and keeps the matching smallest, but
// then a round moves at most 2 units through any node, and at hubs — nodes with many arcs,
// like the border node that collects every strip ending at a mesh boundary — refinement crawls
// towards the optimum over dozens of rounds. Any K ≥ 2 keeps Thm 3.8, so a node with at least
// kHubArcs arcs gets K = 2·⌊arcs / kArcsPerThroughflowPair⌋, at most kMaxThroughflow, in
// tiers with parts of degree kTierPartDegree; ordinary nodes keep K = 2 and one b-node per
// side. Generated QuadWild-like 10^6 edges (border node of 3,715 arcs): flat K = 32 there took
// 39 rounds, the tail all waiting on the border's throughflow (K = 4 at every other node gave
// the same objective after every round), and flat K = 256 made a round 10× slower; tiers with
// K = 256, and refinement's widening windows (refine.cpp), take 8 rounds and under half the
// time. K from arcs/32 rather than fewer: K² is the tiers' own cost, and at 10^5 edges
// (border node of 401 arcs) K = 256 made the matchings slower than flat K = 32 had.
// Below the hubs, a busy node — at least kBusyArcs arcs, about a dozen edges where a round's
// residual is not yet pruned — gets K = kBusyThroughflow without tiers. On the shared
// instances the approximation's distance to the optimum needs throughflow 3–4 at a few nodes
// of degree 9–18 (bull__flow_1: one, cow__flow_0: four), so K = 2 there left the optimum
// outside round 1 and took an extra round: 200 → 187 rounds over the 63 instances (K = 3
// from 16 arcs: 182, but larger matchings), the exact solves 1–5% faster in five alternating
// runs (median 3.4%); the generated 10^5-edge instance unchanged (docs/benchmarks.md).
inline constexpr int kBusyArcs = 24;
inline constexpr int kBusyThroughflow = 4;
inline constexpr int kHubArcs = 128;
inline constexpr int kArcsPerThroughflowPair = 32;
inline constexpr int kMaxThroughflow = 256;
inline constexpr int kTierPartDegree = 8;
// `min_throughflow`, when not empty, raises each node's K to at least its entry, and a tiered
// node's part degree too (refinement's widened windows need that much through one part).
Throughflow refinement_throughflow(const BiMcf& bimcf, std::span<const int> min_throughflow = {});

}  // namespace bimdf::detail
