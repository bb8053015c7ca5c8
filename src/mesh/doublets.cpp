// remove_doublets (doublets.hpp).
#include "mesh/doublets.hpp"

#include <algorithm>
#include <utility>

#include "mesh/quad_cleanup.hpp"
#include "mesh/quad_quality.hpp"

namespace bimdf::detail {

int remove_doublets(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber) {
  const int nv = mesh.num_vertices();
  renumber.resize(nv);
  for (int v = 0; v < nv; ++v) renumber[v] = v;
  keep_border(mesh, may_go);
  std::vector<std::vector<int>> quads_at = quads_at_vertices(mesh);
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
  drop_gone(mesh, vertex_gone, quad_gone, renumber);
  return removed;
}

int remove_doublets(const quant::Layout& layout, quant::Tessellation& t) {
  std::vector<int> renumber;
  const int removed = remove_doublets(t.mesh, off_features(layout, t), renumber);
  if (removed > 0) follow_renumbering(t, renumber);
  return removed;
}

}  // namespace bimdf::detail
