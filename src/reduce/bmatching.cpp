#include "reduce/bmatching.hpp"

#include <algorithm>
#include <stdexcept>

namespace bimdf::detail {

BMatchingReduction reduce_to_bmatching(const BiMcf& in, int k) {
  BMatchingReduction r;
  BMatching& bm = r.bmatching;
  const int n = in.num_nodes();
  auto side = [](End e) { return 2 * e.node + (e.head ? 0 : 1); };  // v_in = 2v, v_out = 2v+1
  bm.degree.assign(2 * n, k);
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
    add(2 * v, 2 * v + 1, k, 0.0, -1);
  }
  for (int i = 0; i < in.num_arcs(); ++i) {
    const int a = side(in.end_a[i]), b = side(in.end_b[i]);
    const int64_t limit = a == b ? k / 2 : k;
    const int cap = static_cast<int>(std::min<int64_t>(in.capacity[i], limit));
    if (cap > 0) add(a, b, cap, -in.cost[i], i);
  }
  return r;
}

std::vector<int64_t> BMatchingReduction::lift(std::span<const int> edge_value,
                                              int num_arcs) const {
  std::vector<int64_t> y(num_arcs, 0);
  for (size_t e = 0; e < edge_value.size(); ++e)
    if (arc_of_edge[e] >= 0) y[arc_of_edge[e]] += edge_value[e];
  return y;
}

}  // namespace bimdf::detail
