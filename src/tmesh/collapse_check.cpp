// Conformity check of collapse_and_tessellate (tmesh/collapse_check.hpp): quads, edges and
// vertex fans of the finished mesh, with messages naming what each vertex was made of.
#include "tmesh/collapse_check.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/union_find.hpp"

namespace bimdf::tmesh::detail {
namespace {

using UnionFind = bimdf::detail::SmallestRootUnionFind;

// "T-mesh vertex 3", "T-mesh vertices 3 and 7", "T-mesh vertices 3, 5 and 7".
std::string list_ids(const std::string& one, const std::string& many, const std::vector<int>& ids) {
  std::string s = (ids.size() == 1 ? one : many) + " ";
  for (size_t k = 0; k < ids.size(); ++k) {
    if (k > 0) s += k + 1 == ids.size() ? " and " : ", ";
    s += std::to_string(ids[k]);
  }
  return s;
}

}  // namespace

// The conformity checks of collapse.hpp on the finished mesh; `describe` names an output
// vertex by what it was made of.
void check_result(const CollapsedMesh& result, const std::vector<std::array<int, 2>>& quad_cell,
                  const std::vector<int>& class_size) {
  const QuadMesh& out = result.mesh;
  const auto describe = [&](int v) {
    const CollapsedVertex& o = result.origin[v];
    if (!o.tmesh_vertices.empty())
      return list_ids("T-mesh vertex", "T-mesh vertices", o.tmesh_vertices);
    if (!o.arcs.empty()) return "a point of " + list_ids("arc", "arcs", o.arcs);
    return "a point inside " + list_ids("patch", "patches", o.patches);
  };
  const int nq = out.num_quads();
  for (int f = 0; f < nq; ++f)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (out.quads[f][a] == out.quads[f][b])
          throw CollapseError("patch " + std::to_string(out.quad_patch[f]) + ": " +
                                  (quad_cell[f][1] < 0  // an irregular patch's pattern quad
                                       ? "pattern quad " + std::to_string(quad_cell[f][0])
                                       : "quad (" + std::to_string(quad_cell[f][0]) + ", " +
                                             std::to_string(quad_cell[f][1]) + ")") +
                                  " would have two corners at " + describe(out.quads[f][a]),
                              {out.quad_patch[f]});
  // Edges as (smaller vertex, larger vertex, quad, direction), grouped by sorting.
  std::vector<std::tuple<int, int, int, bool>> edges;
  edges.reserve(size_t(4) * nq);
  for (int f = 0; f < nq; ++f)
    for (int a = 0; a < 4; ++a) {
      const int u = out.quads[f][a], v = out.quads[f][(a + 1) % 4];
      edges.emplace_back(std::min(u, v), std::max(u, v), f, u < v);
    }
  std::sort(edges.begin(), edges.end());
  std::vector<int> closed_edges(out.num_vertices(), 0);  // edges with two quads, per vertex
  for (size_t e = 0; e < edges.size();) {
    size_t end = e;
    while (end < edges.size() && std::get<0>(edges[end]) == std::get<0>(edges[e]) &&
           std::get<1>(edges[end]) == std::get<1>(edges[e]))
      ++end;
    const auto [u, v, f, dir] = edges[e];
    const std::string between = " the edge between " + describe(u) + " and " + describe(v);
    if (end - e > 2)
      throw CollapseError(
          std::to_string(end - e) + " quads (patches " + std::to_string(out.quad_patch[f]) + ", " +
              std::to_string(out.quad_patch[std::get<2>(edges[e + 1])]) + ", " +
              std::to_string(out.quad_patch[std::get<2>(edges[e + 2])]) + ") would share" + between,
          {out.quad_patch[f], out.quad_patch[std::get<2>(edges[e + 1])],
           out.quad_patch[std::get<2>(edges[e + 2])]});
    if (end - e == 2) {
      const int g = std::get<2>(edges[e + 1]);
      if (dir == std::get<3>(edges[e + 1]))
        throw CollapseError("patches " + std::to_string(out.quad_patch[f]) + " and " +
                                std::to_string(out.quad_patch[g]) + " would both walk" + between +
                                " in the same direction",
                            {out.quad_patch[f], out.quad_patch[g]});
      ++closed_edges[u], ++closed_edges[v];
    }
    e = end;
  }
  // Fans: the quads at a vertex, joined where they share an edge at it.
  std::vector<std::vector<std::pair<int, int>>> corners(out.num_vertices());  // (prev, next)
  for (const auto& q : out.quads)
    for (int a = 0; a < 4; ++a) corners[q[a]].push_back({q[(a + 3) % 4], q[(a + 1) % 4]});
  for (int v = 0; v < out.num_vertices(); ++v) {
    const auto& around = corners[v];
    UnionFind fans(static_cast<int>(around.size()));
    for (size_t a = 0; a < around.size(); ++a)
      for (size_t b = 0; b < a; ++b)
        if (around[a].first == around[b].second || around[a].second == around[b].first)
          fans.unite(static_cast<int>(a), static_cast<int>(b));
    int count = 0;
    for (size_t a = 0; a < around.size(); ++a) count += fans.find(static_cast<int>(a)) == int(a);
    if (count > 1)
      throw CollapseError(describe(v) + " would be non-manifold: its quads form " +
                              std::to_string(count) + " separate fans",
                          result.origin[v].patches);
    // Two quads around an interior vertex share two consecutive edges and fold onto each
    // other; an input mesh may have such a vertex, but collapse must not make one.
    if (around.size() == 2 && closed_edges[v] == 2 && class_size[v] > 1)
      throw CollapseError(describe(v) + " would become an interior vertex of only two quads",
                          result.origin[v].patches);
  }
}

}  // namespace bimdf::tmesh::detail
