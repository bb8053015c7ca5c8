// Patch labels and corners of a cut mesh (patches.hpp).
#include "layout/patches.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "mesh/vec3.hpp"

namespace bimdf::layout {
namespace {

double corner_angle(const SurfaceTopology& top, int h) {
  const TriangleMesh& m = top.mesh();
  const int v = top.from(h);
  const detail::Vec3 a = detail::sub(m.vertices[top.to(h)], m.vertices[v]);
  const detail::Vec3 b = detail::sub(m.vertices[top.from(SurfaceTopology::prev(h))], m.vertices[v]);
  return std::atan2(detail::norm(detail::cross(a, b)), detail::dot(a, b));
}

}  // namespace

Patches label_patches(const SurfaceTopology& top, const std::vector<bool>& boundary_edge) {
  const TriangleMesh& m = top.mesh();
  const int F = m.num_faces(), V = m.num_vertices();
  Patches out;
  out.face_patch.assign(F, -1);
  int P = 0;
  std::vector<int> stack;
  for (int f0 = 0; f0 < F; ++f0) {
    if (out.face_patch[f0] >= 0) continue;
    out.face_patch[f0] = P;
    stack.push_back(f0);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const int h = 3 * f + i, g = top.opposite(h);
        if (g < 0 || boundary_edge[top.edge(h)] || out.face_patch[g / 3] >= 0) continue;
        out.face_patch[g / 3] = P;
        stack.push_back(g / 3);
      }
    }
    ++P;
  }
  out.corners.assign(P, {});
  out.problem.assign(P, "");

  // Topology per patch: V − E + F, and its boundary half-edges (edges inside a patch are
  // counted from both sides, so twice).
  std::vector<int> faces(P, 0), edges2(P, 0), vertices(P, 0);
  for (int f = 0; f < F; ++f) ++faces[out.face_patch[f]];
  std::vector<std::vector<int>> patch_border(P);
  for (int h = 0; h < 3 * F; ++h) {
    const int p = out.face_patch[h / 3], g = top.opposite(h);
    const bool on_border = g < 0 || out.face_patch[g / 3] != p;
    edges2[p] += on_border ? 2 : 1;
    if (on_border) patch_border[p].push_back(h);
  }
  // Vertices per patch: distinct (vertex, patch) pairs.
  {
    std::vector<std::pair<int, int>> pairs;
    for (int f = 0; f < F; ++f)
      for (int v : m.faces[f]) pairs.push_back({out.face_patch[f], v});
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [p, v] : pairs) ++vertices[p];
  }
  // Total angle around each vertex, for scaling a patch's angle to a flat vertex's.
  std::vector<double> total(V, 0);
  for (int h = 0; h < 3 * F; ++h) total[top.from(h)] += corner_angle(top, h);

  for (int p = 0; p < P; ++p) {
    const int euler = vertices[p] - edges2[p] / 2 + faces[p];
    // A disk's boundary passes each of its vertices once.
    std::map<int, int> visits;
    for (int h : patch_border[p]) ++visits[top.from(h)];
    bool pinched = false;
    for (const auto& [v, n] : visits) pinched |= n > 1;
    if (euler != 1 || pinched) {
      out.problem[p] = euler != 1
                           ? "not a disk (Euler characteristic " + std::to_string(euler) + ")"
                           : "its boundary touches itself";
    }
  }
  // Angles: sum the patch's corner angles at its boundary vertices.
  std::vector<std::map<int, double>> sector(P);
  for (int p = 0; p < P; ++p)
    for (int h : patch_border[p]) sector[p][top.from(h)] = 0;
  for (int h = 0; h < 3 * F; ++h) {
    const int p = out.face_patch[h / 3];
    auto it = sector[p].find(top.from(h));
    if (it != sector[p].end()) it->second += corner_angle(top, h);
  }
  for (int p = 0; p < P; ++p) {
    if (!out.problem[p].empty()) continue;
    std::vector<std::pair<double, int>> by_angle;  // scaled angle, vertex
    for (const auto& [v, a] : sector[p])
      // Inside, the angle in a flat vertex's terms; on the mesh border as it is (the border
      // may turn there: the corner is real).
      by_angle.push_back({top.on_border(v) ? a : a * 2 * M_PI / total[v], v});
    std::sort(by_angle.begin(), by_angle.end());
    int k = 0;
    while (k < static_cast<int>(by_angle.size()) && by_angle[k].first < 0.75 * M_PI) ++k;
    // A patch the traces left with fewer than 3 or more than 6 sharp turns (two traces meeting
    // at a sliver, a wiggly feature curve) still gets 3 to 6 corners, its sharpest turns: its
    // pattern then has a singularity, which is better than no layout.
    const int kept = std::clamp(k, 3, 6);
    if (kept != k) ++out.adjusted;
    for (int i = 0; i < std::min(kept, static_cast<int>(by_angle.size())); ++i)
      out.corners[p].push_back(by_angle[i].second);
    if (static_cast<int>(out.corners[p].size()) < 3)
      out.problem[p] = std::to_string(out.corners[p].size()) + " boundary vertices";
  }
  return out;
}

}  // namespace bimdf::layout
