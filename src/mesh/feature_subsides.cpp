// feature_subsides (mesh/feature_subsides.hpp), and feature_edges_of (quant/tessellate.hpp):
// which edges of a tessellation run along the layout's feature curves, read off where each quad
// mesh vertex comes from (Tessellation::origin).
#include "mesh/feature_subsides.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <utility>

#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

std::vector<char> feature_subsides(const Layout& layout) {
  std::vector<char> along(layout.subsides.size(), 0);
  if (layout.feature_edges.empty()) return along;
  std::set<std::pair<int, int>> feature;
  for (const auto& e : layout.feature_edges)
    feature.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  for (size_t s = 0; s < layout.subsides.size(); ++s) {
    const std::vector<int>& chain = layout.subsides[s].vertices;
    bool all = !layout.subsides[s].on_border() && chain.size() >= 2;
    for (size_t i = 0; all && i + 1 < chain.size(); ++i)
      all = feature.count({std::min(chain[i], chain[i + 1]), std::max(chain[i], chain[i + 1])});
    along[s] = all;
  }
  return along;
}

std::vector<std::array<int, 2>> feature_edges_of(const Layout& layout, const Tessellation& t) {
  std::vector<std::array<int, 2>> out;
  const std::vector<char> on_feature = feature_subsides(layout);
  const int S = static_cast<int>(on_feature.size());
  std::vector<std::vector<int>> ending_at(layout.mesh.num_vertices());
  for (int s = 0; s < S; ++s) {
    if (!on_feature[s]) continue;
    const std::vector<int>& chain = layout.subsides[s].vertices;
    ending_at[chain.front()].push_back(s);
    if (chain.back() != chain.front()) ending_at[chain.back()].push_back(s);
  }
  // The feature subsides a quad mesh vertex lies on: its own (a point inside one), or those
  // ending at its layout vertex (a corner or T-junction). Sorted, for the intersection below.
  const auto subsides_of = [&](int v) {
    std::vector<int> result;
    if (v < 0 || v >= static_cast<int>(t.origin.size())) return result;
    const VertexOrigin& o = t.origin[v];
    if (o.subside >= 0 && o.subside < S && on_feature[o.subside]) result.push_back(o.subside);
    if (o.mesh_vertex >= 0 && o.mesh_vertex < static_cast<int>(ending_at.size()))
      result = ending_at[o.mesh_vertex];
    std::sort(result.begin(), result.end());
    return result;
  };
  std::vector<std::vector<int>> at(t.mesh.num_vertices());
  for (int v = 0; v < t.mesh.num_vertices(); ++v) at[v] = subsides_of(v);
  std::set<std::pair<int, int>> seen;
  for (const auto& q : t.mesh.quads)
    for (int k = 0; k < 4; ++k) {
      const int a = q[k], b = q[(k + 1) % 4];
      if (at[a].empty() || at[b].empty() || !seen.insert({std::min(a, b), std::max(a, b)}).second)
        continue;
      std::vector<int> common;
      std::set_intersection(at[a].begin(), at[a].end(), at[b].begin(), at[b].end(),
                            std::back_inserter(common));
      if (!common.empty()) out.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace bimdf::quant
