// The local untangling step (src/mesh/untangle.hpp) against a brute-force oracle: the best
// position it returns must be at least as good as every point of a fine grid over the disk,
// and no point of the grid may beat it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/untangle.hpp"
#include "mesh/vec3.hpp"
#include "test_helpers.hpp"

namespace bimdf::detail {
namespace {

// A 2 × 2 grid of unit quads in z = 0 whose centre vertex 4 sits at (cx, cy).
QuadMesh grid_with_centre(double cx, double cy) {
  QuadMesh m = testing::quad_grid_2x2();
  m.vertices[4] = {cx, cy, 0};
  return m;
}

// The smallest corner area of the quads at vertex 4 that touch it, each divided by the
// product of its edge lengths at `scale_at` (the mesh as given), with vertex 4 at p.
double smallest_corner(const QuadMesh& scale_at, Vec3 p) {
  QuadMesh m = scale_at;
  m.vertices[4] = p;
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& q : m.quads) {
    int k = 0;
    while (q[k] != 4) ++k;
    for (int corner : {k, (k + 1) % 4, (k + 3) % 4}) {
      const auto edge = [&](const QuadMesh& mesh, int to) {
        return sub(mesh.vertices[q[to]], mesh.vertices[q[corner]]);
      };
      const double scale =
          norm(edge(scale_at, (corner + 1) % 4)) * norm(edge(scale_at, (corner + 3) % 4));
      const double area = cross(edge(m, (corner + 1) % 4), edge(m, (corner + 3) % 4))[2];
      worst = std::min(worst, area / scale);
    }
  }
  return worst;
}

TEST(Untangle, FindsTheBestPositionOfATangledCentre) {
  const std::vector<Vec3> up(4, Vec3{0, 0, 1});
  const Vec3 t1{1, 0, 0}, t2{0, 1, 0};
  // Centre pulled outside the square (every quad at it tangled), near a side, and inside.
  for (const auto& [cx, cy, radius] : std::vector<std::array<double, 3>>{
           {2.4, 1.7, 1.5}, {0.2, 1.0, 1.0}, {1.3, 0.9, 0.5}, {1.9, 0.1, 0.3}}) {
    const QuadMesh m = grid_with_centre(cx, cy);
    const auto best = max_min_corner_position(m, 4, {0, 1, 2, 3}, up, t1, t2, radius);
    const Vec3 at = best ? *best : m.vertices[4];
    const double value = smallest_corner(m, at);
    // Inside the disk (the 16-gon inscribed in it contains the returned point).
    EXPECT_LE(std::hypot(at[0] - cx, at[1] - cy), radius * (1 + 1e-12)) << cx << " " << cy;
    EXPECT_EQ(at[2], 0);
    // The oracle: a 201 × 201 grid over the 16-gon's inscribed disk.
    const double inner = radius * std::cos(std::acos(-1.0) / 16);
    double oracle = smallest_corner(m, m.vertices[4]);
    for (int i = -100; i <= 100; ++i)
      for (int j = -100; j <= 100; ++j) {
        const double x = inner * i / 100, y = inner * j / 100;
        if (x * x + y * y <= inner * inner)
          oracle = std::max(oracle, smallest_corner(m, {cx + x, cy + y, 0}));
      }
    EXPECT_GE(value, oracle - 1e-12) << cx << " " << cy;
    // ...and not better than the true optimum over the 16-gon by more than the grid's reach.
    EXPECT_LE(value, oracle + 0.05) << cx << " " << cy;
  }
  // With room enough the tangled centre is untangled: back inside, all corners positive.
  const QuadMesh tangled = grid_with_centre(2.4, 1.7);
  const auto fixed = max_min_corner_position(tangled, 4, {0, 1, 2, 3}, up, t1, t2, 1.5);
  ASSERT_TRUE(fixed);
  EXPECT_GT(smallest_corner(tangled, *fixed), 0);
  EXPECT_LT(smallest_corner(tangled, tangled.vertices[4]), 0);
}

TEST(Untangle, NoCornerDependsOnTheVertex) {
  const QuadMesh m = grid_with_centre(1, 1);
  EXPECT_FALSE(max_min_corner_position(m, 4, {}, {}, {1, 0, 0}, {0, 1, 0}, 1));
}

TEST(Untangle, EnergyIsTheConditionNumberForValidQuadsAndFiniteForInvertedOnes) {
  const QuadMesh square = grid_with_centre(1, 1);
  const Vec3 up{0, 0, 1}, down{0, 0, -1};
  // A unit square: each corner (1 + 1) / (1 + √(1 + 4δ²)), → 1 as δ → 0.
  for (double delta : {0.0, 0.05, 0.5})
    EXPECT_NEAR(untangling_energy(square, square.quads[0], up, delta),
                4 * 2 / (1 + std::sqrt(1 + 4 * delta * delta)), 1e-15);
  // Seen from below every corner is inverted: finite with δ > 0, and far larger.
  EXPECT_TRUE(std::isinf(untangling_energy(square, square.quads[0], down, 0)) ||
              untangling_energy(square, square.quads[0], down, 0) > 1e300);
  const double upside_down = untangling_energy(square, square.quads[0], down, 0.05);
  EXPECT_TRUE(std::isfinite(upside_down));
  EXPECT_GT(upside_down, 100);
  // Pulling the centre out of the square tangles its quads; the energy grows all the way.
  double previous = 0;
  for (double x : {1.0, 1.5, 1.9, 2.1, 2.5}) {
    const QuadMesh m = grid_with_centre(x, x);
    double sum = 0;
    for (const auto& q : m.quads) sum += untangling_energy(m, q, up, 0.05);
    EXPECT_GT(sum, previous) << x;
    previous = sum;
  }
  // A zero-length edge: infinite.
  QuadMesh collapsed = square;
  collapsed.vertices[4] = collapsed.vertices[1];
  EXPECT_TRUE(std::isinf(untangling_energy(collapsed, collapsed.quads[0], up, 0.05)));
}

TEST(Untangle, NewtonDescentFindsTheMinimumAndAvoidsForbiddenPoints) {
  const Vec3 at{1, 2, 3}, t1{0, 1, 0}, t2{0, 0, 1};
  // An anisotropic bowl around (1, 2.3, 2.8): Newton lands on it.
  const auto bowl = [](const Vec3& p) {
    return 5 * (p[1] - 2.3) * (p[1] - 2.3) + (p[2] - 2.8) * (p[2] - 2.8) +
           (p[1] - 2.3) * (p[2] - 2.8);
  };
  const Vec3 p = descend_in_tangent_plane(bowl, at, t1, t2, 1.0, 5);
  EXPECT_NEAR(p[0], 1, 1e-12);
  EXPECT_NEAR(p[1], 2.3, 1e-6);
  EXPECT_NEAR(p[2], 2.8, 1e-6);
  // The same bowl with everything beyond y = 2.1 forbidden: it stops short, lower than it
  // started, and never in the forbidden part.
  const auto fenced = [&](const Vec3& q) {
    return q[1] > 2.1 ? std::numeric_limits<double>::infinity() : bowl(q);
  };
  const Vec3 r = descend_in_tangent_plane(fenced, at, t1, t2, 1.0, 20);
  EXPECT_LE(r[1], 2.1);
  EXPECT_LT(bowl(r), bowl(at));
  // A forbidden start: nothing moves.
  const auto nowhere = [](const Vec3&) { return std::numeric_limits<double>::infinity(); };
  EXPECT_EQ(descend_in_tangent_plane(nowhere, at, t1, t2, 1.0, 5), at);
}

}  // namespace
}  // namespace bimdf::detail
