// The seamless parametrization (src/layout/seamless.cpp): exact where the field is a gradient,
// and seamless everywhere — around every vertex the faces' angles in the parameter plane add up
// to the field's quarter turns there (4 at a regular vertex, 4 − the quarter index at a
// singular one), so iso-lines continue across every edge and the singularities are cones.
#include <gtest/gtest.h>

#include <cmath>

#include "bimdf/layout/cross_field.hpp"
#include "bimdf/layout/surface.hpp"
#include "layout/feature_flags.hpp"
#include "layout/seamless.hpp"
#include "layout/singularity_pairs.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

struct MapRun {
  layout::FieldIndices indices;
  layout::SeamlessMap map;
  // Per vertex: the sum of its faces' angles in the parameter plane, in quarter turns.
  std::vector<double> quarters;
};

// The map of `field` (curves: the border) and its cone angles; `offset`: SeamlessOptions'
// matching_offset, which r.indices then include.
MapRun parametrize_field(const TriangleMesh& mesh, const layout::CrossField& field,
                         const std::vector<bool>& curve, const std::vector<int>& offset = {}) {
  const layout::SurfaceTopology top(mesh);
  const layout::FaceFrames frames(mesh);
  MapRun r;
  r.indices = layout::field_indices(mesh, field, offset);
  layout::SeamlessOptions options;
  options.matching_offset = offset;
  r.map = layout::seamless_parametrization(top, frames, field, curve, options);
  r.quarters.assign(mesh.num_vertices(), 0);
  for (int h = 0; h < 3 * mesh.num_faces(); ++h) {
    const auto& g = r.map.gradient[h / 3];
    const auto& o = mesh.vertices[top.from(h)];
    const auto x = detail::sub(mesh.vertices[top.to(h)], o);
    const auto y = detail::sub(mesh.vertices[top.from(layout::SurfaceTopology::prev(h))], o);
    const double xu = detail::dot(g[0], x), xv = detail::dot(g[1], x);
    const double yu = detail::dot(g[0], y), yv = detail::dot(g[1], y);
    r.quarters[top.from(h)] += std::atan2(xu * yv - xv * yu, xu * yu + xv * yv) / (M_PI / 2);
  }
  return r;
}

MapRun parametrize(const TriangleMesh& mesh, layout::CrossFieldOptions field_options = {}) {
  const layout::Features features = layout::detect_features(mesh, {});
  const layout::CrossField field = layout::compute_cross_field(mesh, features, field_options);
  const layout::SurfaceTopology top(mesh);
  return parametrize_field(mesh, field, layout::feature_edge_flags(top, features));
}

// Every interior vertex closes up into a cone of the field's quarter turns (up to the closure
// penalty's residue: a wrong matching would be off by whole quarters).
void expect_seamless(const TriangleMesh& mesh, const MapRun& r) {
  const layout::SurfaceTopology top(mesh);
  EXPECT_EQ(r.map.folded_faces, 0);
  EXPECT_LT(r.map.max_closure, 1e-3);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (top.on_border(v)) continue;
    EXPECT_NEAR(r.quarters[v], 4 - r.indices.quarter_index[v], 1e-4) << "vertex " << v;
  }
}

TEST(LayoutSeamless, SquareIsMappedExactly) {
  const TriangleMesh square = test::square(2, 6);
  const MapRun r = parametrize(square);
  expect_seamless(square, r);
  EXPECT_LT(r.map.mean_distortion, 1e-6);
  // Border corners are right angles of the map, straight border vertices straight.
  const layout::SurfaceTopology top(square);
  int corners = 0;
  for (int v = 0; v < square.num_vertices(); ++v) {
    if (!top.on_border(v)) continue;
    const double q = r.quarters[v];
    EXPECT_NEAR(q, std::round(q), 1e-6) << "vertex " << v;
    corners += std::round(q) == 1;
  }
  EXPECT_EQ(corners, 4);
}

TEST(LayoutSeamless, SphereAndCubeAreConesAtTheirSingularities) {
  layout::CrossFieldOptions smoothest;
  smoothest.align_to_curvature = false;
  const TriangleMesh sphere = test::icosphere(3);
  const MapRun s = parametrize(sphere, smoothest);
  expect_seamless(sphere, s);
  int cones = 0;
  for (int v = 0; v < sphere.num_vertices(); ++v) cones += std::fabs(s.quarters[v] - 4) > 0.5;
  EXPECT_EQ(cones, 8);  // the field's 8 valence-3 singularities, each a cone of 3 quarters

  const TriangleMesh cube = test::cube(3);
  const MapRun c = parametrize(cube);
  expect_seamless(cube, c);
  EXPECT_LT(c.map.mean_distortion, 1e-6);  // the cube's faces are flat and the field exact
}

TEST(LayoutSeamless, TorusFollowsItsPrincipalDirectionsWithoutCones) {
  const TriangleMesh torus = test::torus(3, 1, 48, 16);
  const MapRun t = parametrize(torus);
  expect_seamless(torus, t);
  for (int v = 0; v < torus.num_vertices(); ++v) EXPECT_NEAR(t.quarters[v], 4, 1e-4);
}

// A ± pair of field singularities 0.4 apart on a flat square (edges 0.2): u = e^{4iθ} winds
// once around p and back around q. Cancelled (singularity_pairs.hpp), neither is a cone of the
// map — every interior vertex closes up flat — and the index sum is unchanged; not cancelled,
// they are cones of 3 and 5 quarters. Farther apart than the radius, or on a kept vertex, the
// pair stays.
TEST(LayoutSeamless, ACloseSingularityPairIsLeftOutOfTheMap) {
  const TriangleMesh square = test::square(2, 10);
  const layout::SurfaceTopology top(square);
  const double px = 0.8, qx = 1.2, y = 1.02;  // inside faces, off the vertices
  layout::CrossField field;
  for (const auto& t : square.faces) {
    const double cx =
        (square.vertices[t[0]][0] + square.vertices[t[1]][0] + square.vertices[t[2]][0]) / 3;
    const double cy =
        (square.vertices[t[0]][1] + square.vertices[t[1]][1] + square.vertices[t[2]][1]) / 3;
    const double theta = (std::atan2(cy - y, cx - px) - std::atan2(cy - y, cx - qx)) / 4;
    field.direction.push_back({std::cos(theta), std::sin(theta), 0});
  }
  field.fixed.assign(square.num_faces(), false);
  field.curvature_weight.assign(square.num_faces(), 0);
  std::vector<bool> border(top.num_edges());
  for (int e = 0; e < top.num_edges(); ++e) border[e] = top.opposite(top.edge_half_edge(e)) < 0;
  const std::vector<bool> keep = layout::vertices_of_edges(top, border);

  const MapRun plain = parametrize_field(square, field, border);
  std::vector<int> inside;  // the interior singular vertices: one +1, one −1
  for (const auto& s : plain.indices.singularities)
    if (!s.on_border) inside.push_back(s.vertex);
  ASSERT_EQ(inside.size(), 2u);
  const int plus = plain.indices.quarter_index[inside[0]] == 1 ? inside[0] : inside[1];
  const int minus = inside[0] + inside[1] - plus;
  ASSERT_EQ(plain.indices.quarter_index[plus], 1);
  ASSERT_EQ(plain.indices.quarter_index[minus], -1);
  EXPECT_NEAR(plain.quarters[plus], 3, 1e-4);
  EXPECT_NEAR(plain.quarters[minus], 5, 1e-4);

  const layout::CancelledPairs cancelled =
      layout::cancel_close_pairs(top, plain.indices, keep, 0.5);
  ASSERT_EQ(cancelled.pairs.size(), 1u);
  EXPECT_EQ(cancelled.pairs[0], (std::array<int, 2>{plus, minus}));
  const MapRun flat = parametrize_field(square, field, border, cancelled.matching_offset);
  EXPECT_EQ(flat.indices.quarter_index_sum, plain.indices.quarter_index_sum);
  EXPECT_LT(flat.map.max_closure, 1e-3);
  for (int v = 0; v < square.num_vertices(); ++v) {
    if (top.on_border(v)) continue;
    EXPECT_EQ(flat.indices.quarter_index[v], 0) << "vertex " << v;
    EXPECT_NEAR(flat.quarters[v], 4, 1e-4) << "vertex " << v;
  }

  EXPECT_TRUE(layout::cancel_close_pairs(top, plain.indices, keep, 0.3).pairs.empty());
  std::vector<bool> keep_plus = keep;
  keep_plus[plus] = true;
  EXPECT_TRUE(layout::cancel_close_pairs(top, plain.indices, keep_plus, 0.5).pairs.empty());
  const layout::CancelledPairs none = layout::cancel_close_pairs(top, plain.indices, keep, 0);
  EXPECT_TRUE(none.pairs.empty());
  EXPECT_EQ(none.matching_offset, std::vector<int>(top.num_edges(), 0));
}

}  // namespace
}  // namespace bimdf
