// Quality polishing, the last step of smoothing (src/mesh/quality_polish.hpp): it straightens
// corners — the mean and 5th-percentile scaled Jacobian rise — and keeps its guarantees: the
// minimum never falls, nothing is turned over, the Hausdorff distance to the input never grows,
// vertices stay on the surface, feature corners stay put and feature vertices on their curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "bimdf/metrics.hpp"
#include "bimdf/quant/quantize.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "mesh/closest_point.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/smoothing.hpp"
#include "tmesh_collapse_support.hpp"

namespace bimdf::quant {
namespace {

constexpr SmoothingOptions kPolishOnly{0, 0.5, 5};

// A flat n × n grid of unit quads on the plane z = 0, its interior vertices jittered by up to
// `jitter` of an edge in x and y; the layout is one chart of two triangles covering it.
struct JitteredGrid {
  Layout layout;
  Tessellation t;
};

JitteredGrid jittered_grid(int n, double jitter, unsigned seed) {
  JitteredGrid g;
  g.layout.mesh.vertices = {
      {0, 0, 0}, {double(n), 0, 0}, {double(n), double(n), 0}, {0, double(n), 0}};
  g.layout.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  g.layout.face_chart = {0, 0};
  g.layout.charts.resize(1);
  g.layout.charts[0].faces = {0, 1};
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inside = i > 0 && i < n && j > 0 && j < n;
      g.t.mesh.vertices.push_back(
          {i + (inside ? jitter * unit(random) : 0), j + (inside ? jitter * unit(random) : 0), 0});
      VertexOrigin origin;
      if (inside) origin.chart = 0;  // the border stays: no chart, no curve
      g.t.origin.push_back(origin);
    }
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      g.t.mesh.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      g.t.mesh.quad_patch.push_back(0);
    }
  return g;
}

// On a plane the optimum is the regular grid: from jittered grids (30 seeds) polishing alone
// must come close to it, never lower the worst quad, keep every vertex on the plane and the
// border where it was.
TEST(QualityPolish, StraightensJitteredGrids) {
  for (unsigned seed = 1; seed <= 30; ++seed) {
    JitteredGrid g = jittered_grid(8, 0.2, seed);
    const QuadMesh before = g.t.mesh;
    const QuadMeshMetrics start = measure_quad_mesh(before);
    ASSERT_EQ(start.inverted, 0) << seed;
    ASSERT_LT(start.scaled_jacobian_p5, 0.95) << seed;  // far from regular
    smooth_on_surface(g.layout, g.t, kPolishOnly);
    const QuadMeshMetrics end = measure_quad_mesh(g.t.mesh);
    EXPECT_GT(end.scaled_jacobian_mean, 0.995) << seed;
    EXPECT_GT(end.scaled_jacobian_p5, 0.99) << seed;
    EXPECT_GE(end.scaled_jacobian_min, start.scaled_jacobian_min) << seed;
    EXPECT_EQ(end.inverted, 0) << seed;
    for (int v = 0; v < before.num_vertices(); ++v) {
      EXPECT_EQ(g.t.mesh.vertices[v][2], 0) << seed << " vertex " << v;
      if (g.t.origin[v].chart < 0) {
        EXPECT_EQ(g.t.mesh.vertices[v], before.vertices[v]) << seed << " vertex " << v;
      }
    }
  }
}

// A regular grid is already optimal: nothing moves.
TEST(QualityPolish, LeavesARegularGridAlone) {
  JitteredGrid g = jittered_grid(6, 0, 1);
  const QuadMesh before = g.t.mesh;
  smooth_on_surface(g.layout, g.t, kPolishOnly);
  EXPECT_EQ(g.t.mesh.vertices, before.vertices);
}

// The distance from p to the polyline of layout vertices `chain`.
double distance_to_polyline(const Layout& layout, const std::vector<int>& chain,
                            const std::array<double, 3>& p) {
  double best = INFINITY;
  for (size_t i = 0; i + 1 < chain.size(); ++i)
    best =
        std::min(best, tmesh::testsupport::distance_to_segment(p, layout.mesh.vertices[chain[i]],
                                                               layout.mesh.vertices[chain[i + 1]]));
  return best;
}

// The layout's feature edges, each as (smaller, larger) vertex.
std::set<std::pair<int, int>> feature_edge_set(const Layout& layout) {
  std::set<std::pair<int, int>> feature;
  for (const auto& e : layout.feature_edges)
    feature.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  return feature;
}

// Whether subside `s` runs along `feature` edges all the way (a border subside does not count:
// the border is a curve of its own).
bool along_feature(const std::set<std::pair<int, int>>& feature, const Subside& s) {
  bool along = !s.on_border();
  for (size_t i = 0; i + 1 < s.vertices.size() && along; ++i)
    along = feature.count({std::min(s.vertices[i], s.vertices[i + 1]),
                           std::max(s.vertices[i], s.vertices[i + 1])}) > 0;
  return along;
}

// The bundled bunny (with feature curves and corners), remeshed with and without polishing:
// polishing raises the mean and 5th percentile, lowers neither the minimum nor raises the
// Hausdorff distance, adds no inverted or degenerate quad, and keeps feature corners in place
// and feature-curve vertices on their curves.
TEST(QualityPolish, RaisesTheBunnysQualityWithinItsGuarantees) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  ASSERT_FALSE(layout.feature_corners.empty());
  const std::vector<int64_t> lengths = quantize(layout, QuantizeOptions{}).lengths();
  SmoothingOptions without;
  without.quality_rounds = 0;
  const Tessellation plain = tessellate(layout, lengths, without);
  const Tessellation polished = tessellate(layout, lengths, SmoothingOptions{});
  const QuadMeshMetrics a = measure_quad_mesh(plain.mesh, &layout.mesh);
  const QuadMeshMetrics b = measure_quad_mesh(polished.mesh, &layout.mesh);
  EXPECT_GT(b.scaled_jacobian_mean, a.scaled_jacobian_mean + 0.005);
  // +0.0997 measured (0.7735 → 0.8732); without the rounds over the worst tenth, +0.0925.
  EXPECT_GT(b.scaled_jacobian_p5, a.scaled_jacobian_p5 + 0.095);
  EXPECT_GE(b.scaled_jacobian_min, a.scaled_jacobian_min);
  EXPECT_LE(b.hausdorff, a.hausdorff);
  EXPECT_LE(b.inverted, a.inverted);
  EXPECT_EQ(b.degenerate, 0);

  const std::set<std::pair<int, int>> feature = feature_edge_set(layout);
  const std::set<int> corners(layout.feature_corners.begin(), layout.feature_corners.end());
  const double scale = layout.average_edge_length;
  int on_curves = 0, at_corners = 0;
  for (int v = 0; v < polished.mesh.num_vertices(); ++v) {
    const VertexOrigin& o = polished.origin[v];
    if (o.mesh_vertex >= 0 && corners.count(o.mesh_vertex)) {
      EXPECT_EQ(polished.mesh.vertices[v], layout.mesh.vertices[o.mesh_vertex]) << v;
      ++at_corners;
    }
    if (o.subside < 0 || !along_feature(feature, layout.subsides[o.subside])) continue;
    EXPECT_LT(distance_to_polyline(layout, layout.subsides[o.subside].vertices,
                                   polished.mesh.vertices[v]),
              1e-9 * scale)
        << v;
    ++on_curves;
  }
  EXPECT_GT(at_corners, 10);
  EXPECT_GT(on_curves, 50);
}

// A feature-curve vertex pushed off its curve (towards the middle of one of its quads): a
// smoother that is given charts for it (as inverted-quad cleanup does for a vertex let off its
// curve) moves it on those charts and leaves it off the curve; an ordinary one puts it back on
// the curve.
TEST(QualityPolish, AVertexGivenChartsLeavesItsCurve) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  const std::vector<int64_t> lengths = quantize(layout, QuantizeOptions{}).lengths();
  const Tessellation start = tessellate(layout, lengths, SmoothingOptions{});
  const std::set<std::pair<int, int>> feature = feature_edge_set(layout);
  int v = -1;
  for (int u = 0; u < start.mesh.num_vertices() && v < 0; ++u)
    if (start.origin[u].subside >= 0 &&
        along_feature(feature, layout.subsides[start.origin[u].subside]))
      v = u;
  ASSERT_GE(v, 0);
  const std::vector<int>& chain = layout.subsides[start.origin[v].subside].vertices;
  const double scale = layout.average_edge_length;
  std::vector<std::vector<int>> charts(start.mesh.num_vertices());
  std::array<double, 3> pushed{0, 0, 0};
  for (int q = 0; q < start.mesh.num_quads(); ++q) {
    const auto& quad = start.mesh.quads[q];
    if (std::find(quad.begin(), quad.end(), v) == quad.end()) continue;
    charts[v].push_back(start.mesh.quad_patch[q]);
    if (charts[v].size() > 1) continue;
    for (int u : quad)
      for (int d = 0; d < 3; ++d) pushed[d] += start.mesh.vertices[u][d] / 4;
  }
  std::sort(charts[v].begin(), charts[v].end());
  charts[v].erase(std::unique(charts[v].begin(), charts[v].end()), charts[v].end());
  ASSERT_EQ(charts[v].size(), 2u);  // the curve runs between two charts
  for (const bool given : {true, false}) {
    Tessellation t = start;
    t.mesh.vertices[v] = pushed;
    ASSERT_GT(distance_to_polyline(layout, chain, t.mesh.vertices[v]), 1e-3 * scale);
    SurfaceSmoother smoother(layout, t, given ? &charts : nullptr);
    smoother.run(SmoothingOptions{}, {v});
    smoother.polish(SmoothingOptions{}, {v});
    const double off = distance_to_polyline(layout, chain, t.mesh.vertices[v]);
    if (given)
      EXPECT_GT(off, 1e-6 * scale);  // not snapped: on the curve it would be < 1e-9
    else
      EXPECT_LT(off, 1e-9 * scale);
  }
}

// The closest point of a segment: the foot of the perpendicular inside it, an end beyond it,
// the one point of a segment of length 0.
TEST(ClosestPoint, OnASegmentTheFootOrAnEnd) {
  using bimdf::detail::closest_point_on_segment;
  const bimdf::detail::Vec3 a{0, 0, 0}, b{2, 0, 0};
  EXPECT_EQ(closest_point_on_segment({0.5, 3, -1}, a, b), (bimdf::detail::Vec3{0.5, 0, 0}));
  EXPECT_EQ(closest_point_on_segment({-1, 1, 0}, a, b), a);
  EXPECT_EQ(closest_point_on_segment({5, 0, 2}, a, b), b);
  EXPECT_EQ(closest_point_on_segment({1, 1, 1}, b, b), b);
}

}  // namespace
}  // namespace bimdf::quant
