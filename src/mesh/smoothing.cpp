// smooth_on_surface (quant/tessellate.hpp): damped umbrella smoothing with projection onto the
// input surface. Each free vertex is projected onto the triangles of the chart(s) it belongs
// to rather than onto the whole surface, so that on thin parts it cannot jump to the far side.
#include <memory>
#include <set>
#include <utility>

#include "bimdf/quant/tessellate.hpp"
#include "mesh/closest_point.hpp"

namespace bimdf::quant {

void smooth_on_surface(const Layout& layout, Tessellation& t, const SmoothingOptions& options) {
  if (options.iterations <= 0) return;
  QuadMesh& mesh = t.mesh;
  const int nv = mesh.num_vertices();
  std::set<std::pair<int, int>> feature;
  for (const auto& e : layout.feature_edges)
    feature.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  const auto on_feature = [&](const Subside& s) {
    if (feature.empty()) return false;
    for (size_t i = 0; i + 1 < s.vertices.size(); ++i)
      if (!feature.count({std::min(s.vertices[i], s.vertices[i + 1]),
                          std::max(s.vertices[i], s.vertices[i + 1])}))
        return false;
    return true;
  };
  // Mesh vertices that stay: feature corners and the ends of border and feature subsides.
  std::vector<char> pinned(layout.mesh.num_vertices(), 0);
  for (int v : layout.feature_corners) pinned[v] = 1;
  std::vector<char> subside_free(layout.subsides.size(), 0);
  for (size_t s = 0; s < layout.subsides.size(); ++s) {
    const Subside& sub = layout.subsides[s];
    subside_free[s] = !sub.on_border() && !on_feature(sub);
    if (!subside_free[s]) pinned[sub.vertices.front()] = pinned[sub.vertices.back()] = 1;
  }
  std::vector<std::set<int>> charts_at(layout.mesh.num_vertices());
  for (int f = 0; f < layout.mesh.num_faces(); ++f)
    for (int v : layout.mesh.faces[f])
      if (layout.face_chart[f] >= 0) charts_at[v].insert(layout.face_chart[f]);
  // The charts each vertex may move on (empty: fixed).
  std::vector<std::vector<int>> charts(nv);
  for (int v = 0; v < nv; ++v) {
    const VertexOrigin& o = t.origin[v];
    if (o.chart >= 0) charts[v] = {o.chart};
    if (o.subside >= 0 && subside_free[o.subside]) {
      const Subside& s = layout.subsides[o.subside];
      charts[v] = {s.charts[0], s.charts[1]};
    }
    if (o.mesh_vertex >= 0 && !pinned[o.mesh_vertex])
      charts[v].assign(charts_at[o.mesh_vertex].begin(), charts_at[o.mesh_vertex].end());
  }
  std::vector<std::unique_ptr<detail::TriangleTree>> tree(layout.charts.size());
  for (size_t c = 0; c < layout.charts.size(); ++c)
    if (!layout.charts[c].empty())
      tree[c] = std::make_unique<detail::TriangleTree>(layout.mesh, layout.charts[c].faces);
  std::vector<std::vector<int>> neighbours(nv);
  for (const auto& q : mesh.quads)
    for (int a = 0; a < 4; ++a) {
      neighbours[q[a]].push_back(q[(a + 1) % 4]);
      neighbours[q[(a + 1) % 4]].push_back(q[a]);
    }
  // Each edge was added once from each of its (at most two) quads: the mean is unaffected
  // for interior edges, and boundary vertices are fixed anyway.
  std::vector<std::array<double, 3>> next = mesh.vertices;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    for (int v = 0; v < nv; ++v) {
      if (charts[v].empty() || neighbours[v].empty()) continue;
      std::array<double, 3> mean{0, 0, 0};
      for (int w : neighbours[v])
        for (int d = 0; d < 3; ++d) mean[d] += mesh.vertices[w][d] / neighbours[v].size();
      std::array<double, 3> p;
      for (int d = 0; d < 3; ++d)
        p[d] = (1 - options.damping) * mesh.vertices[v][d] + options.damping * mean[d];
      detail::TriangleTree::Hit best;
      best.distance = -1;
      for (int c : charts[v]) {
        if (!tree[c]) continue;
        const detail::TriangleTree::Hit hit = tree[c]->closest(p);
        if (best.distance < 0 || hit.distance < best.distance) best = hit;
      }
      next[v] = best.distance >= 0 ? best.point : p;
    }
    mesh.vertices.swap(next);
    next = mesh.vertices;
  }
}

}  // namespace bimdf::quant
