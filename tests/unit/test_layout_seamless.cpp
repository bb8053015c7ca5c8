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
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

struct MapRun {
  layout::FieldIndices indices;
  layout::SeamlessMap map;
  // Per vertex: the sum of its faces' angles in the parameter plane, in quarter turns.
  std::vector<double> quarters;
};

MapRun parametrize(const TriangleMesh& mesh, layout::CrossFieldOptions field_options = {}) {
  const layout::Features features = layout::detect_features(mesh, {});
  const layout::CrossField field = layout::compute_cross_field(mesh, features, field_options);
  const layout::SurfaceTopology top(mesh);
  const layout::FaceFrames frames(mesh);
  MapRun r;
  r.indices = layout::field_indices(mesh, field);
  r.map = layout::seamless_parametrization(top, frames, field,
                                           layout::feature_edge_flags(top, features));
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

}  // namespace
}  // namespace bimdf
