#include "reduce/matching_gadgets.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace bimdf::detail {
namespace {

// Whether b-edge e becomes gadgets (its capacity can bind) rather than the complete bipartite
// graph between the copies of its ends (for a loop: between distinct copies).
bool uses_gadgets(const BMatching& bm, int e) {
  const int p = bm.end_a[e], q = bm.end_b[e];
  return p == q ? bm.capacity[e] < bm.degree[p] / 2
                : bm.capacity[e] < std::min(bm.degree[p], bm.degree[q]);
}

}  // namespace

MatchingReduction reduce_to_perfect_matching(const BMatching& bm) {
  MatchingReduction r;
  MatchingGraph& g = r.graph;
  std::vector<int64_t> first(bm.num_nodes() + 1, 0);
  for (int w = 0; w < bm.num_nodes(); ++w) first[w + 1] = first[w] + bm.degree[w];
  int64_t nodes = first.back();
  auto check = [](int64_t count) {
    if (count > std::numeric_limits<int>::max())
      throw std::length_error("perfect matching instance too large for int indices");
  };
  check(nodes);
  r.bnode_of_node.resize(nodes);
  for (int w = 0; w < bm.num_nodes(); ++w)
    for (int64_t i = first[w]; i < first[w + 1]; ++i) r.bnode_of_node[i] = w;
  r.gadget_of_node.assign(nodes, -1);
  auto add = [&](int64_t a, int64_t b, double w, int bedge) {
    g.end_a.push_back(static_cast<int>(a));
    g.end_b.push_back(static_cast<int>(b));
    g.weight.push_back(w);
    r.bedge_of_edge.push_back(bedge);
  };
  r.first_edge_of_bedge.resize(bm.num_edges());
  for (int e = 0; e < bm.num_edges(); ++e) {
    r.first_edge_of_bedge[e] = static_cast<int>(g.end_a.size());
    const int p = bm.end_a[e], q = bm.end_b[e];
    const double w = bm.weight[e];
    const int kappa = bm.capacity[e];
    if (!uses_gadgets(bm, e)) {
      for (int64_t i = first[p]; i < first[p + 1]; ++i)
        for (int64_t j = p == q ? i + 1 : first[q]; j < first[q + 1]; ++j) add(i, j, w, e);
      continue;
    }
    for (int k = 0; k < kappa; ++k) {
      const int64_t left = nodes++, right = nodes++;
      check(nodes);
      r.bnode_of_node.insert(r.bnode_of_node.end(), {-1, -1});
      r.gadget_of_node.insert(r.gadget_of_node.end(), {2 * e, 2 * e + 1});
      add(left, right, 0.0, -1);
      for (int64_t i = first[p]; i < first[p + 1]; ++i) add(i, left, w, e);
      for (int64_t j = first[q]; j < first[q + 1]; ++j) add(j, right, 0.0, -1);
    }
  }
  check(static_cast<int64_t>(g.end_a.size()));
  g.num_nodes = static_cast<int>(nodes);
  return r;
}

std::vector<int64_t> gadget_duals(const BMatching& bm, const MatchingReduction& r,
                                  std::span<const int64_t> bnode_dual,
                                  std::span<const int64_t> bedge_weight) {
  const int n = r.graph.num_nodes;
  std::vector<int64_t> y(n);
  for (int v = 0; v < n; ++v) {
    if (r.bnode_of_node[v] >= 0) {
      y[v] = bnode_dual[r.bnode_of_node[v]];
      continue;
    }
    const int e = r.gadget_of_node[v] / 2;
    const int64_t yp = bnode_dual[bm.end_a[e]], yq = bnode_dual[bm.end_b[e]];
    y[v] = r.gadget_of_node[v] % 2 == 0 ? std::max(yq, bedge_weight[e] - yp) : -yq;
  }
  return y;
}

std::vector<char> gadget_matching(const BMatching& bm, const MatchingReduction& r,
                                  std::span<const int> value) {
  std::vector<int> first(bm.num_nodes() + 1, 0), used(bm.num_nodes(), 0);
  for (int w = 0; w < bm.num_nodes(); ++w) first[w + 1] = first[w] + bm.degree[w];
  std::vector<char> matched(r.graph.num_edges(), 0);
  for (int e = 0; e < bm.num_edges(); ++e) {
    if (!uses_gadgets(bm, e)) continue;
    const int p = bm.end_a[e], q = bm.end_b[e];
    const int dp = bm.degree[p], dq = bm.degree[q];
    for (int k = 0; k < bm.capacity[e]; ++k) {
      const int base = r.first_edge_of_bedge[e] + k * (1 + dp + dq);
      if (k < value[e] && used[p] < dp && used[q] < dq && (p != q || used[p] + 1 < dp)) {
        matched[base + 1 + used[p]++] = 1;
        matched[base + 1 + dp + used[q]++] = 1;
      } else {
        matched[base] = 1;
      }
    }
  }
  for (int e = 0; e < bm.num_edges(); ++e) {
    const int p = bm.end_a[e], q = bm.end_b[e];
    if (uses_gadgets(bm, e) || p == q || bm.weight[e] != 0) continue;
    const int dq = bm.degree[q];
    while (used[p] < bm.degree[p] && used[q] < dq) {
      matched[r.first_edge_of_bedge[e] + used[p] * dq + used[q]] = 1;
      ++used[p];
      ++used[q];
    }
  }
  return matched;
}

std::vector<int> MatchingReduction::lift(std::span<const char> matched, int num_bedges) const {
  std::vector<int> value(num_bedges, 0);
  for (size_t e = 0; e < matched.size(); ++e)
    if (matched[e] && bedge_of_edge[e] >= 0) ++value[bedge_of_edge[e]];
  return value;
}

}  // namespace bimdf::detail
