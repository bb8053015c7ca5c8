// Patch labels and corners of a cut mesh (patches.hpp).
#include "layout/patches.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

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
  out.not_disk.assign(P, false);

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
      out.not_disk[p] = true;
      out.problem[p] = euler != 1
                           ? "not a disk (Euler characteristic " + std::to_string(euler) + ")"
                           : "its boundary touches itself";
    }
  }
  // Each disk patch meets each of its boundary vertices in one sector: its angle there, and
  // the two boundary edges that bound it (leaving and reaching the vertex along its border).
  struct Sector {
    double angle = 0, parameter_quarters = 0;
    bool folded = false;  // a face of the sector is folded (or flat) in the parameter plane
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
    if (!hints.parameter_quarters.empty()) {
      it->second.parameter_quarters += hints.parameter_quarters[h];
      it->second.folded |= hints.parameter_quarters[h] <= 0;
    }
  }
  for (int p = 0; p < P; ++p) {
    if (!out.problem[p].empty()) continue;
    std::vector<std::pair<double, int>> by_turn;  // the sector in quarter turns, vertex
    for (const auto& [v, sec] : sector[p]) {
      // Where the map folds, its angles mean nothing: the sector's share of the field's turns.
      const double share = sec.angle / total[v] * hints.field_quarters[v];
      double quarters =
          hints.parameter_quarters.empty() || sec.folded ? share : sec.parameter_quarters;
      // A sector the map reads as a corner where the surface is flat (CornerHints::flat_share).
      if (hints.flat_share > 0 && !hints.parameter_quarters.empty() && !sec.folded &&
          !top.on_border(v) && quarters < 1.5 && share > hints.flat_share)
        quarters = share;
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

namespace bimdf::layout {

int cut_across_non_disks(const SurfaceTopology& top, const Patches& patches,
                         std::vector<bool>& boundary_edge, CornerHints& hints) {
  constexpr int kSeveral = -3;  // a vertex on two boundary loops, or on a slit
  const TriangleMesh& m = top.mesh();
  const int F = m.num_faces(), V = m.num_vertices();
  int cuts = 0;
  std::vector<std::vector<int>> faces_of(patches.problem.size());
  for (int f = 0; f < F; ++f)
    if (patches.not_disk[patches.face_patch[f]]) faces_of[patches.face_patch[f]].push_back(f);
  std::vector<int> loop(V, -1), parent(V, -2), parent_edge(V, -1);
  for (const std::vector<int>& faces : faces_of) {
    if (faces.empty()) continue;
    std::vector<int> verts;
    for (int f : faces)
      for (int v : m.faces[f]) loop[v] = -1, parent[v] = -2, verts.push_back(v);
    const int p = patches.face_patch[faces[0]];
    // Edges the flood does not cross: those to another patch or the mesh border (the patch's
    // true boundary), and trace or curve edges with the patch on both sides (slits: a trace
    // across an annulus leaves an annulus cut open along it, one patch, not a chart).
    const auto across = [&](int h) {
      const int g = top.opposite(h);
      return g < 0 || patches.face_patch[g / 3] != p;
    };
    const auto on_border = [&](int h) { return across(h) || boundary_edge[top.edge(h)]; };
    // The true boundary's loops: cycles of its half-edges, each continued by the next one
    // round the vertex it reaches. A cycle that passes a vertex twice (the patch wrapped round
    // an island it touches there) counts as two loops, split there. A vertex on two loops or on
    // a slit belongs to none: a path through or from it would pinch a patch there.
    std::set<int> walked;
    int loops = 0;
    const auto mark = [&](int v, int l) { loop[v] = loop[v] == -1 || loop[v] == l ? l : kSeveral; };
    for (int f : faces)
      for (int i = 0; i < 3; ++i) {
        const int h0 = 3 * f + i;
        if (!across(h0) || walked.count(h0)) continue;
        std::vector<int> cycle;
        for (int h = h0; walked.insert(h).second;) {
          cycle.push_back(top.from(h));
          int g = SurfaceTopology::next(h);
          while (!across(g)) g = SurfaceTopology::next(top.opposite(g));
          h = g;
        }
        std::map<int, size_t> first_visit;
        size_t a = 0, b = 0;
        for (size_t k = 0; k < cycle.size() && b == 0; ++k) {
          const auto [it, fresh] = first_visit.emplace(cycle[k], k);
          if (!fresh) a = it->second, b = k;
        }
        for (size_t k = 0; k < cycle.size(); ++k)
          mark(cycle[k], b > 0 && k > a && k < b ? loops + 1 : loops);
        if (b > 0) loop[cycle[a]] = kSeveral;
        loops += b > 0 ? 2 : 1;
      }
    for (int f : faces)
      for (int i = 0; i < 3; ++i)
        if (on_border(3 * f + i) && !across(3 * f + i))
          for (int v : {top.from(3 * f + i), top.to(3 * f + i)}) loop[v] = kSeveral;
    if (loops < 2) continue;
    // Breadth first from loop 0 through the patch's inside to the first vertex of another
    // loop: that path, made a boundary, joins the two loops (an annulus becomes a disk).
    std::vector<int> queue;
    for (int v : verts)
      if (loop[v] == 0 && parent[v] == -2) parent[v] = -1, queue.push_back(v);
    int reached = -1;
    for (size_t q = 0; q < queue.size() && reached < 0; ++q) {
      const int v = queue[q];
      for (int h : top.outgoing(v)) {
        if (patches.face_patch[h / 3] != p || on_border(h)) continue;
        const int w = top.to(h);
        if (parent[w] != -2) continue;
        parent[w] = v, parent_edge[w] = top.edge(h);
        if (loop[w] == kSeveral) continue;  // a pinch joins nothing
        if (loop[w] > 0) {
          reached = w;
          break;
        }
        if (loop[w] < 0) queue.push_back(w);
      }
    }
    if (reached < 0) continue;
    // Where it reaches the other loop it ends like a trace ending on a line (a T-junction).
    if (hints.ending_edge[reached] < 0) hints.ending_edge[reached] = parent_edge[reached];
    for (int v = reached; parent[v] >= 0; v = parent[v]) boundary_edge[parent_edge[v]] = true;
    ++cuts;
  }
  return cuts;
}

}  // namespace bimdf::layout
