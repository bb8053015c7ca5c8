#include "reduce/bmatching.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace bimdf::detail {

BMatchingReduction reduce_to_bmatching(const BiMcf& in, std::span<const int> k) {
  BMatchingReduction r;
  BMatching& bm = r.bmatching;
  const int n = in.num_nodes();
  if (static_cast<int>(k.size()) != n)
    throw std::invalid_argument("b-matching reduction: " + std::to_string(k.size()) +
                                " throughflow limits for " + std::to_string(n) + " nodes");
  auto side = [](End e) { return 2 * e.node + (e.head ? 0 : 1); };  // v_in = 2v, v_out = 2v+1
  bm.degree.resize(2 * n);
  for (int v = 0; v < n; ++v) {
    if (k[v] < 1)
      throw std::invalid_argument("b-matching reduction: throughflow limit " +
                                  std::to_string(k[v]) + " at node " + std::to_string(v));
    bm.degree[2 * v] = bm.degree[2 * v + 1] = k[v];
  }
  auto add = [&](int a, int b, int cap, double w, int arc) {
    bm.end_a.push_back(a);
    bm.end_b.push_back(b);
    bm.capacity.push_back(cap);
    bm.weight.push_back(w);
    r.arc_of_edge.push_back(arc);
  };
  for (int v = 0; v < n; ++v) {
    if (in.demand[v] != 0)
      throw std::invalid_argument("b-matching reduction needs zero demands (node " +
                                  std::to_string(v) + ")");
    add(2 * v, 2 * v + 1, k[v], 0.0, -1);
  }
  for (int i = 0; i < in.num_arcs(); ++i) {
    const int a = side(in.end_a[i]), b = side(in.end_b[i]);
    const int ka = k[in.end_a[i].node], kb = k[in.end_b[i].node];
    const int64_t limit = a == b ? ka / 2 : std::min(ka, kb);
    const int cap = static_cast<int>(std::min<int64_t>(in.capacity[i], limit));
    if (cap > 0) add(a, b, cap, -in.cost[i], i);
  }
  return r;
}

std::vector<int> refinement_throughflow(const BiMcf& bimcf) {
  std::vector<int> arcs(bimcf.num_nodes(), 0);
  for (int i = 0; i < bimcf.num_arcs(); ++i) {
    ++arcs[bimcf.end_a[i].node];
    ++arcs[bimcf.end_b[i].node];
  }
  std::vector<int> k(arcs.size());
  for (size_t v = 0; v < arcs.size(); ++v)
    k[v] = std::clamp(2 * (arcs[v] / kArcsPerThroughflowPair), 2, kMaxThroughflow);
  return k;
}

std::vector<int64_t> BMatchingReduction::lift(std::span<const int> edge_value, int num_arcs) const {
  std::vector<int64_t> y(num_arcs, 0);
  for (size_t e = 0; e < edge_value.size(); ++e)
    if (arc_of_edge[e] >= 0) y[arc_of_edge[e]] += edge_value[e];
  return y;
}

}  // namespace bimdf::detail
