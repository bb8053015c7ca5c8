#include "reduce/bmatching.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace bimdf::detail {

BMatchingReduction reduce_to_bmatching(const BiMcf& in, const Throughflow& tf) {
  BMatchingReduction r;
  BMatching& bm = r.bmatching;
  const int n = in.num_nodes();
  const std::span<const int> k = tf.limit;
  if (static_cast<int>(k.size()) != n ||
      (!tf.part_degree.empty() && static_cast<int>(tf.part_degree.size()) != n))
    throw std::invalid_argument("b-matching reduction: " + std::to_string(k.size()) +
                                " throughflow limits for " + std::to_string(n) + " nodes");
  auto part_degree = [&](int v) { return tf.part_degree.empty() ? 0 : tf.part_degree[v]; };
  auto side = [](End e) { return 2 * e.node + (e.head ? 0 : 1); };  // v_in = 2v, v_out = 2v+1
  bm.degree.resize(2 * n);
  for (int v = 0; v < n; ++v) {
    if (k[v] < 1 || part_degree(v) < 0)
      throw std::invalid_argument("b-matching reduction: throughflow limit " +
                                  std::to_string(k[v]) + ", part degree " +
                                  std::to_string(part_degree(v)) + " at node " + std::to_string(v));
    if (in.demand[v] != 0)
      throw std::invalid_argument("b-matching reduction needs zero demands (node " +
                                  std::to_string(v) + ")");
    bm.degree[2 * v] = bm.degree[2 * v + 1] = k[v];
  }
  r.side_of_bnode.resize(2 * n);
  for (int s = 0; s < 2 * n; ++s) r.side_of_bnode[s] = s;

  // Tiers: both sides get the same number of parts, the side's own b-node being its first.
  std::vector<int> ends(2 * n, 0), parts(n, 0), first_part(2 * n, -1), next_end(2 * n, 0);
  for (int i = 0; i < in.num_arcs(); ++i) {
    const int a = side(in.end_a[i]), b = side(in.end_b[i]);
    ++ends[a];
    if (b != a) ++ends[b];
  }
  for (int v = 0; v < n; ++v) {
    const int pd = part_degree(v);
    if (pd == 0) continue;
    parts[v] = std::max(1, std::min((k[v] + pd - 1) / pd, std::max(ends[2 * v], ends[2 * v + 1])));
    for (int s : {2 * v, 2 * v + 1}) {
      bm.degree[s] = pd;
      first_part[s] = bm.num_nodes() - 1;  // parts 1, 2, … follow; part 0 is s itself
      bm.degree.insert(bm.degree.end(), parts[v] - 1, pd);
      r.side_of_bnode.insert(r.side_of_bnode.end(), parts[v] - 1, s);
    }
  }
  auto part = [&](int s, int j) { return j == 0 ? s : first_part[s] + j; };
  auto attach = [&](int s) {
    if (first_part[s] < 0) return s;
    return part(s, static_cast<int>(int64_t{next_end[s]++} * parts[s / 2] / ends[s]));
  };

  auto add = [&](int a, int b, int cap, double w, int arc) {
    bm.end_a.push_back(a);
    bm.end_b.push_back(b);
    bm.capacity.push_back(cap);
    bm.weight.push_back(w);
    r.arc_of_edge.push_back(arc);
  };
  for (int v = 0; v < n; ++v)
    if (part_degree(v) == 0) add(2 * v, 2 * v + 1, k[v], 0.0, -1);
  for (int i = 0; i < in.num_arcs(); ++i) {
    const int a = attach(side(in.end_a[i]));
    const int b = side(in.end_b[i]) == side(in.end_a[i]) ? a : attach(side(in.end_b[i]));
    const int64_t limit = a == b ? bm.degree[a] / 2 : std::min(bm.degree[a], bm.degree[b]);
    const int cap = static_cast<int>(std::min<int64_t>(in.capacity[i], limit));
    if (cap > 0) add(a, b, cap, -in.cost[i], i);
  }
  // What a head-side part leaves unused pairs with what a tail-side part does.
  for (int v = 0; v < n; ++v)
    for (int i = 0; i < parts[v]; ++i)
      for (int j = 0; j < parts[v]; ++j)
        add(part(2 * v, i), part(2 * v + 1, j), part_degree(v), 0.0, -1);
  return r;
}

int64_t matching_copies_bound(int limit, int part_degree) {
  // Parts: ⌈K/P⌉·P < K + P per side.
  return part_degree == 0 ? 2 * int64_t{limit} : 2 * (int64_t{limit} + part_degree);
}

Throughflow refinement_throughflow(const BiMcf& bimcf, std::span<const int> min_throughflow) {
  std::vector<int> arcs(bimcf.num_nodes(), 0);
  for (int i = 0; i < bimcf.num_arcs(); ++i) {
    ++arcs[bimcf.end_a[i].node];
    ++arcs[bimcf.end_b[i].node];
  }
  Throughflow tf;
  tf.limit.assign(arcs.size(), 2);
  tf.part_degree.assign(arcs.size(), 0);
  for (size_t v = 0; v < arcs.size(); ++v) {
    if (arcs[v] >= kHubArcs) {
      tf.limit[v] = std::min(2 * (arcs[v] / kArcsPerThroughflowPair), kMaxThroughflow);
      tf.part_degree[v] = kTierPartDegree;
    } else if (arcs[v] >= kBusyArcs) {
      tf.limit[v] = kBusyThroughflow;
    }
    if (min_throughflow.empty()) continue;
    tf.limit[v] = std::max(tf.limit[v], min_throughflow[v]);
    if (tf.part_degree[v] > 0) tf.part_degree[v] = std::max(tf.part_degree[v], min_throughflow[v]);
  }
  return tf;
}

std::vector<int64_t> BMatchingReduction::lift(std::span<const int> edge_value, int num_arcs) const {
  std::vector<int64_t> y(num_arcs, 0);
  for (size_t e = 0; e < edge_value.size(); ++e)
    if (arc_of_edge[e] >= 0) y[arc_of_edge[e]] += edge_value[e];
  return y;
}

}  // namespace bimdf::detail
