#include "bimdf/summary.hpp"

#include <algorithm>
#include <vector>

namespace bimdf {
namespace {

void count_terms(const Cost& c, std::array<int, kNumCostKinds>& counts) {
  if (c.kind() != CostKind::Sum) {
    ++counts[static_cast<int>(c.kind())];
    return;
  }
  for (const Cost& t : c.terms()) count_terms(t, counts);
}

}  // namespace

ProblemSummary summarize(const Problem& p) {
  ProblemSummary s;
  s.nodes = p.num_nodes();
  s.edges = p.num_edges();
  for (int64_t b : p.demand) {
    s.nodes_with_demand += b != 0;
    s.total_demand += static_cast<double>(b);
  }
  std::vector<int> comp = connected_components(p, &s.components);
  std::vector<int> comp_nodes(s.components, 0), comp_edges(s.components, 0);
  std::vector<__int128> comp_demand(s.components, 0);
  std::vector<char> comp_outer(s.components, 0), comp_doubling(s.components, 0);
  for (int v = 0; v < s.nodes; ++v) {
    ++comp_nodes[comp[v]];
    comp_demand[comp[v]] += p.demand[v];
  }
  for (int e = 0; e < s.edges; ++e) {
    const EdgeKind kind = p.edge_kind(e);
    ++s.edge_kinds[static_cast<int>(kind)];
    ++s.cost_kinds[static_cast<int>(p.cost[e].kind())];
    count_terms(p.cost[e], s.cost_terms);
    s.fixed_edges += p.lower[e] == p.upper[e];
    s.finite_upper += p.upper[e] != kInfinity;
    s.positive_lower += p.lower[e] > 0;
    s.negative_lower += p.lower[e] < 0;
    const int c = comp[p.end_a[e].node];
    ++comp_edges[c];
    if (kind == EdgeKind::OuterHead || kind == EdgeKind::OuterTail) comp_outer[c] = 1;
    if (kind != EdgeKind::HeadTail) comp_doubling[c] = 1;
  }
  for (int c = 0; c < s.components; ++c) {
    if (comp_nodes[c] > s.largest_component_nodes) {
      s.largest_component_nodes = comp_nodes[c];
      s.largest_component_edges = comp_edges[c];
    }
    if (comp_outer[c]) continue;
    const bool odd = comp_demand[c] % 2 != 0;
    const bool nonzero_without_doubling = !comp_doubling[c] && comp_demand[c] != 0;
    s.parity_infeasible_components += odd || nonzero_without_doubling;
  }
  return s;
}

}  // namespace bimdf
