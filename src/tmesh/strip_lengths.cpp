// strip_refined_lengths (tmesh/strip_lengths.hpp): a union–find over the coarse units of all
// arcs, joined across patches and zips, then one factor per class.
#include "tmesh/strip_lengths.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/union_find.hpp"

namespace bimdf::tmesh::detail {

std::vector<int64_t> strip_refined_lengths(const TMesh& tmesh, const std::vector<int64_t>& coarse,
                                           const std::vector<Zip>& zips, double* factor_mean) {
  const int na = tmesh.num_arcs();
  if (static_cast<int>(coarse.size()) != na)
    throw std::invalid_argument("strip_refined_lengths: one length per arc expected");
  std::vector<int64_t> first(na + 1, 0);  // first unit of each arc, in the arc's direction
  for (int a = 0; a < na; ++a) first[a + 1] = first[a] + coarse[a];
  if (first[na] > (int64_t{1} << 30))
    throw std::invalid_argument("strip_refined_lengths: too many coarse units");
  bimdf::detail::SmallestRootUnionFind strip(static_cast<int>(first[na]));
  // The units of a chain of half-arcs, in walking order.
  const auto units = [&](const std::vector<int>& chain) {
    std::vector<int> out;
    for (int h : chain) {
      const int a = TMesh::arc_of(h);
      for (int64_t i = 0; i < coarse[a]; ++i)
        out.push_back(static_cast<int>((h & 1) ? first[a + 1] - 1 - i : first[a] + i));
    }
    return out;
  };
  const auto join_facing = [&](const std::vector<int>& x, const std::vector<int>& y) {
    if (x.size() != y.size())
      throw std::invalid_argument("strip_refined_lengths: facing chains of unequal length");
    for (size_t s = 0; s < x.size(); ++s) strip.unite(x[s], y[y.size() - 1 - s]);
  };
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k : {0, 1})
      join_facing(units(tmesh.patch_sides[p][k]), units(tmesh.patch_sides[p][k + 2]));
  for (const Zip& z : zips) join_facing(units(z[0]), units(z[1]));

  std::vector<double> sum(first[na], 0);
  std::vector<int> count(first[na], 0);
  for (int a = 0; a < na; ++a)
    for (int64_t i = first[a]; i < first[a + 1]; ++i) {
      const int root = strip.find(static_cast<int>(i));
      sum[root] += tmesh.arc_target[a] / static_cast<double>(coarse[a]);
      ++count[root];
    }
  std::vector<int64_t> factor(first[na], 0);
  double factors = 0;
  int strips = 0;
  for (int64_t i = 0; i < first[na]; ++i)
    if (count[i] > 0) {
      factor[i] = std::max<int64_t>(1, std::llround(sum[i] / count[i]));
      factors += static_cast<double>(factor[i]), ++strips;
    }
  if (factor_mean) *factor_mean = strips > 0 ? factors / strips : 0;
  std::vector<int64_t> length(na, 0);
  for (int a = 0; a < na; ++a)
    for (int64_t i = first[a]; i < first[a + 1]; ++i)
      length[a] += factor[strip.find(static_cast<int>(i))];
  return length;
}

}  // namespace bimdf::tmesh::detail
