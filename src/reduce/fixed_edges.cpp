#include "reduce/fixed_edges.hpp"

#include "reduce/checked.hpp"

namespace bimdf::detail {

FixedEdgeElimination eliminate_fixed_edges(const Problem& p) {
  FixedEdgeElimination r;
  std::vector<__int128> demand(p.demand.begin(), p.demand.end());
  r.reduced_edge.assign(p.num_edges(), -1);
  r.fixed_flow.assign(p.num_edges(), 0);
  r.reduced.reserve(p.num_nodes(), p.num_edges());  // at most
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.lower[e] == p.upper[e]) {
      const int64_t x = p.lower[e];
      r.fixed_flow[e] = x;
      demand[p.end_a[e].node] -= static_cast<__int128>(p.end_a[e].sign()) * x;
      if (!p.is_outer(e)) demand[p.end_b[e].node] -= static_cast<__int128>(p.end_b[e].sign()) * x;
      continue;
    }
    r.reduced_edge[e] = r.reduced.add_edge(
        p.end_a[e], p.is_outer(e) ? std::nullopt : std::optional(p.end_b[e]), p.lower[e],
        p.upper[e], p.cost[e]);
    r.original_edge.push_back(e);
  }
  r.reduced.demand.resize(p.num_nodes());
  for (int v = 0; v < p.num_nodes(); ++v)
    r.reduced.demand[v] =
        narrow_checked(demand[v], "the demand of node " + std::to_string(v) + " after fixed edges");
  return r;
}

std::vector<int64_t> FixedEdgeElimination::lift(std::span<const int64_t> reduced_flow) const {
  std::vector<int64_t> flow = fixed_flow;
  for (size_t i = 0; i < original_edge.size(); ++i) flow[original_edge[i]] = reduced_flow[i];
  return flow;
}

}  // namespace bimdf::detail
