// Patch labels and corners of a cut mesh (patches.hpp).
#include "layout/patches.hpp"

#include <algorithm>
#include <cmath>
#include <map>


namespace bimdf::layout {

Patches label_patches(const SurfaceTopology& top, const std::vector<bool>& boundary_edge,
                      const CornerHints& hints) {
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
  // Total angle around each vertex: a sector's share of it, times the field's quarter turns
  // there, is the sector's turn.
  std::vector<double> total(V, 0);
  for (int h = 0; h < 3 * F; ++h) total[top.from(h)] += top.corner_angle(h);

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
  // Each disk patch meets each of its boundary vertices in one sector: its angle there, and
  // the two boundary edges that bound it (leaving and reaching the vertex along its border).
  struct Sector {
    double angle = 0, parameter_quarters = 0;
    int edge_out = -1, edge_in = -1;
  };
  std::vector<std::map<int, Sector>> sector(P);
  for (int p = 0; p < P; ++p)
    for (int h : patch_border[p]) {
      sector[p][top.from(h)].edge_out = top.edge(h);
      sector[p][top.to(h)].edge_in = top.edge(h);
    }
  for (int h = 0; h < 3 * F; ++h) {
    const int p = out.face_patch[h / 3];
    auto it = sector[p].find(top.from(h));
    if (it == sector[p].end()) continue;
    it->second.angle += top.corner_angle(h);
    if (!hints.parameter_quarters.empty())
      it->second.parameter_quarters += hints.parameter_quarters[h];
  }
  for (int p = 0; p < P; ++p) {
    if (!out.problem[p].empty()) continue;
    std::vector<std::pair<double, int>> by_turn;  // the sector in quarter turns, vertex
    for (const auto& [v, sec] : sector[p]) {
      double quarters = hints.parameter_quarters.empty()
                            ? sec.angle / total[v] * hints.field_quarters[v]
                            : sec.parameter_quarters;
      const int end = hints.ending_edge[v];
      if (end >= 0) quarters = end == sec.edge_out || end == sec.edge_in ? 1 : 2;
      by_turn.push_back({quarters, v});
    }
    std::sort(by_turn.begin(), by_turn.end());
    int k = 0;
    while (k < static_cast<int>(by_turn.size()) && by_turn[k].first < 1.5) ++k;
    // A patch the traces left with fewer than 3 or more than 6 corners (two traces meeting at a
    // sliver, a wiggly feature curve) still gets 3 to 6 corners, its sharpest turns: its
    // pattern then has a singularity, which is better than no layout.
    const int kept = std::clamp(k, 3, 6);
    if (kept != k) ++out.adjusted;
    for (int i = 0; i < std::min(kept, static_cast<int>(by_turn.size())); ++i)
      out.corners[p].push_back(by_turn[i].second);
    if (static_cast<int>(out.corners[p].size()) < 3)
      out.problem[p] = std::to_string(out.corners[p].size()) + " boundary vertices";
  }
  return out;
}

}  // namespace bimdf::layout
