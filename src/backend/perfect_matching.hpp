// Maximum-weight perfect matching (reduce/matching_gadgets.hpp: MatchingGraph), solved by
// LEMON's MaxWeightedPerfectMatching (Edmonds' blossom algorithm, O(nm log n)). LEMON-free
// header (DESIGN §6). Weights are scaled to integers by integer_cost_scale (min_cost_flow.hpp)
// with 2^58 in place of 2^60, because LEMON keeps integer duals multiplied by 4.
#pragma once

#include <optional>
#include <vector>

#include "graph/matching_graph.hpp"

namespace bimdf::detail {

// Matched flag per edge, or nullopt when the graph has no perfect matching.
std::optional<std::vector<char>> max_weight_perfect_matching(const MatchingGraph& graph);

}  // namespace bimdf::detail
