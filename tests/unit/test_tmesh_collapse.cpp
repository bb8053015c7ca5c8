// Collapse and tessellation of quantized T-meshes, smoothing on the input, conforming layouts
// (tmesh/collapse.hpp, src/tmesh/smooth_requantized.hpp). The T-meshes are built by hand:
// rectangles of a grid mesh (with patch grids and arc chains), and a cube and a cylinder
// without a mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "tmesh/smooth_requantized.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh {
namespace {

using Vec3 = std::array<double, 3>;

struct Grid {
  QuadMesh mesh;
  int nx = 0, ny = 0;
  int id(int i, int j) const { return j * (nx + 1) + i; }
};

// An nx × ny grid of quads, counter-clockwise seen from +z; `curved` bends it and spaces it
// unevenly so that exact reproduction means something.
Grid grid_mesh(int nx, int ny, bool curved) {
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
TMeshIncidence incidence_of(const TMesh& t) {
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
TMesh tmesh_from_rectangles(const Grid& g, const std::vector<std::array<int, 4>>& rects) {
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

std::vector<int64_t> targets(const TMesh& t, int64_t factor = 1) {
  std::vector<int64_t> x;
  for (double v : t.arc_target) x.push_back(static_cast<int64_t>(v) * factor);
  return x;
}

// Collapses the arcs of target 1 of the strip layouts (their strips), keeps the others.
std::vector<int64_t> collapse_strips(const TMesh& t, int64_t factor) {
  std::vector<int64_t> x = targets(t, factor);
  for (int a = 0; a < t.num_arcs(); ++a)
    if (t.arc_target[a] == 1) x[a] = 0;
  return x;
}

// The unit cube as a T-mesh without a mesh: vertex x + 2y + 4z, one patch per face, one arc
// per edge (its direction class — 0 for x, 1 for y, 2 for z — in `axis`).
TMesh cube_tmesh(std::vector<int>& axis) {
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

std::vector<int64_t> cube_lengths(const std::vector<int>& axis, std::array<int64_t, 3> size) {
  std::vector<int64_t> x;
  for (int a : axis) x.push_back(size[a]);
  return x;
}

// Output vertex → input vertex at the same position (within 1e-12), or −1.
std::vector<int> match_positions(const QuadMesh& out, const QuadMesh& in) {
  std::vector<int> match(out.num_vertices(), -1);
  for (int v = 0; v < out.num_vertices(); ++v)
    for (int w = 0; w < in.num_vertices(); ++w) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(out.vertices[v][k] - in.vertices[w][k]));
      if (d <= 1e-12) match[v] = w;
    }
  return match;
}

// A quad as the rotation of its corners that starts at the smallest id.
std::array<int, 4> canonical(std::array<int, 4> q) {
  std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
  return q;
}

// Checks that `out` is `in` up to vertex numbering and returns the matching (out → in).
std::vector<int> expect_reproduces(const QuadMesh& out, const QuadMesh& in) {
  std::set<int> used;  // input vertices of quads (a fixture may leave one unused)
  for (const auto& q : in.quads) used.insert(q.begin(), q.end());
  EXPECT_EQ(static_cast<size_t>(out.num_vertices()), used.size());
  EXPECT_EQ(out.num_quads(), in.num_quads());
  const std::vector<int> match = match_positions(out, in);
  EXPECT_EQ(std::set<int>(match.begin(), match.end()), used);
  std::set<std::array<int, 4>> want, got;
  for (const auto& q : in.quads) want.insert(canonical(q));
  for (const auto& q : out.quads)
    got.insert(canonical({match[q[0]], match[q[1]], match[q[2]], match[q[3]]}));
  EXPECT_EQ(got, want);
  return match;
}

// Vertices on edges with a single quad.
std::set<int> border_vertices(const QuadMesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& q : m.quads)
    for (int a = 0; a < 4; ++a)
      ++count[{std::min(q[a], q[(a + 1) % 4]), std::max(q[a], q[(a + 1) % 4])}];
  std::set<int> border;
  for (const auto& [e, n] : count)
    if (n == 1) border.insert(e.first), border.insert(e.second);
  return border;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  double ab2 = 0, t = 0;
  for (int d = 0; d < 3; ++d)
    ab2 += (b[d] - a[d]) * (b[d] - a[d]), t += (p[d] - a[d]) * (b[d] - a[d]);
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (int d = 0; d < 3; ++d) d2 += std::pow(a[d] + t * (b[d] - a[d]) - p[d], 2);
  return std::sqrt(d2);
}

// The largest distance from a border vertex of `out` to the border of `in`.
double border_deviation(const QuadMesh& out, const QuadMesh& in) {
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
const std::vector<std::array<int, 4>> kTwoByTwo{
    {0, 0, 2, 1}, {2, 0, 4, 1}, {0, 1, 2, 3}, {2, 1, 4, 3}};
// A T-junction: one patch on the left, two on the right, meeting at (2, 1) on its side 1.
const std::vector<std::array<int, 4>> kTJunction{{0, 0, 2, 2}, {2, 0, 4, 1}, {2, 1, 4, 2}};
// A thin strip (height 1, split in two at x = 2) between two patches of a 4 × 5 grid.
// A thin strip along the border (height 1, split in two at x = 2) below a 4 × 3 patch.
const std::vector<std::array<int, 4>> kBorderStrip{{0, 0, 2, 1}, {2, 0, 4, 1}, {0, 1, 4, 4}};
const std::vector<std::array<int, 4>> kStrip{
    {0, 0, 4, 2}, {0, 2, 2, 3}, {2, 2, 4, 3}, {0, 3, 4, 5}};

TEST(TMeshCollapse, HandBuiltTMeshesAreValid) {
  // The fixtures above agree with validate_tmesh (tmesh.hpp) and its incidence.
  std::vector<TMesh> meshes;
  for (const auto& [rects, nx, ny] : {std::tuple{kTwoByTwo, 4, 3}, std::tuple{kTJunction, 4, 2},
                                      std::tuple{kStrip, 4, 5}, std::tuple{kBorderStrip, 4, 4}})
    meshes.push_back(tmesh_from_rectangles(grid_mesh(nx, ny, true), rects));
  std::vector<int> axis;
  meshes.push_back(cube_tmesh(axis));
  for (const TMesh& t : meshes) {
    const TMeshIncidence inc = validate_tmesh(t, "fixture");
    EXPECT_EQ(inc.half_arc_patch, incidence_of(t).half_arc_patch);
    EXPECT_EQ(inc.half_arc_side, incidence_of(t).half_arc_side);
  }
}

TEST(TMeshCollapse, TargetLengthsReproduceTheInputMesh) {
  for (const auto& [rects, nx, ny] : {std::tuple{kTwoByTwo, 4, 3}, std::tuple{kTJunction, 4, 2},
                                      std::tuple{kStrip, 4, 5}, std::tuple{kBorderStrip, 4, 4}}) {
    const Grid g = grid_mesh(nx, ny, true);
    const TMesh t = tmesh_from_rectangles(g, rects);
    const CollapsedMesh out = collapse_and_tessellate(t, incidence_of(t), targets(t), &g.mesh);
    const std::vector<int> match = expect_reproduces(out.mesh, g.mesh);
    EXPECT_EQ(out.zero_arcs, 0);
    EXPECT_EQ(out.collapsed_patches, 0);
    // Every quad lies in the rectangle of the patch it was made for.
    for (int f = 0; f < out.mesh.num_quads(); ++f) {
      const auto& [i0, j0, i1, j1] = rects[out.mesh.quad_patch[f]];
      for (int v : out.mesh.quads[f]) {
        const int i = match[v] % (nx + 1), j = match[v] / (nx + 1);
        EXPECT_TRUE(i0 <= i && i <= i1 && j0 <= j && j <= j1) << "quad " << f;
      }
    }
  }
}

TEST(TMeshCollapse, DoublingEveryLengthGivesFourTimesTheQuads) {
  for (const auto& [rects, nx, ny] : {std::tuple{kTwoByTwo, 4, 3}, std::tuple{kTJunction, 4, 2},
                                      std::tuple{kStrip, 4, 5}, std::tuple{kBorderStrip, 4, 4}}) {
    const Grid g = grid_mesh(nx, ny, true);
    const TMesh t = tmesh_from_rectangles(g, rects);
    const CollapsedMesh out = collapse_and_tessellate(t, incidence_of(t), targets(t, 2), &g.mesh);
    EXPECT_EQ(out.mesh.num_quads(), 4 * g.mesh.num_quads());
    EXPECT_EQ(out.mesh.num_vertices(), (2 * nx + 1) * (2 * ny + 1));
    const QuadMeshMetrics m = measure_quad_mesh(out.mesh);
    EXPECT_TRUE(m.manifold());
    EXPECT_EQ(m.euler_characteristic, 1);
    EXPECT_EQ(m.inverted + m.degenerate, 0);
    // Every input vertex is an output vertex (every other grid line is an input grid line).
    const std::vector<int> match = match_positions(g.mesh, out.mesh);
    EXPECT_EQ(std::count(match.begin(), match.end(), -1), 0);
  }
}

TEST(TMeshCollapse, ZeroWidthStripCollapses) {
  const Grid g = grid_mesh(4, 5, false);
  const TMesh t = tmesh_from_rectangles(g, kStrip);
  const TMeshIncidence inc = incidence_of(t);
  // The strip's three vertical arcs are its only arcs of length 1.
  const CollapsedMesh out = collapse_and_tessellate(t, inc, collapse_strips(t, 1), &g.mesh);
  EXPECT_EQ(out.zero_arcs, 3);
  EXPECT_EQ(out.collapsed_patches, 2);
  EXPECT_EQ(out.mesh.num_quads(), 16);
  EXPECT_EQ(out.mesh.num_vertices(), 25);
  const QuadMeshMetrics before = measure_quad_mesh(g.mesh), after = measure_quad_mesh(out.mesh);
  EXPECT_TRUE(after.manifold());
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_EQ(after.degenerate + after.inverted, 0);
  EXPECT_TRUE(after.interior_singularities.empty());
  // The strip's lower and upper lines became one, at their mean height.
  int merged = 0;
  for (int v = 0; v < out.mesh.num_vertices(); ++v) {
    const CollapsedVertex& o = out.origin[v];
    if (std::abs(out.mesh.vertices[v][1] - 2.5) > 1e-12) continue;
    ++merged;
    EXPECT_TRUE(o.tmesh_vertices.size() == 2 || o.tmesh_vertices.empty()) << v;
    EXPECT_TRUE(std::count(o.patches.begin(), o.patches.end(), 1) +
                    std::count(o.patches.begin(), o.patches.end(), 2) >
                0);
  }
  EXPECT_EQ(merged, 5);
}

TEST(TMeshCollapse, ZeroArcAtTJunction) {
  const Grid g = grid_mesh(4, 2, false);
  const TMesh t = tmesh_from_rectangles(g, kTJunction);
  std::vector<int64_t> x = targets(t);
  // The lower right patch gets height 0: its vertical sides are zero arcs, one of them ends
  // at the T-junction, which lands on the border.
  for (int a = 0; a < t.num_arcs(); ++a) {
    const Vec3& p = g.mesh.vertices[t.arc_chain[a].front()];
    const Vec3& q = g.mesh.vertices[t.arc_chain[a].back()];
    if (p[0] == q[0] && p[0] >= 2) x[a] = std::min(p[1], q[1]) == 0 ? 0 : 2;
    if (p[0] == q[0] && p[0] == 0) x[a] = 2;
  }
  const CollapsedMesh out = collapse_and_tessellate(t, incidence_of(t), x, &g.mesh);
  EXPECT_EQ(out.mesh.num_quads(), 8);
  EXPECT_EQ(out.mesh.num_vertices(), 15);
  const QuadMeshMetrics m = measure_quad_mesh(out.mesh);
  EXPECT_TRUE(m.manifold());
  EXPECT_EQ(m.euler_characteristic, 1);
  EXPECT_EQ(m.degenerate + m.inverted, 0);
  EXPECT_EQ(out.collapsed_patches, 1);
}

TEST(TMeshCollapse, CubeWithoutMesh) {
  std::vector<int> axis;
  const TMesh t = cube_tmesh(axis);
  const CollapsedMesh out =
      collapse_and_tessellate(t, incidence_of(t), cube_lengths(axis, {3, 3, 3}), nullptr);
  EXPECT_EQ(out.mesh.num_quads(), 54);
  EXPECT_EQ(out.mesh.num_vertices(), 56);
  const QuadMeshMetrics m = measure_quad_mesh(out.mesh);
  EXPECT_TRUE(m.manifold());
  EXPECT_EQ(m.euler_characteristic, 2);
  EXPECT_EQ(m.boundary_edges, 0);
  EXPECT_EQ(m.interior_singularities, (std::map<int, int>{{3, 8}}));
  EXPECT_EQ(m.inverted + m.degenerate, 0);
  EXPECT_NEAR(m.scaled_jacobian_min, 1, 1e-12);  // flat faces, evenly spaced: squares
  // Twice the same input, twice the same output.
  const CollapsedMesh again =
      collapse_and_tessellate(t, incidence_of(t), cube_lengths(axis, {3, 3, 3}), nullptr);
  EXPECT_EQ(again.mesh.quads, out.mesh.quads);
  EXPECT_EQ(again.mesh.vertices, out.mesh.vertices);
}

TEST(TMeshCollapse, SingularVerticesMergingIsRefused) {
  // Height 0 along z: the four side faces collapse, each bottom corner (valence 3) merges with
  // the top corner above it, and the cube becomes a pillow of two quads per grid cell.
  std::vector<int> axis;
  const TMesh t = cube_tmesh(axis);
  try {
    collapse_and_tessellate(t, incidence_of(t), cube_lengths(axis, {2, 2, 0}), nullptr);
    FAIL() << "no CollapseError";
  } catch (const CollapseError& e) {
    EXPECT_STREQ(e.what(),
                 "T-mesh vertices 0 and 4 would become an interior vertex of only two quads");
  }
  try {
    collapse_and_tessellate(t, incidence_of(t), cube_lengths(axis, {0, 2, 0}), nullptr);
    FAIL() << "no CollapseError";
  } catch (const CollapseError& e) {
    EXPECT_STREQ(e.what(), "every patch would collapse (width or height 0): no quad is left");
  }
}

TEST(TMeshCollapse, SelfGluedPatchIsRefused) {
  // A cylinder of two patches, P from b0 to b1 and Q from b1 back to b0 (vertices b0 = 0,
  // b1 = 1, t0 = 2, t1 = 3). P of width 0 glues Q's two vertical sides; Q one quad wide then
  // has its left and right corners in one vertex.
  TMesh t;
  t.vertices = {{1, 0, 0}, {-1, 0, 0}, {1, 0, 1}, {-1, 0, 1}};
  t.arc_ends = {{0, 1}, {1, 0}, {2, 3}, {3, 2}, {0, 2}, {1, 3}};
  t.arc_target.assign(6, 1);
  t.patch_sides = {{{{0}, {10}, {5}, {9}}}, {{{2}, {8}, {7}, {11}}}};
  try {
    collapse_and_tessellate(t, incidence_of(t), {0, 1, 0, 1, 1, 1}, nullptr);
    FAIL() << "no CollapseError";
  } catch (const CollapseError& e) {
    EXPECT_STREQ(e.what(),
                 "patch 1: quad (0, 0) would have two corners at T-mesh vertices 0 and 1");
  }
  // Three quads wide, Q closes into a valid band.
  const CollapsedMesh band =
      collapse_and_tessellate(t, incidence_of(t), {0, 3, 0, 3, 1, 1}, nullptr);
  EXPECT_EQ(band.mesh.num_quads(), 3);
  EXPECT_EQ(measure_quad_mesh(band.mesh).euler_characteristic, 0);
}

TEST(TMeshCollapse, BadLengthsAreRejected) {
  const Grid g = grid_mesh(4, 2, false);
  const TMesh t = tmesh_from_rectangles(g, kTJunction);
  const TMeshIncidence inc = incidence_of(t);
  const auto message = [&](const std::vector<int64_t>& x) {
    try {
      collapse_and_tessellate(t, inc, x, &g.mesh);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({1, 2}), "2 arc lengths for " + std::to_string(t.num_arcs()) + " arcs");
  std::vector<int64_t> x = targets(t);
  x[0] = -1;
  EXPECT_EQ(message(x), "arc 0: length -1, expected 0 to 2^28");
  x = targets(t);
  x[0] += 1;  // arc 0 is patch 0's bottom side
  EXPECT_EQ(message(x),
            "patch 0: sides 0 and 2 have lengths 3 and 2, opposite sides must be equal");
}

TEST(TMeshSmoothing, KeepsTheBorderAndNeverInverts) {
  for (const auto& [rects, nx, ny, factor, strip] :
       {std::tuple{kTwoByTwo, 4, 3, 2, false}, std::tuple{kTJunction, 4, 2, 3, false},
        std::tuple{kStrip, 4, 5, 1, true}, std::tuple{kBorderStrip, 4, 4, 2, true}}) {
    const Grid g = grid_mesh(nx, ny, true);
    const TMesh t = tmesh_from_rectangles(g, rects);
    const TMeshIncidence inc = incidence_of(t);
    CollapsedMesh out = collapse_and_tessellate(
        t, inc, strip ? collapse_strips(t, factor) : targets(t, factor), &g.mesh);
    const QuadMesh before = out.mesh;
    smooth_requantized(g.mesh, t, inc, {}, {}, out, quant::SmoothingOptions{});
    EXPECT_EQ(out.mesh.quads, before.quads);
    if (rects == kBorderStrip) {  // the merged border starts half a strip inside
      EXPECT_GT(border_deviation(before, g.mesh), 0.4);
    }
    EXPECT_LT(border_deviation(out.mesh, g.mesh), 1e-9);
    const TriangleMesh surface = requantization_layout(g.mesh, t, inc, {}, {}).mesh;
    const QuadMeshMetrics m = measure_quad_mesh(out.mesh, &surface);
    EXPECT_EQ(m.inverted + m.degenerate + m.flipped, 0);
    EXPECT_GT(m.scaled_jacobian_min, 0.5);
    EXPECT_GE(m.scaled_jacobian_mean, measure_quad_mesh(before).scaled_jacobian_mean);
    EXPECT_LT(m.hausdorff_relative, 0.01);
    // The grid's corners stay.
    for (const Vec3& c : {g.mesh.vertices[g.id(0, 0)], g.mesh.vertices[g.id(nx, ny)]})
      EXPECT_EQ(std::count(out.mesh.vertices.begin(), out.mesh.vertices.end(), c), 1);
  }
}

TEST(TMeshSmoothing, FeatureCurvesAndCornersStay) {
  // The line j = 1 of the 2 × 2 patches is a feature curve, its middle (2, 1) a feature corner.
  const Grid g = grid_mesh(4, 3, true);
  TMesh t = tmesh_from_rectangles(g, kTwoByTwo);
  std::vector<int> feature_line;
  for (int i = 0; i <= 4; ++i) feature_line.push_back(g.id(i, 1));
  for (int a = 0; a < t.num_arcs(); ++a)
    t.arc_feature[a] = std::all_of(t.arc_chain[a].begin(), t.arc_chain[a].end(),
                                   [&](int m) { return m / 5 == 1; });
  const TMeshIncidence inc = incidence_of(t);
  CollapsedMesh out = collapse_and_tessellate(t, inc, targets(t, 3), &g.mesh);
  const QuadMesh before = out.mesh;
  smooth_requantized(g.mesh, t, inc, {}, {g.id(2, 1)}, out, quant::SmoothingOptions{});
  int on_line = 0, moved = 0;
  for (int v = 0; v < out.mesh.num_vertices(); ++v) {
    moved += out.mesh.vertices[v] != before.vertices[v];
    const auto& arcs = out.origin[v].arcs;
    if (arcs.size() != 1 || !t.arc_feature[arcs[0]]) continue;
    ++on_line;
    double d = 1e300;
    for (int i = 0; i < 4; ++i)
      d = std::min(d, distance_to_segment(out.mesh.vertices[v], g.mesh.vertices[feature_line[i]],
                                          g.mesh.vertices[feature_line[i + 1]]));
    EXPECT_LT(d, 1e-9) << v;
  }
  EXPECT_EQ(on_line, 10);  // 5 interior points on each of the two feature arcs
  EXPECT_GT(moved, 0);
  EXPECT_EQ(
      std::count(out.mesh.vertices.begin(), out.mesh.vertices.end(), g.mesh.vertices[g.id(2, 1)]),
      1);
  EXPECT_EQ(measure_quad_mesh(out.mesh).inverted, 0);
}

TEST(TMeshSmoothing, LayoutMatchesTheTMesh) {
  const Grid g = grid_mesh(4, 2, true);
  const TMesh t = tmesh_from_rectangles(g, kTJunction);
  const quant::Layout layout = requantization_layout(g.mesh, t, incidence_of(t), {}, {});
  ASSERT_EQ(layout.mesh.num_faces(), 16);
  EXPECT_EQ(layout.charts[0].faces.size(), 8u);
  EXPECT_EQ(layout.charts[1].faces.size(), 4u);
  ASSERT_EQ(layout.subsides.size(), size_t(t.num_arcs()));
  int border = 0;
  for (const quant::Subside& s : layout.subsides) border += s.on_border();
  EXPECT_EQ(border, 7);  // the left patch's left, bottom and top; two on each right patch
  // Each chart's sides start at its corners.
  for (int p = 0; p < t.num_patches(); ++p)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(layout.charts[p].corners[k],
                t.vertex_mesh_vertex[t.half_arc_tail(t.patch_sides[p][k][0])]);
}

TEST(ConformingLayout, GridIsOnePatch) {
  const Grid g = grid_mesh(5, 3, true);
  const ConformingLayout layout = conforming_layout(g.mesh);
  ASSERT_EQ(layout.patch_corners.size(), 1u);
  EXPECT_EQ(layout.patch_side_length[0], (std::array<int64_t, 4>{5, 3, 5, 3}));
  EXPECT_EQ(layout.patch_corners[0],
            (std::array<int, 4>{g.id(0, 0), g.id(5, 0), g.id(5, 3), g.id(0, 3)}));
  EXPECT_EQ(layout.face_patch, std::vector<int>(15, 0));
  EXPECT_EQ(layout.patch_side_chain[0][1],
            (std::vector<int>{g.id(5, 0), g.id(5, 1), g.id(5, 2), g.id(5, 3)}));
}

TEST(ConformingLayout, FeatureEdgesCut) {
  const Grid g = grid_mesh(5, 3, false);
  // A feature line from the bottom border up to (2, 2). Its end is a feature corner that
  // traces on in every direction (up, left, right), so the layout is four rectangles, not a
  // slit one. Patches are numbered by their first quad.
  const ConformingLayout layout =
      conforming_layout(g.mesh, {{g.id(2, 0), g.id(2, 1)}, {g.id(2, 1), g.id(2, 2)}});
  ASSERT_EQ(layout.patch_corners.size(), 4u);
  EXPECT_EQ(layout.patch_side_length[0], (std::array<int64_t, 4>{2, 2, 2, 2}));
  EXPECT_EQ(layout.patch_side_length[1], (std::array<int64_t, 4>{3, 2, 3, 2}));
  EXPECT_EQ(layout.patch_side_length[2], (std::array<int64_t, 4>{2, 1, 2, 1}));
  EXPECT_EQ(layout.patch_side_length[3], (std::array<int64_t, 4>{3, 1, 3, 1}));
  EXPECT_EQ(layout.patch_corners[3],
            (std::array<int, 4>{g.id(2, 2), g.id(5, 2), g.id(5, 3), g.id(2, 3)}));
  try {
    conforming_layout(g.mesh, {{g.id(0, 0), g.id(1, 1)}});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "feature edge (0, 7) is not an edge of the mesh");
  }
}

TEST(ConformingLayout, SubdividedCubeHasSixEqualPatches) {
  std::vector<int> axis;
  const TMesh t = cube_tmesh(axis);
  for (int64_t n : {1, 2, 4}) {
    const QuadMesh cube =
        collapse_and_tessellate(t, incidence_of(t), cube_lengths(axis, {n, n, n}), nullptr).mesh;
    const ConformingLayout layout = conforming_layout(cube);
    ASSERT_EQ(layout.patch_corners.size(), 6u);
    for (const auto& sides : layout.patch_side_length)
      EXPECT_EQ(sides, (std::array<int64_t, 4>{n, n, n, n}));
  }
}

TEST(ConformingLayout, CatmullClarkCubeHasSixEqualPatches) {
  for (int levels = 1; levels <= 3; ++levels) {
    const ConformingLayout layout = conforming_layout(test::subdivided_cube(levels));
    ASSERT_EQ(layout.patch_corners.size(), 6u);
    const int64_t n = int64_t{1} << levels;
    for (const auto& sides : layout.patch_side_length)
      EXPECT_EQ(sides, (std::array<int64_t, 4>{n, n, n, n}));
    // Every corner is one of the cube's corners (ids 0..7).
    for (const auto& corners : layout.patch_corners)
      for (int v : corners) EXPECT_LT(v, 8);
  }
}

TEST(ConformingLayout, AgreesWithTheBaseComplex) {
  // Without features the cuts are those of measure_quad_mesh's base complex.
  std::vector<QuadMesh> meshes{test::thin_strip_mesh()};
  for (uint64_t seed = 0; seed < 40; ++seed) meshes.push_back(test::random_quad_mesh(seed));
  for (size_t k = 0; k < meshes.size(); ++k) {
    const QuadMesh& mesh = meshes[k];
    const ConformingLayout layout = conforming_layout(mesh);
    EXPECT_EQ(static_cast<int>(layout.patch_corners.size()),
              measure_quad_mesh(mesh).base_complex_faces)
        << "mesh " << k;
    // Sides are chains of mesh edges from corner to corner.
    for (size_t p = 0; p < layout.patch_corners.size(); ++p)
      for (int s = 0; s < 4; ++s) {
        const auto& chain = layout.patch_side_chain[p][s];
        EXPECT_EQ(chain.front(), layout.patch_corners[p][s]);
        EXPECT_EQ(chain.back(), layout.patch_corners[p][(s + 1) % 4]);
      }
  }
}

TEST(ConformingLayout, ClosedGridWithoutCornersIsRefused) {
  try {
    conforming_layout(test::torus_mesh(12, 12));
    FAIL() << "no CollapseError";
  } catch (const CollapseError& e) {
    EXPECT_STREQ(e.what(), "base complex patch 0 (with quad 0) has 0 corners, expected 4");
  }
}

TEST(ConformingLayout, CollapsedStripLayout) {
  // The collapsed strip (see ZeroWidthStripCollapses) is a 4 × 4 grid: one patch again.
  const Grid g = grid_mesh(4, 5, false);
  const TMesh t = tmesh_from_rectangles(g, kStrip);
  const CollapsedMesh out =
      collapse_and_tessellate(t, incidence_of(t), collapse_strips(t, 1), &g.mesh);
  const ConformingLayout layout = conforming_layout(out.mesh);
  ASSERT_EQ(layout.patch_corners.size(), 1u);
  EXPECT_EQ(layout.patch_side_length[0], (std::array<int64_t, 4>{4, 4, 4, 4}));
}

TEST(ConformingLayout, ObjFormat) {
  const Grid g = grid_mesh(2, 1, false);
  std::ostringstream out;
  write_layout_obj(out, g.mesh, conforming_layout(g.mesh));
  EXPECT_EQ(out.str(),
            "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
            "g patch_0\n# sides 2 1 2 1\nf 1 3 6 4\nl 1 2 3\nl 3 6\nl 6 5 4\nl 4 1\n");
}

// T-meshes traced from quad meshes (from_quad_mesh.hpp) and validated (tmesh.hpp).
std::vector<std::pair<std::string, QuadMesh>> traced_inputs() {
  std::vector<std::pair<std::string, QuadMesh>> meshes{
      {"grid", test::grid_mesh(5, 3)},
      {"thin strip", test::thin_strip_mesh()},
      {"cube 2", test::subdivided_cube(2)},
      {"folded grid", test::folded_grid(6, 4, 3, 60)}};
  for (uint64_t seed = 0; seed < 12; ++seed) {
    std::string description;
    QuadMesh mesh = test::random_quad_mesh(seed, &description);
    meshes.emplace_back("random " + std::to_string(seed) + " (" + description + ")", mesh);
  }
  return meshes;
}

TEST(TMeshCollapseTraced, TargetsReproduceAndDoublingQuadruples) {
  for (const auto& [name, mesh] : traced_inputs()) {
    SCOPED_TRACE(name);
    const TracedTMesh traced = trace_tmesh(mesh, TraceOptions{}, name);
    const TMesh& t = traced.tmesh;
    const TMeshIncidence inc = validate_tmesh(t, name);
    expect_reproduces(collapse_and_tessellate(t, inc, targets(t), &mesh).mesh, mesh);
    CollapsedMesh twice = collapse_and_tessellate(t, inc, targets(t, 2), &mesh);
    EXPECT_EQ(twice.mesh.num_quads(), 4 * mesh.num_quads());
    const QuadMeshMetrics in = measure_quad_mesh(mesh), out = measure_quad_mesh(twice.mesh);
    EXPECT_EQ(out.euler_characteristic, in.euler_characteristic);
    EXPECT_EQ(out.interior_singularities, in.interior_singularities);
    EXPECT_EQ(out.boundary_singularities, in.boundary_singularities);
    EXPECT_EQ(out.base_complex_faces, in.base_complex_faces);
    // The same conforming layout, every side twice as long.
    const ConformingLayout before = conforming_layout(mesh);
    smooth_requantized(mesh, t, inc, traced.feature_edges, traced.feature_corners, twice,
                       quant::SmoothingOptions{});
    const ConformingLayout after = conforming_layout(twice.mesh);
    // Patches are numbered by their first quad and start at their smallest corner, which
    // both differ: compare the patches' sizes as a multiset.
    const auto sizes = [](const ConformingLayout& layout, int64_t factor) {
      std::multiset<std::pair<int64_t, int64_t>> out;
      for (const auto& x : layout.patch_side_length)
        out.insert({factor * std::min(x[0], x[1]), factor * std::max(x[0], x[1])});
      return out;
    };
    EXPECT_EQ(sizes(after, 1), sizes(before, 2));
    const QuadMeshMetrics smoothed = measure_quad_mesh(twice.mesh, nullptr);
    // Degenerate quads only where the input has them (a quad alone at a straight border).
    EXPECT_EQ(smoothed.inverted, 0);
    EXPECT_EQ(smoothed.degenerate, in.degenerate);
    EXPECT_GE(smoothed.scaled_jacobian_mean, out.scaled_jacobian_mean - 1e-9);
    EXPECT_LT(border_deviation(twice.mesh, mesh), 1e-9);
  }
}

// Quantizations from the exact solver (quantize.hpp), with zero arcs.
TMeshQuantization quantized(const TMesh& t, const TMeshIncidence& inc, bool coarse) {
  QuantizeOptions options;
  options.coarse = coarse;
  return quantize_tmesh(t, inc, options);
}

TEST(TMeshCollapseQuantized, ThinStripCollapses) {
  // At half density the staircase's one-quad strip between its reflex corners A and B
  // (thin_strip_mesh) goes: its arcs across are 0, the strip patch collapses.
  const QuadMesh mesh = test::thin_strip_mesh();
  TraceOptions trace;
  trace.density = 0.5;
  const TracedTMesh traced = trace_tmesh(mesh, trace, "thin strip");
  const TMesh& t = traced.tmesh;
  const TMeshIncidence inc = validate_tmesh(t, "thin strip");
  const TMeshQuantization q = quantized(t, inc, false);
  ASSERT_EQ(q.status, SolveStatus::Optimal);
  CollapsedMesh out = collapse_and_tessellate(t, inc, q.arc_length, &mesh);
  EXPECT_GT(out.zero_arcs, 0);
  EXPECT_GE(out.collapsed_patches, 1);
  const QuadMeshMetrics in = measure_quad_mesh(mesh), m = measure_quad_mesh(out.mesh);
  EXPECT_TRUE(m.manifold());
  EXPECT_EQ(m.euler_characteristic, in.euler_characteristic);
  EXPECT_EQ(m.boundary_singularities, in.boundary_singularities);
  EXPECT_EQ(m.degenerate, 0);
  // A and B (and every T-mesh vertex) stay apart: no vertex holds two seeds.
  for (const CollapsedVertex& o : out.origin) {
    int seeds = 0;
    for (int v : o.tmesh_vertices)
      seeds += std::count(traced.seeds.begin(), traced.seeds.end(), t.vertex_mesh_vertex[v]) > 0;
    EXPECT_LE(seeds, 1);
  }
  smooth_requantized(mesh, t, inc, traced.feature_edges, traced.feature_corners, out,
                     quant::SmoothingOptions{});
  const QuadMeshMetrics smoothed = measure_quad_mesh(out.mesh);
  EXPECT_EQ(smoothed.inverted + smoothed.degenerate, 0);
  EXPECT_GT(smoothed.scaled_jacobian_min, 0.5);
  EXPECT_LT(border_deviation(out.mesh, mesh), 1e-9);
  // A's and B's separatrices now run on one grid line: the layout has fewer patches.
  EXPECT_LT(conforming_layout(out.mesh).patch_corners.size(),
            conforming_layout(mesh).patch_corners.size());
}

TEST(TMeshCollapseQuantized, CollapseIsConformingOrRefused) {
  // Whatever the solver returns, collapse gives a conforming mesh (a conforming layout
  // exists, smoothing adds no inverted quad) or a CollapseError, never anything else.
  int collapsed = 0;
  for (const auto& [name, mesh] : traced_inputs())
    for (const double density : {0.5, 1.0})
      for (const bool coarse : {false, true}) {
        SCOPED_TRACE(name + ", density " + std::to_string(density) + (coarse ? ", coarse" : ""));
        TraceOptions trace;
        trace.density = density;
        const TracedTMesh traced = trace_tmesh(mesh, trace, name);
        const TMesh& t = traced.tmesh;
        const TMeshIncidence inc = validate_tmesh(t, name);
        const TMeshQuantization q = quantized(t, inc, coarse);
        ASSERT_EQ(q.status, SolveStatus::Optimal);
        CollapsedMesh out;
        try {
          out = collapse_and_tessellate(t, inc, q.arc_length, &mesh);
        } catch (const CollapseError&) {
          continue;
        }
        const QuadMeshMetrics in = measure_quad_mesh(mesh), m = measure_quad_mesh(out.mesh);
        EXPECT_TRUE(m.manifold());
        // Where the solver kept every singularity apart (not always the case yet), smoothing
        // ends without inverted quads: collapsed vertices find their place.
        const bool kept = m.interior_singularities == in.interior_singularities &&
                          m.boundary_singularities == in.boundary_singularities;
        collapsed += kept && out.collapsed_patches > 0;
        smooth_requantized(mesh, t, inc, traced.feature_edges, traced.feature_corners, out,
                           quant::SmoothingOptions{});
        if (kept) {
          EXPECT_EQ(measure_quad_mesh(out.mesh).inverted, 0);
        }
        EXPECT_LT(border_deviation(out.mesh, mesh), 1e-9);
        EXPECT_NO_THROW(conforming_layout(out.mesh));
      }
  EXPECT_GT(collapsed, 0);
}

}  // namespace
}  // namespace bimdf::tmesh
