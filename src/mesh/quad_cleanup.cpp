// Shared pieces of the quad mesh cleanups (quad_cleanup.hpp).
#include "mesh/quad_cleanup.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace bimdf::detail {

std::vector<char> off_features(const quant::Layout& layout, const quant::Tessellation& t) {
  std::vector<char> on_feature(layout.mesh.num_vertices(), 0);
  std::set<std::pair<int, int>> feature;
  for (const auto& [a, b] : layout.feature_edges) {
    on_feature[a] = on_feature[b] = 1;
    feature.insert(std::minmax(a, b));
  }
  for (int v : layout.feature_corners) on_feature[v] = 1;
  std::vector<char> out(t.origin.size(), 1);
  for (size_t v = 0; v < t.origin.size(); ++v) {
    const quant::VertexOrigin& o = t.origin[v];
    if (o.mesh_vertex >= 0) out[v] = !on_feature[o.mesh_vertex];
    if (o.subside >= 0) {
      const std::vector<int>& chain = layout.subsides[o.subside].vertices;
      out[v] = !feature.count(std::minmax(chain[0], chain[1]));
    }
  }
  return out;
}

void keep_border(const QuadMesh& mesh, std::vector<char>& may_go) {
  std::map<std::pair<int, int>, int> edge_quads;
  for (const auto& q : mesh.quads)
    for (int k = 0; k < 4; ++k) ++edge_quads[std::minmax(q[k], q[(k + 1) % 4])];
  for (const auto& [e, n] : edge_quads)
    if (n == 1) may_go[e.first] = may_go[e.second] = 0;
}

void drop_gone(QuadMesh& mesh, const std::vector<char>& vertex_gone,
               const std::vector<char>& quad_gone, std::vector<int>& renumber) {
  const int nv = mesh.num_vertices();
  renumber.assign(nv, -1);
  QuadMesh kept;
  for (int v = 0; v < nv; ++v) {
    if (vertex_gone[v]) continue;
    renumber[v] = kept.num_vertices();
    kept.vertices.push_back(mesh.vertices[v]);
  }
  for (int q = 0; q < mesh.num_quads(); ++q)
    if (!quad_gone[q]) {
      std::array<int, 4> quad = mesh.quads[q];
      for (int& v : quad) v = renumber[v];
      kept.quads.push_back(quad);
      if (!mesh.quad_patch.empty()) kept.quad_patch.push_back(mesh.quad_patch[q]);
    }
  mesh = std::move(kept);
}

void follow_renumbering(quant::Tessellation& t, const std::vector<int>& renumber) {
  std::vector<quant::VertexOrigin> origin(t.mesh.num_vertices());
  for (size_t v = 0; v < renumber.size(); ++v)
    if (renumber[v] >= 0) origin[renumber[v]] = t.origin[v];
  t.origin = std::move(origin);
  for (quant::ChartTiling& c : t.charts) c.quads = 0;
  for (int c : t.mesh.quad_patch) ++t.charts[c].quads;
}

}  // namespace bimdf::detail
