// Hand-built T-meshes shared by the collapse and layout tests (test_tmesh_collapse.cpp,
// test_tmesh_layout.cpp): rectangles of a grid mesh (with patch grids and arc chains), the cube
// without a mesh, their target lengths and incidence, and distances to a mesh's border.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh::testsupport {

using Vec3 = std::array<double, 3>;

struct Grid {
  QuadMesh mesh;
  int nx = 0, ny = 0;
  int id(int i, int j) const { return j * (nx + 1) + i; }
};

// An nx × ny grid of quads, counter-clockwise seen from +z; `curved` bends it and spaces it
// unevenly so that exact reproduction means something.
inline Grid grid_mesh(int nx, int ny, bool curved) {
  Grid g;
  g.nx = nx, g.ny = ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      g.mesh.vertices.push_back(
          curved ? Vec3{i + 0.2 * std::sin(j + 0.5 * i), j + 0.1 * i * i / nx, 0.05 * i * j}
                 : Vec3{double(i), double(j), 0});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      g.mesh.quads.push_back({g.id(i, j), g.id(i + 1, j), g.id(i + 1, j + 1), g.id(i, j + 1)});
      g.mesh.quad_patch.push_back(-1);
    }
  return g;
}

// What validate_tmesh derives, computed here so that these tests stand alone.
inline TMeshIncidence incidence_of(const TMesh& t) {
  TMeshIncidence inc;
  inc.half_arc_patch.assign(t.num_half_arcs(), -1);
  inc.half_arc_side.assign(t.num_half_arcs(), -1);
  for (int p = 0; p < t.num_patches(); ++p)
    for (int k = 0; k < 4; ++k)
      for (int h : t.patch_sides[p][k]) inc.half_arc_patch[h] = p, inc.half_arc_side[h] = k;
  return inc;
}

// A T-mesh whose patches are the rectangles [i0, i1] × [j0, j1] of grid g (they must tile
// it): T-mesh vertices are their corners, arcs the pieces of their sides between T-mesh
// vertices, oriented as first walked; targets are the arcs' numbers of mesh edges.
inline TMesh tmesh_from_rectangles(const Grid& g, const std::vector<std::array<int, 4>>& rects) {
  TMesh t;
  std::map<int, int> vertex_of;  // grid vertex → T-mesh vertex
  for (const auto& [i0, j0, i1, j1] : rects)
    for (int m : {g.id(i0, j0), g.id(i1, j0), g.id(i1, j1), g.id(i0, j1)})
      if (vertex_of.emplace(m, t.num_vertices()).second) {
        t.vertices.push_back(g.mesh.vertices[m]);
        t.vertex_mesh_vertex.push_back(m);
      }
  std::map<std::pair<int, int>, int> arc_of;  // sorted end grid vertices → arc
  for (const auto& [i0, j0, i1, j1] : rects) {
    const std::array<std::array<int, 2>, 5> corner{
        {{i0, j0}, {i1, j0}, {i1, j1}, {i0, j1}, {i0, j0}}};
    std::array<std::vector<int>, 4> sides;
    for (int k = 0; k < 4; ++k) {
      const auto [a, b] = corner[k];
      const auto [c, d] = corner[k + 1];
      const int n = std::abs(c - a) + std::abs(d - b);
      std::vector<int> chain{g.id(a, b)};
      for (int s = 1; s <= n; ++s) {
        chain.push_back(g.id(a + (c - a) / n * s, b + (d - b) / n * s));
        if (!vertex_of.count(chain.back())) continue;
        const std::pair<int, int> key{std::min(chain.front(), chain.back()),
                                      std::max(chain.front(), chain.back())};
        auto [it, added] = arc_of.emplace(key, t.num_arcs());
        if (added) {
          t.arc_ends.push_back({vertex_of[chain.front()], vertex_of[chain.back()]});
          t.arc_chain.push_back(chain);
          t.arc_target.push_back(double(chain.size() - 1));
          t.arc_feature.push_back(0);
        }
        sides[k].push_back(2 * it->second + (t.arc_chain[it->second].front() != chain.front()));
        chain = {chain.back()};
      }
    }
    t.patch_sides.push_back(sides);
    PatchGrid grid;
    grid.width = i1 - i0, grid.height = j1 - j0;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) grid.vertices.push_back(g.id(i, j));
    t.patch_grid.push_back(grid);
  }
  return t;
}

inline std::vector<int64_t> targets(const TMesh& t, int64_t factor = 1) {
  std::vector<int64_t> x;
  for (double v : t.arc_target) x.push_back(static_cast<int64_t>(v) * factor);
  return x;
}

// Collapses the arcs of target 1 of the strip layouts (their strips), keeps the others.
inline std::vector<int64_t> collapse_strips(const TMesh& t, int64_t factor) {
  std::vector<int64_t> x = targets(t, factor);
  for (int a = 0; a < t.num_arcs(); ++a)
    if (t.arc_target[a] == 1) x[a] = 0;
  return x;
}

// The unit cube as a T-mesh without a mesh: vertex x + 2y + 4z, one patch per face, one arc
// per edge (its direction class — 0 for x, 1 for y, 2 for z — in `axis`).
inline TMesh cube_tmesh(std::vector<int>& axis) {
  TMesh t;
  for (int v = 0; v < 8; ++v)
    t.vertices.push_back({double(v & 1), double(v >> 1 & 1), double(v >> 2)});
  const std::vector<std::array<int, 4>> faces{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::map<std::pair<int, int>, int> arc_of;
  axis.clear();
  for (const auto& f : faces) {
    std::array<std::vector<int>, 4> sides;
    for (int k = 0; k < 4; ++k) {
      const int u = f[k], v = f[(k + 1) % 4];
      auto [it, added] = arc_of.emplace(std::pair{std::min(u, v), std::max(u, v)}, t.num_arcs());
      if (added) {
        t.arc_ends.push_back({u, v});
        t.arc_target.push_back(1);
        axis.push_back((u ^ v) == 1 ? 0 : (u ^ v) == 2 ? 1 : 2);
      }
      sides[k] = {2 * it->second + (t.arc_ends[it->second][0] != u)};
    }
    t.patch_sides.push_back(sides);
  }
  return t;
}

inline std::vector<int64_t> cube_lengths(const std::vector<int>& axis,
                                         std::array<int64_t, 3> size) {
  std::vector<int64_t> x;
  for (int a : axis) x.push_back(size[a]);
  return x;
}

// Vertices on edges with a single quad.
inline std::set<int> border_vertices(const QuadMesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& q : m.quads)
    for (int a = 0; a < 4; ++a)
      ++count[{std::min(q[a], q[(a + 1) % 4]), std::max(q[a], q[(a + 1) % 4])}];
  std::set<int> border;
  for (const auto& [e, n] : count)
    if (n == 1) border.insert(e.first), border.insert(e.second);
  return border;
}

inline double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  double ab2 = 0, t = 0;
  for (int d = 0; d < 3; ++d)
    ab2 += (b[d] - a[d]) * (b[d] - a[d]), t += (p[d] - a[d]) * (b[d] - a[d]);
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (int d = 0; d < 3; ++d) d2 += std::pow(a[d] + t * (b[d] - a[d]) - p[d], 2);
  return std::sqrt(d2);
}

// The largest distance from a border vertex of `out` to the border of `in`.
inline double border_deviation(const QuadMesh& out, const QuadMesh& in) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& q : in.quads)
    for (int a = 0; a < 4; ++a)
      ++count[{std::min(q[a], q[(a + 1) % 4]), std::max(q[a], q[(a + 1) % 4])}];
  double worst = 0;
  for (int v : border_vertices(out)) {
    double best = 1e300;
    for (const auto& [e, n] : count)
      if (n == 1)
        best = std::min(best, distance_to_segment(out.vertices[v], in.vertices[e.first],
                                                  in.vertices[e.second]));
    worst = std::max(worst, best);
  }
  return worst;
}

// 2 × 2 patches of a 4 × 3 grid.
inline const std::vector<std::array<int, 4>> kTwoByTwo{
    {0, 0, 2, 1}, {2, 0, 4, 1}, {0, 1, 2, 3}, {2, 1, 4, 3}};
// A T-junction: one patch on the left, two on the right, meeting at (2, 1) on its side 1.
inline const std::vector<std::array<int, 4>> kTJunction{{0, 0, 2, 2}, {2, 0, 4, 1}, {2, 1, 4, 2}};
// A thin strip along the border (height 1, split in two at x = 2) below a 4 × 3 patch.
inline const std::vector<std::array<int, 4>> kBorderStrip{{0, 0, 2, 1}, {2, 0, 4, 1}, {0, 1, 4, 4}};
// A thin strip (height 1, split in two at x = 2) between two patches of a 4 × 5 grid.
inline const std::vector<std::array<int, 4>> kStrip{
    {0, 0, 4, 2}, {0, 2, 2, 3}, {2, 2, 4, 3}, {0, 3, 4, 5}};

}  // namespace bimdf::tmesh::testsupport
