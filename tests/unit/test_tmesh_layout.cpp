// Smoothing of collapsed T-meshes on the input surface (src/tmesh/smooth_requantized.hpp) and
// conforming layouts of quad meshes (tmesh/collapse.hpp): borders, feature curves and corners
// stay, nothing inverts; layouts of grids, cubes and random meshes, feature cuts, refusals and
// the OBJ form.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "tmesh/smooth_requantized.hpp"
#include "tmesh_collapse_support.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh {
namespace {

using namespace testsupport;

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

}  // namespace
}  // namespace bimdf::tmesh
