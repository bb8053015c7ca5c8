// The cross field (src/layout/cross_field.cpp): the index theorem on every field, singularities
// where the surface's shape forces them, alignment to borders, creases and curvature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bimdf/layout/cross_field.hpp"
#include "bimdf/layout/surface.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

struct FieldRun {
  layout::CrossField field;
  layout::FieldIndices indices;
  int euler = 0;
};

FieldRun run(const TriangleMesh& mesh, layout::CrossFieldOptions options = {}) {
  FieldRun r;
  const layout::Features features = layout::detect_features(mesh, {});
  r.field = layout::compute_cross_field(mesh, features, options);
  r.indices = layout::field_indices(mesh, r.field);
  r.euler = layout::describe_surface(mesh).euler_characteristic;
  // The index theorem holds on every field, and every vertex's turning is a whole quarter.
  EXPECT_EQ(r.indices.quarter_index_sum, 4 * r.euler);
  EXPECT_LT(r.indices.max_rounding, 1e-6);
  for (const auto& d : r.field.direction)
    EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1, 1e-9);
  return r;
}

// How far direction d is, as a cross, from the cross of axis-aligned directions in the plane
// with normal n (radians, 0..π/4), for a tangent frame (a, b).
double off_cross(const std::array<double, 3>& d, const std::array<double, 3>& a,
                 const std::array<double, 3>& b) {
  const double x = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
  const double y = d[0] * b[0] + d[1] * b[1] + d[2] * b[2];
  const double t = std::atan2(y, x);
  return std::fabs(t - (M_PI / 2) * std::round(t / (M_PI / 2)));
}

TEST(LayoutCrossField, CubeHasItsEightCornersAsValenceThreeSingularities) {
  const TriangleMesh cube = test::cube(4);
  const FieldRun r = run(cube);
  ASSERT_EQ(r.indices.singularities.size(), 8u);
  for (const auto& s : r.indices.singularities) {
    EXPECT_EQ(s.quarter_index, 1);
    for (double c : cube.vertices[s.vertex]) EXPECT_EQ(std::fabs(c), 1.0);
  }
  // Every face is axis-aligned: the field follows the creases throughout.
  for (int f = 0; f < cube.num_faces(); ++f) {
    const auto& d = r.field.direction[f];
    int axis_components = 0;
    for (double c : d) axis_components += std::fabs(std::fabs(c) - 1) < 1e-6;
    EXPECT_EQ(axis_components, 1) << "face " << f;
  }
}

TEST(LayoutCrossField, SquareFollowsItsBorderWithoutInteriorSingularities) {
  const TriangleMesh sq = test::square(1, 6);
  const FieldRun r = run(sq);
  EXPECT_EQ(r.euler, 1);
  ASSERT_EQ(r.indices.singularities.size(), 4u);  // the four corners, +1 each
  for (const auto& s : r.indices.singularities) {
    EXPECT_TRUE(s.on_border);
    EXPECT_EQ(s.quarter_index, 1);
  }
  for (const auto& d : r.field.direction) EXPECT_LT(off_cross(d, {1, 0, 0}, {0, 1, 0}), 1e-6);
}

// The square grid [−1, 1]² mapped onto the unit disc (x√(1 − y²/2), y√(1 − x²/2)).
TriangleMesh disc(int n) {
  TriangleMesh m = test::square(2, n);
  for (auto& p : m.vertices) {
    const double x = p[0] - 1, y = p[1] - 1;
    p = {x * std::sqrt(1 - y * y / 2), y * std::sqrt(1 - x * x / 2), 0};
  }
  return m;
}

// disc(n) as the lid of a can: a wall of `rings` rings below its border, 2/n apart, open at
// the bottom; the rim is a right-angled crease.
TriangleMesh can(int n, int rings) {
  TriangleMesh m = disc(n);
  std::vector<int> rim;
  for (int v = 0; v < m.num_vertices(); ++v)
    if (std::hypot(m.vertices[v][0], m.vertices[v][1]) > 1 - 1e-9) rim.push_back(v);
  std::sort(rim.begin(), rim.end(), [&](int a, int b) {
    return std::atan2(m.vertices[a][1], m.vertices[a][0]) <
           std::atan2(m.vertices[b][1], m.vertices[b][0]);
  });
  const int R = static_cast<int>(rim.size());
  std::vector<int> above = rim;
  for (int k = 1; k <= rings; ++k) {
    std::vector<int> ring;
    for (int v : rim) {
      ring.push_back(m.num_vertices());
      m.vertices.push_back({m.vertices[v][0], m.vertices[v][1], -2.0 * k / n});
    }
    // The disc is counter-clockwise seen from +z: the wall's faces point outwards.
    for (int i = 0; i < R; ++i) {
      const int j = (i + 1) % R;
      m.faces.push_back({above[i], ring[i], ring[j]});
      m.faces.push_back({above[i], ring[j], above[j]});
    }
    above = ring;
  }
  return m;
}

TEST(LayoutCrossField, ACansLidGetsItsFourSingularitiesSpreadApart) {
  // Following the rim, the field turns once inside the lid: four valence-3 singularities. The
  // linear solve alone, pulled round by the rim's curvature, crowds two of them near the
  // centre (polar wedges of patches there); pulled towards unit length they spread out.
  const TriangleMesh m = can(24, 8);
  std::vector<double> closest;
  for (int rounds : {0, 10}) {
    layout::CrossFieldOptions o;
    o.unit_rounds = rounds;
    const FieldRun r = run(m, o);
    std::vector<std::array<double, 3>> at;
    for (const auto& s : r.indices.singularities) {
      EXPECT_FALSE(s.on_border);
      EXPECT_EQ(s.quarter_index, 1);
      at.push_back(m.vertices[s.vertex]);
    }
    ASSERT_EQ(at.size(), 4u);
    closest.push_back(1e9);
    for (size_t i = 0; i < at.size(); ++i) {
      EXPECT_NEAR(at[i][2], 0, 1e-12);  // on the lid
      for (size_t j = i + 1; j < at.size(); ++j)
        closest.back() =
            std::min(closest.back(), std::hypot(at[i][0] - at[j][0], at[i][1] - at[j][1]));
    }
  }
  EXPECT_LT(closest[0], 0.45);
  EXPECT_GT(closest[1], 0.6);
}

TEST(LayoutCrossField, SphereGetsTheSmoothestFieldWithEightQuarterSingularities) {
  layout::CrossFieldOptions o;
  o.align_to_curvature = false;  // nothing to align to: the smoothest field
  const FieldRun r = run(test::icosphere(3), o);
  EXPECT_EQ(r.field.smoothest_components, 1);
  EXPECT_EQ(r.indices.quarter_index_sum, 8);
  EXPECT_EQ(r.indices.singularities.size(), 8u);
  for (const auto& s : r.indices.singularities) EXPECT_EQ(s.quarter_index, 1);
  // With curvature alignment the sphere's noise is followed, and the theorem still holds.
  const FieldRun aligned = run(test::icosphere(3));
  EXPECT_EQ(aligned.field.smoothest_components, 0);
}

TEST(LayoutCrossField, TorusAndCylinderFollowTheirPrincipalDirections) {
  // A torus of revolution: curvature lines are the parallels and meridians, no singularity.
  const int n = 48, m = 16;
  const TriangleMesh torus = test::torus(3, 1, n, m);
  const FieldRun t = run(torus);
  EXPECT_TRUE(t.indices.singularities.empty());
  for (int f = 0; f < torus.num_faces(); ++f) {
    const auto& tri = torus.faces[f];
    std::array<double, 3> c{};
    for (int v : tri)
      for (int k = 0; k < 3; ++k) c[k] += torus.vertices[v][k] / 3;
    const double u = std::atan2(c[1], c[0]);
    const std::array<double, 3> around = {-std::sin(u), std::cos(u), 0};
    // The meridian's tangent at the face, orthogonal to the parallel and the face normal.
    const auto& a = torus.vertices[tri[0]];
    const auto& b = torus.vertices[tri[1]];
    const auto& d = torus.vertices[tri[2]];
    const std::array<double, 3> e1 = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const std::array<double, 3> e2 = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    std::array<double, 3> nrm = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                 e1[0] * e2[1] - e1[1] * e2[0]};
    const std::array<double, 3> meridian = {nrm[1] * around[2] - nrm[2] * around[1],
                                            nrm[2] * around[0] - nrm[0] * around[2],
                                            nrm[0] * around[1] - nrm[1] * around[0]};
    const double len = std::sqrt(meridian[0] * meridian[0] + meridian[1] * meridian[1] +
                                 meridian[2] * meridian[2]);
    EXPECT_LT(off_cross(t.field.direction[f], around,
                        {meridian[0] / len, meridian[1] / len, meridian[2] / len}),
              0.1)  // the grid's diagonals bias the curvature estimate by up to ~4° here
        << "face " << f;
  }
  // An open cylinder: its two border circles fix the field; no singularity anywhere.
  const FieldRun c = run(test::cylinder(2, 32, 8));
  EXPECT_TRUE(c.indices.singularities.empty());
}

TEST(LayoutCrossField, SeveralPiecesEachKeepTheTheorem) {
  const TriangleMesh three = test::combine(
      test::combine(test::cube(3), test::torus(3, 1, 32, 12), 5), test::square(1, 4), 12);
  const FieldRun r = run(three);
  EXPECT_EQ(r.euler, 2 + 0 + 1);
  int cube_corners = 0, square_corners = 0, other = 0;
  for (const auto& s : r.indices.singularities) {
    if (s.on_border)
      square_corners += s.quarter_index == 1;
    else if (s.quarter_index == 1 && s.vertex < test::cube(3).num_vertices())
      ++cube_corners;
    else
      ++other;
  }
  EXPECT_EQ(cube_corners, 8);
  EXPECT_EQ(square_corners, 4);
  EXPECT_EQ(other, 0);
}

}  // namespace
}  // namespace bimdf
