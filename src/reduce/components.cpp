#include "reduce/components.hpp"

namespace bimdf::detail {

ComponentSplit split_components(const Problem& p) {
  ComponentSplit s;
  int count = 0;
  s.part_of_node = connected_components(p, &count);
  s.parts.resize(count);
  s.part_of_edge.resize(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) s.part_of_edge[e] = s.part_of_node[p.end_a[e].node];
  {
    std::vector<int> nodes(count, 0), edges(count, 0);
    for (int part : s.part_of_node) ++nodes[part];
    for (int part : s.part_of_edge) ++edges[part];
    for (int k = 0; k < count; ++k) s.parts[k].reserve(nodes[k], edges[k]);
  }
  s.node_in_part.resize(p.num_nodes());
  for (int v = 0; v < p.num_nodes(); ++v)
    s.node_in_part[v] = s.parts[s.part_of_node[v]].add_node(p.demand[v]);
  s.edge_in_part.resize(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    const int part = s.part_of_edge[e];
    auto local = [&](End end) {
      return end.node == kNoNode ? end : End{s.node_in_part[end.node], end.head};
    };
    s.edge_in_part[e] =
        s.parts[part].add_edge(local(p.end_a[e]), p.is_outer(e) ? std::nullopt
                                                                : std::optional(local(p.end_b[e])),
                               p.lower[e], p.upper[e], p.cost[e]);
  }
  return s;
}

std::vector<int64_t> ComponentSplit::lift(
    const std::vector<std::vector<int64_t>>& part_flows) const {
  std::vector<int64_t> flow(part_of_edge.size());
  for (size_t e = 0; e < flow.size(); ++e) flow[e] = part_flows[part_of_edge[e]][edge_in_part[e]];
  return flow;
}

}  // namespace bimdf::detail
