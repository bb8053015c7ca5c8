// Collapse and tessellation of quantized T-meshes (tmesh/collapse.hpp): hand-built T-meshes
// reproduce their grid, double it, collapse zero-width strips and reject bad lengths; T-meshes
// traced from quad meshes and quantized by the exact solver collapse to conforming meshes or
// are refused. Smoothing and conforming layouts are tested in test_tmesh_layout.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "tmesh/separation_repair.hpp"
#include "tmesh/smooth_requantized.hpp"
#include "tmesh_collapse_support.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh {
namespace {

using namespace testsupport;

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
    // Points inside the strip's arcs keep their own positions, one on each line: where one
    // line is a curve, smoothing starts the vertex at its point there, not at the mean.
    if (o.tmesh_vertices.empty()) {
      ASSERT_EQ(o.arc_points.size(), 2u) << v;
      std::set<double> heights;
      for (const auto& [a, p] : o.arc_points) {
        heights.insert(p[1]);
        EXPECT_EQ(p[0], out.mesh.vertices[v][0]);
        EXPECT_TRUE(std::count(o.arcs.begin(), o.arcs.end(), a)) << v;
      }
      EXPECT_EQ(heights, (std::set<double>{2, 3})) << v;
    }
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

// requantize's collapse-failure repair: a cube whose vertical arcs want 0.2 collapses into a
// pillow (the top glued onto the bottom, every vertex inside two quads), which no non-zero path
// forbids. The repair bounds one zero element of the patches the failure names (the vertical
// arcs and the side faces' heights tie; the first found is bounded) and solves again: a 3 × 3 × 1
// box. With nothing zero there, it adds nothing.
TEST(TMeshCollapse, RequantizeBoundsAZeroElementWhereTheCollapseFails) {
  std::vector<int> axis;
  TracedTMesh traced;
  traced.tmesh = cube_tmesh(axis);
  for (int a = 0; a < traced.tmesh.num_arcs(); ++a)
    traced.tmesh.arc_target[a] = axis[a] == 2 ? 0.2 : 3;
  const TMesh& t = traced.tmesh;
  const TMeshQuantization plain = quantize_tmesh(t, incidence_of(t), {});
  ASSERT_EQ(plain.arc_length, cube_lengths(axis, {3, 3, 0}));
  std::vector<int> patches;
  try {
    collapse_and_tessellate(t, incidence_of(t), plain.arc_length, nullptr);
    FAIL() << "no CollapseError";
  } catch (const CollapseError& e) {
    patches = e.patches();
  }
  ASSERT_FALSE(patches.empty());
  MinOneConstraints bounds;
  EXPECT_FALSE(add_collapse_failure_bounds(t, plain.arc_length, {}, bounds));
  EXPECT_FALSE(add_collapse_failure_bounds(t, cube_lengths(axis, {3, 3, 1}), patches, bounds));
  ASSERT_TRUE(add_collapse_failure_bounds(t, plain.arc_length, patches, bounds));
  EXPECT_EQ(bounds.size(), 1);

  const RequantizeResult r = requantize_tmesh(traced, nullptr, {}, "cube");
  EXPECT_EQ(r.repair_rounds, 1);
  EXPECT_EQ(r.quantization.arc_length, cube_lengths(axis, {3, 3, 1}));
  EXPECT_EQ(r.collapsed.mesh.num_quads(), 2 * 9 + 4 * 3);
  const QuadMeshMetrics m = measure_quad_mesh(r.collapsed.mesh);
  EXPECT_TRUE(m.manifold());
  EXPECT_EQ(m.euler_characteristic, 2);
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
