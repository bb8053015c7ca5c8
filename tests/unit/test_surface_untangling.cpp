// The untangling descent of src/mesh/surface_untangling.hpp: on regions whose boundary is not
// convex (where Tutte's embedding folds) and on a curved surface, from scrambled inner
// vertices, every corner ends counter-clockwise about its quad's normal, fixed points stay.
// (Tutte's embedding of the C-shaped region below folds 44 of its corners.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/surface_untangling.hpp"

namespace bimdf::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An n × m grid whose point (i, j) lies at place(i / n, j / m); border points fixed.
QuadsOnSurface grid(int n, int m, const std::function<Vec3(double, double)>& place,
                    const std::function<Vec3(const Vec3&)>& normal_at) {
  QuadsOnSurface g;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      g.points.push_back(place(double(i) / n, double(j) / m));
      g.movable.push_back(i > 0 && i < n && j > 0 && j < m);
    }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      g.quads.push_back({a, a + 1, a + n + 2, a + n + 1});
      Vec3 centre{0, 0, 0};
      for (int v : g.quads.back()) centre = along(centre, 0.25, g.points[v]);
      g.normals.push_back(normal_at(centre));
    }
  return g;
}

// The smallest corner determinant (e_next × e_prev)·normal over the quads.
double smallest_corner(const QuadsOnSurface& g) {
  double lowest = 1e300;
  for (size_t f = 0; f < g.quads.size(); ++f)
    for (int i = 0; i < 4; ++i) {
      const Vec3& p = g.points[g.quads[f][i]];
      const Vec3 a = sub(g.points[g.quads[f][(i + 1) % 4]], p);
      const Vec3 b = sub(g.points[g.quads[f][(i + 3) % 4]], p);
      lowest = std::min(lowest, dot(cross(a, b), g.normals[f]));
    }
  return lowest;
}

// Moves every movable point to a random position among the region's points.
void scramble(QuadsOnSurface& g, unsigned seed) {
  std::mt19937 random(seed);
  const std::vector<Vec3> start = g.points;
  for (size_t p = 0; p < g.points.size(); ++p)
    if (g.movable[p]) g.points[p] = start[random() % start.size()];
  if (g.project)
    for (size_t p = 0; p < g.points.size(); ++p)
      if (g.movable[p]) g.points[p] = g.project(int(p), g.points[p]);
}

void expect_untangled(QuadsOnSurface g, double edge_length, unsigned seed) {
  const QuadsOnSurface start = g;
  scramble(g, seed);
  ASSERT_LT(smallest_corner(g), 0) << seed;
  const SurfaceUntangling result = untangle_quads_on_surface(g, edge_length);
  EXPECT_TRUE(result.untangled()) << seed << ": " << result.min_det_after;
  EXPECT_GT(smallest_corner(g), 0) << seed;
  for (size_t p = 0; p < g.points.size(); ++p)
    if (!g.movable[p]) {
      EXPECT_EQ(g.points[p], start.points[p]) << seed << " point " << p;
    }
}

// A C-shaped region: three quarters of an annulus, its inner border concave.
TEST(SurfaceUntangling, UntanglesAScrambledCShapeInThePlane) {
  const auto place = [](double s, double t) {
    const double angle = 1.5 * kPi * t, radius = 1 + s;
    return Vec3{radius * std::cos(angle), radius * std::sin(angle), 0};
  };
  const auto up = [](const Vec3&) { return Vec3{0, 0, 1}; };
  for (unsigned seed = 1; seed <= 10; ++seed) expect_untangled(grid(6, 18, place, up), 0.2, seed);
}

// A band around a cylinder (half its circumference), points projected back onto it.
TEST(SurfaceUntangling, UntanglesAScrambledBandOnACylinder) {
  const auto place = [](double s, double t) {
    const double angle = kPi * s;
    return Vec3{std::cos(angle), std::sin(angle), 1.5 * t};
  };
  const auto outward = [](const Vec3& p) { return normalized(Vec3{p[0], p[1], 0}); };
  for (unsigned seed = 1; seed <= 10; ++seed) {
    QuadsOnSurface g = grid(12, 8, place, outward);
    g.project = [](int, const Vec3& p) {
      const Vec3 r = normalized(Vec3{p[0], p[1], 0});
      return Vec3{r[0], r[1], p[2]};
    };
    expect_untangled(g, 0.2, seed);
  }
}

// A region with nothing to move, or with nothing tangled, is left as it is.
TEST(SurfaceUntangling, LeavesFixedAndUntangledRegionsAlone) {
  const auto place = [](double s, double t) { return Vec3{s, t, 0}; };
  const auto up = [](const Vec3&) { return Vec3{0, 0, 1}; };
  QuadsOnSurface fixed = grid(3, 3, place, up);
  fixed.movable.assign(fixed.points.size(), 0);
  const std::vector<Vec3> start = fixed.points;
  EXPECT_EQ(untangle_quads_on_surface(fixed, 1.0 / 3).rounds, 0);
  EXPECT_EQ(fixed.points, start);

  // A regular grid of the target size is where the energy is least: nothing moves.
  QuadsOnSurface square = grid(4, 4, place, up);
  const std::vector<Vec3> regular = square.points;
  const SurfaceUntangling result = untangle_quads_on_surface(square, 0.25);
  EXPECT_TRUE(result.untangled());
  EXPECT_NEAR(result.min_det_after, 1.0, 1e-9);
  for (size_t p = 0; p < regular.size(); ++p)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(square.points[p][d], regular[p][d], 1e-9) << p;
}

}  // namespace
}  // namespace bimdf::detail
