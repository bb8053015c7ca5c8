// LEMON adapter for perfect_matching.hpp; C++17 (DESIGN §6), no LEMON type leaves this file.
#include "backend/perfect_matching.hpp"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

#include <cmath>

#include "backend/min_cost_flow.hpp"
#include "core/deep_stack.hpp"

namespace bimdf::detail {

std::optional<std::vector<char>> max_weight_perfect_matching(const MatchingGraph& in) {
  if (in.num_nodes == 0) return std::vector<char>();
  lemon::SmartGraph g;
  g.reserveNode(in.num_nodes);
  g.reserveEdge(in.num_edges());
  for (int v = 0; v < in.num_nodes; ++v) g.addNode();
  for (int e = 0; e < in.num_edges(); ++e)
    g.addEdge(g.nodeFromId(in.end_a[e]), g.nodeFromId(in.end_b[e]));
  const double scale = integer_cost_scale(in.weight, in.num_nodes, 58);
  lemon::SmartGraph::EdgeMap<int64_t> weight(g);
  for (int e = 0; e < in.num_edges(); ++e)
    weight[g.edgeFromId(e)] = std::llround(in.weight[e] * scale);
  std::optional<std::vector<char>> matched;
  run_with_stack(matching_stack_bytes(in.num_nodes), [&] {
    lemon::MaxWeightedPerfectMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<int64_t>>
        matching(g, weight);
    if (!matching.run()) return;
    matched.emplace(in.num_edges(), 0);
    for (int e = 0; e < in.num_edges(); ++e) (*matched)[e] = matching.matching(g.edgeFromId(e));
  });
  return matched;
}

}  // namespace bimdf::detail
