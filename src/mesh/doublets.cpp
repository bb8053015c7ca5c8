// remove_doublets (doublets.hpp).
#include "mesh/doublets.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "mesh/quad_quality.hpp"

namespace bimdf::detail {
namespace {

// Whether each quad mesh vertex may go: not on a feature curve or corner of the layout.
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

}  // namespace

int remove_doublets(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber) {
  const int nv = mesh.num_vertices();
  renumber.resize(nv);
  for (int v = 0; v < nv; ++v) renumber[v] = v;
  // Border vertices stay: an edge of one quad marks them.
  std::map<std::pair<int, int>, int> edge_quads;
  for (const auto& q : mesh.quads)
    for (int k = 0; k < 4; ++k) ++edge_quads[std::minmax(q[k], q[(k + 1) % 4])];
  for (const auto& [e, n] : edge_quads)
    if (n == 1) may_go[e.first] = may_go[e.second] = 0;
  std::vector<std::vector<int>> quads_at(nv);
  for (int q = 0; q < mesh.num_quads(); ++q)
    for (int v : mesh.quads[q]) quads_at[v].push_back(q);
  std::vector<char> quad_gone(mesh.num_quads(), 0), vertex_gone(nv, 0);
  const auto rotated_to = [&](int q, int v) {
    std::array<int, 4> r = mesh.quads[q];
    std::rotate(r.begin(), std::find(r.begin(), r.end(), v), r.end());
    return r;
  };
  std::vector<int> queue;
  for (int v = nv - 1; v >= 0; --v) queue.push_back(v);
  int removed = 0;
  while (!queue.empty()) {
    const int v = queue.back();
    queue.pop_back();
    if (vertex_gone[v] || !may_go[v] || quads_at[v].size() != 2) continue;
    const int q1 = quads_at[v][0], q2 = quads_at[v][1];
    const std::array<int, 4> r1 = rotated_to(q1, v), r2 = rotated_to(q2, v);
    const int a = r1[1], x = r1[2], b = r1[3], y = r2[2];
    // The two quads must walk the shared edges v–a and v–b oppositely, and differ elsewhere.
    if (r2[1] != b || r2[3] != a || x == y) continue;
    const std::array<int, 4> merged{a, x, b, y};
    const double before =
        std::min(scaled_jacobian(mesh, mesh.quads[q1]), scaled_jacobian(mesh, mesh.quads[q2]));
    if (!(scaled_jacobian(mesh, merged) > before)) continue;
    mesh.quads[q1] = merged;
    quad_gone[q2] = 1;
    vertex_gone[v] = 1;
    for (int u : {a, b}) std::erase(quads_at[u], q2);
    std::replace(quads_at[y].begin(), quads_at[y].end(), q2, q1);
    queue.push_back(a);
    queue.push_back(b);
    ++removed;
  }
  if (removed == 0) return 0;
  QuadMesh kept;
  for (int v = 0; v < nv; ++v) {
    renumber[v] = vertex_gone[v] ? -1 : kept.num_vertices();
    if (!vertex_gone[v]) kept.vertices.push_back(mesh.vertices[v]);
  }
  for (int q = 0; q < mesh.num_quads(); ++q)
    if (!quad_gone[q]) {
      std::array<int, 4> quad = mesh.quads[q];
      for (int& v : quad) v = renumber[v];
      kept.quads.push_back(quad);
      if (!mesh.quad_patch.empty()) kept.quad_patch.push_back(mesh.quad_patch[q]);
    }
  mesh = std::move(kept);
  return removed;
}

int remove_doublets(const quant::Layout& layout, quant::Tessellation& t) {
  std::vector<int> renumber;
  const int removed = remove_doublets(t.mesh, off_features(layout, t), renumber);
  if (removed == 0) return 0;
  std::vector<quant::VertexOrigin> origin(t.mesh.num_vertices());
  for (size_t v = 0; v < renumber.size(); ++v)
    if (renumber[v] >= 0) origin[renumber[v]] = t.origin[v];
  t.origin = std::move(origin);
  for (quant::ChartTiling& c : t.charts) c.quads = 0;
  for (int c : t.mesh.quad_patch) ++t.charts[c].quads;
  return removed;
}

}  // namespace bimdf::detail
