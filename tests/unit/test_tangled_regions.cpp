// Re-embedding tangled regions (src/mesh/tangled_regions.hpp) on a flat grid, where the plane
// is the surface and the barycentric embedding of a convex region is one-to-one: it untangles
// folds that no single-vertex move can, moves only free vertices inside the regions, and
// keeps the old positions where the new ones are not better.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "mesh/quad_quality.hpp"
#include "mesh/tangled_regions.hpp"

namespace bimdf::detail {
namespace {

struct Grid {
  QuadMesh mesh;
  std::vector<std::vector<int>> vertex_quads, neighbours;
  int n = 0;
  int id(int i, int j) const { return j * (n + 1) + i; }
  bool inside(int v) const {
    const int i = v % (n + 1), j = v / (n + 1);
    return i > 0 && i < n && j > 0 && j < n;
  }
};

// An n × n grid of unit squares on z = 0.
Grid grid(int n) {
  Grid g;
  g.n = n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.mesh.vertices.push_back({double(i), double(j), 0});
  g.vertex_quads.resize(g.mesh.vertices.size());
  g.neighbours.resize(g.mesh.vertices.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::array<int, 4> q{g.id(i, j), g.id(i + 1, j), g.id(i + 1, j + 1), g.id(i, j + 1)};
      for (int a = 0; a < 4; ++a) {
        g.vertex_quads[q[a]].push_back(g.mesh.num_quads());
        g.neighbours[q[a]].push_back(q[(a + 1) % 4]);
        g.neighbours[q[(a + 1) % 4]].push_back(q[a]);
      }
      g.mesh.quads.push_back(q);
    }
  for (std::vector<int>& around : g.neighbours) {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  return g;
}

int count_inverted(const QuadMesh& mesh) {
  int count = 0;
  for (const auto& q : mesh.quads) count += scaled_jacobian(mesh, q, {0, 0, 1}) < 0;
  return count;
}

TangledRegionInput input_for(Grid& g, std::function<void(const std::vector<int>&)> smooth) {
  const auto on_plane = [](int, const Vec3& p) { return Vec3{p[0], p[1], 0}; };
  return {{g.mesh, g.vertex_quads, g.neighbours, on_plane},
          [&g](int v) {
            return g.inside(v) ? TangledRegionInput::Freedom::kFree
                               : TangledRegionInput::Freedom::kPinned;
          },
          [&g](int f) {
            const double up = scaled_jacobian(g.mesh, g.mesh.quads[f], {0, 0, 1});
            return std::array<double, 2>{scaled_jacobian(g.mesh, g.mesh.quads[f]), up};
          },
          [](int) {
            return Vec3{0, 0, 1};
          },
          std::move(smooth)};
}

// Folds: interior vertices pushed across their neighbours (20 seeds, 1–3 folds each, far from
// each other and from the border). Every fold is untangled, and vertices away from the folds
// and on the border stay where they were.
TEST(TangledRegions, UntanglesFoldsOfAFlatGrid) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Grid g = grid(24);
    std::mt19937 random(seed);
    std::vector<int> folded;
    for (int k = 0; k < 1 + int(seed % 3); ++k) {
      const int i = 4 + 8 * k, j = 4 + int(random() % 16);
      Vec3& p = g.mesh.vertices[g.id(i, j)];
      p[0] += 1.6, p[1] += 0.4 * (double(random() % 100) / 100 - 0.5);
      folded.push_back(g.id(i, j));
    }
    const QuadMesh start = g.mesh;
    ASSERT_GT(count_inverted(start), 0) << seed;
    std::vector<int> all(g.mesh.vertices.size());
    for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
    const TangledRegionReport report =
        reembed_tangled_regions(input_for(g, [](const std::vector<int>&) {}), all);
    EXPECT_EQ(report.inverted_before, count_inverted(start)) << seed;
    EXPECT_EQ(report.inverted_after, 0) << seed;
    EXPECT_EQ(count_inverted(g.mesh), 0) << seed;
    EXPECT_GE(report.kept, static_cast<int>(folded.size())) << seed;
    for (size_t v = 0; v < all.size(); ++v) {
      EXPECT_EQ(g.mesh.vertices[v][2], 0) << seed;
      int i = int(v) % 25, j = int(v) / 25, near = 99;
      for (int f : folded)
        near = std::min(near, std::max(std::abs(i - f % 25), std::abs(j - f / 25)));
      if (!g.inside(int(v)) || near > 6) {
        EXPECT_EQ(g.mesh.vertices[v], start.vertices[v]) << seed << " vertex " << v;
      }
    }
  }
}

// A fold between two curves: the vertices of columns 10 and 11 slide along the vertical lines
// x = 10 and x = 11 (as on feature curves), and one of them is pushed past its neighbour on
// its line, turning the quads at it over — every corner of those quads lies on a curve, so
// Tutte's embedding, which moves only free vertices, cannot help; the descent slides them
// back. Every vertex stays on its line, and the fold is undone.
TEST(TangledRegions, UntanglesAFoldAlongCurves) {
  Grid g = grid(20);
  const auto column = [&g](int v) { return v % (g.n + 1); };
  const auto on_curve = [&](int v) { return g.inside(v) && (column(v) == 10 || column(v) == 11); };
  Vec3& pushed = g.mesh.vertices[g.id(10, 9)];
  pushed[1] += 1.5;
  ASSERT_GT(count_inverted(g.mesh), 0);
  TangledRegionInput input = input_for(g, [](const std::vector<int>&) {});
  input.project = [&](int v, const Vec3& p) {
    return on_curve(v) ? Vec3{double(column(v)), p[1], 0} : Vec3{p[0], p[1], 0};
  };
  input.freedom = [&](int v) {
    if (!g.inside(v)) return TangledRegionInput::Freedom::kPinned;
    return on_curve(v) ? TangledRegionInput::Freedom::kOnCurve : TangledRegionInput::Freedom::kFree;
  };
  std::vector<int> all(g.mesh.vertices.size());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  const TangledRegionReport report = reembed_tangled_regions(input, all);
  EXPECT_EQ(report.inverted_after, 0);
  EXPECT_EQ(count_inverted(g.mesh), 0);
  for (size_t v = 0; v < all.size(); ++v)
    if (on_curve(int(v))) {
      EXPECT_EQ(g.mesh.vertices[v][0], double(column(int(v)))) << v;
    }
}

// The positions before smoothing, where given, are the last way out: here every vertex is on
// a curve that holds it where it is (its projection), so neither Tutte's embedding nor the
// descent moves anything, and smoothing is a no-op; but where the vertices were placed, no
// quad was folded.
TEST(TangledRegions, GoesBackToThePlacedPositions) {
  Grid g = grid(12);
  const std::vector<Vec3> placed = g.mesh.vertices;
  const int folded = g.id(6, 6);
  g.mesh.vertices[folded][0] += 1.6;
  const std::vector<Vec3> stuck = g.mesh.vertices;
  TangledRegionInput input = input_for(g, [](const std::vector<int>&) {});
  input.project = [&](int v, const Vec3&) { return stuck[v]; };
  input.freedom = [&](int v) {
    return g.inside(v) ? TangledRegionInput::Freedom::kOnCurve
                       : TangledRegionInput::Freedom::kPinned;
  };
  std::vector<int> all(g.mesh.vertices.size());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  const TangledRegionReport stays = reembed_tangled_regions(input, all);
  EXPECT_GT(stays.inverted_after, 0);
  EXPECT_EQ(g.mesh.vertices, stuck);

  input.placed = &placed;
  const TangledRegionReport back = reembed_tangled_regions(input, all);
  EXPECT_EQ(back.inverted_after, 0);
  EXPECT_EQ(g.mesh.vertices[folded], placed[folded]);
}

// Where the new positions are worse (here a smoothing that throws the region's vertices
// about), the old ones are restored exactly; vertices not given never move.
TEST(TangledRegions, KeepsTheOldPositionsWhereTheNewOnesAreWorse) {
  Grid g = grid(12);
  g.mesh.vertices[g.id(6, 6)][0] += 1.6;
  const QuadMesh start = g.mesh;
  std::mt19937 random(7);
  const auto scramble = [&](const std::vector<int>& vertices) {
    for (int v : vertices)
      for (int d = 0; d < 2; ++d) g.mesh.vertices[v][d] = double(random() % 1200) / 100;
  };
  std::vector<int> all(g.mesh.vertices.size());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  const TangledRegionReport worse = reembed_tangled_regions(input_for(g, scramble), all);
  EXPECT_GT(worse.regions, 0);
  EXPECT_EQ(worse.kept, 0);
  EXPECT_EQ(g.mesh.vertices, start.vertices);

  const TangledRegionReport none =
      reembed_tangled_regions(input_for(g, [](const std::vector<int>&) {}), {});
  EXPECT_EQ(none.regions, 0);
  EXPECT_EQ(g.mesh.vertices, start.vertices);
}

// A smoothing that squeezes every vertex it may move into one point rights every fold in the
// sense that no quad is inverted any more — they are all degenerate. Degenerate quads count
// as inverted, so that is no better, and the old positions stay.
TEST(TangledRegions, SqueezingAFoldIntoAPointIsNoUntangling) {
  Grid g = grid(12);
  g.mesh.vertices[g.id(6, 6)][0] += 1.6;
  const QuadMesh start = g.mesh;
  ASSERT_GT(count_inverted(start), 0);
  const auto squeeze = [&](const std::vector<int>& vertices) {
    for (int v : vertices) g.mesh.vertices[v] = {6, 6, 0};
  };
  std::vector<int> all(g.mesh.vertices.size());
  for (size_t v = 0; v < all.size(); ++v) all[v] = int(v);
  const TangledRegionReport squeezed = reembed_tangled_regions(input_for(g, squeeze), all);
  EXPECT_GT(squeezed.regions, 0);
  EXPECT_EQ(squeezed.kept, 0);
  EXPECT_EQ(g.mesh.vertices, start.vertices);
}

}  // namespace
}  // namespace bimdf::detail
