// Capacitated perfect b-matching → perfect matching (paper §3.8, after Edmonds 1967 and Lawler
// 1976). A b-node of degree d becomes d copies. A b-edge whose capacity can never bind (at
// least the smaller degree; for a loop, half its node's degree) becomes the complete bipartite
// graph between the copies of its ends (for a loop: every pair of distinct copies), each edge
// with the b-edge's weight. A b-edge of smaller capacity κ becomes κ gadgets: nodes L and R
// joined by a weight-0 edge (the gadget unused), L joined to every copy of one end with the
// weight, R to every copy of the other end with weight 0; a used gadget consumes one copy at
// each end. Matchings of both problems correspond with equal weight.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "reduce/bmatching.hpp"
#include "graph/matching_graph.hpp"

namespace bimdf::detail {

struct MatchingReduction {
  MatchingGraph graph;
  std::vector<int> bedge_of_edge;  // matching edge → the b-edge it counts one unit of, or −1
  std::vector<int> bnode_of_node;  // matching node → the b-node it copies, −1 for gadget nodes
  std::vector<int> gadget_of_node;  // gadget node → 2·(its b-edge) for L, 2·(b-edge) + 1 for R; −1
  std::vector<int> first_edge_of_bedge;  // its matching edges are consecutive from here

  // b-edge values from the matched flags of the matching edges.
  std::vector<int> lift(std::span<const char> matched, int num_bedges) const;
};

// Throws std::length_error if the matching graph would exceed int indices.
MatchingReduction reduce_to_perfect_matching(const BMatching& bmatching);

// Dual values for the perfect matching from dual values of the b-matching (one per b-node,
// copied to its copies), all in one integer unit, with `bedge_weight` the b-edges' weights in
// that unit. Each gadget gets the duals that keep its three kinds of edges feasible whatever
// the b-duals are: R = −y(q), L = max(y(q), w − y(p)); so only edges between copies (slack
// edges, uncapacitated b-edges) can be infeasible, and a b-edge whose b-duals are tight (or
// violated) has its gadget's L–p and R–q edges tight, otherwise L–R.
std::vector<int64_t> gadget_duals(const BMatching& bmatching, const MatchingReduction& reduction,
                                  std::span<const int64_t> bnode_dual,
                                  std::span<const int64_t> bedge_weight);

// A matching that puts `value[e]` units on each capacitated b-edge e (its gadgets join a copy
// at each end) as far as free copies allow — all other gadgets matched L–R — and then pairs
// the copies left at the two ends of each weight-0 uncapacitated b-edge (the slack edges).
// Matched flag per matching edge: a warm start for a perfect matching solver (which keeps what
// its duals make tight), e.g. from the LP relaxation's integral part.
std::vector<char> gadget_matching(const BMatching& bmatching, const MatchingReduction& reduction,
                                  std::span<const int> value);

}  // namespace bimdf::detail
