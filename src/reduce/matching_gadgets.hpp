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
#include "reduce/matching_graph.hpp"

namespace bimdf::detail {

struct MatchingReduction {
  MatchingGraph graph;
  std::vector<int> bedge_of_edge;  // matching edge → the b-edge it counts one unit of, or −1

  // b-edge values from the matched flags of the matching edges.
  std::vector<int> lift(std::span<const char> matched, int num_bedges) const;
};

// Throws std::length_error if the matching graph would exceed int indices.
MatchingReduction reduce_to_perfect_matching(const BMatching& bmatching);

}  // namespace bimdf::detail
