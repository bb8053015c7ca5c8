#include "reduce/matching_gadgets.hpp"

#include <limits>
#include <stdexcept>

namespace bimdf::detail {

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
  auto add = [&](int64_t a, int64_t b, double w, int bedge) {
    g.end_a.push_back(static_cast<int>(a));
    g.end_b.push_back(static_cast<int>(b));
    g.weight.push_back(w);
    r.bedge_of_edge.push_back(bedge);
  };
  for (int e = 0; e < bm.num_edges(); ++e) {
    const int p = bm.end_a[e], q = bm.end_b[e];
    const double w = bm.weight[e];
    const int kappa = bm.capacity[e];
    if (p == q) {
      if (kappa >= bm.degree[p] / 2) {
        for (int64_t i = first[p]; i < first[p + 1]; ++i)
          for (int64_t j = i + 1; j < first[p + 1]; ++j) add(i, j, w, e);
        continue;
      }
    } else if (kappa >= std::min(bm.degree[p], bm.degree[q])) {
      for (int64_t i = first[p]; i < first[p + 1]; ++i)
        for (int64_t j = first[q]; j < first[q + 1]; ++j) add(i, j, w, e);
      continue;
    }
    for (int k = 0; k < kappa; ++k) {
      const int64_t left = nodes++, right = nodes++;
      check(nodes);
      add(left, right, 0.0, -1);
      for (int64_t i = first[p]; i < first[p + 1]; ++i) add(i, left, w, e);
      for (int64_t j = first[q]; j < first[q + 1]; ++j) add(j, right, 0.0, -1);
    }
  }
  check(static_cast<int64_t>(g.end_a.size()));
  g.num_nodes = static_cast<int>(nodes);
  return r;
}

std::vector<int> MatchingReduction::lift(std::span<const char> matched, int num_bedges) const {
  std::vector<int> value(num_bedges, 0);
  for (size_t e = 0; e < matched.size(); ++e)
    if (matched[e] && bedge_of_edge[e] >= 0) ++value[bedge_of_edge[e]];
  return value;
}

}  // namespace bimdf::detail
