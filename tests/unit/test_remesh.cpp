// From layout to quad mesh (quant/tessellate.hpp) and its measurements (metrics.hpp): every
// shared layout becomes an all-quad, manifold, conforming mesh with the input's Euler
// characteristic, close to the input surface, with about the reference quantizer's quad count;
// smoothing never makes the worst quad worse; metrics and pictures on hand-checkable meshes;
// the CLI's errors.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "bimdf/metrics.hpp"
#include "bimdf/quant/quantize.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/render.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "cli_fixture.hpp"
#include "mesh/quad_quality.hpp"
#include "quadwild_quality.hpp"
#include "shared_layouts.hpp"
#include "test_helpers.hpp"
#include "tmesh_collapse_support.hpp"

namespace bimdf::quant {
namespace {

// Independent topology check: "" or what is wrong. `boundary_edges` and `euler` are set.
std::string check_topology(const QuadMesh& m, int& boundary_edges, int& euler) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& q : m.quads) {
    if (std::set<int>(q.begin(), q.end()).size() != 4) return "a quad repeats a vertex";
    for (int a = 0; a < 4; ++a)
      if (++directed[{q[a], q[(a + 1) % 4]}] > 1) return "an edge is used twice in one direction";
  }
  std::set<std::pair<int, int>> undirected;
  boundary_edges = 0;
  std::map<int, int> boundary_out, boundary_in;
  for (const auto& [e, n] : directed) {
    undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
    if (!directed.count({e.second, e.first})) {
      ++boundary_edges;
      if (++boundary_out[e.first] > 1 || ++boundary_in[e.second] > 1)
        return "a vertex is on two boundary loops (pinched)";
    }
  }
  std::set<int> used;
  for (const auto& q : m.quads) used.insert(q.begin(), q.end());
  euler = static_cast<int>(used.size()) - static_cast<int>(undirected.size()) + m.num_quads();
  // Every vertex has a single fan: walk around it through shared edges.
  std::map<int, std::vector<int>> at;
  for (int f = 0; f < m.num_quads(); ++f)
    for (int v : m.quads[f]) at[v].push_back(f);
  std::map<std::pair<int, int>, std::vector<int>> edge_quads;
  for (int f = 0; f < m.num_quads(); ++f)
    for (int a = 0; a < 4; ++a) {
      const int u = m.quads[f][a], w = m.quads[f][(a + 1) % 4];
      edge_quads[{std::min(u, w), std::max(u, w)}].push_back(f);
    }
  for (const auto& [v, quads] : at) {
    std::set<int> seen{quads[0]};
    std::vector<int> todo{quads[0]};
    while (!todo.empty()) {
      const int f = todo.back();
      todo.pop_back();
      for (int a = 0; a < 4; ++a)
        if (m.quads[f][a] == v)
          for (int w : {m.quads[f][(a + 1) % 4], m.quads[f][(a + 3) % 4]})
            for (int g : edge_quads[{std::min(v, w), std::max(v, w)}])
              if (seen.insert(g).second) todo.push_back(g);
    }
    if (seen.size() != quads.size()) return "vertex " + std::to_string(v) + " has two fans";
  }
  return "";
}

int euler_characteristic(const TriangleMesh& t) {
  std::set<std::pair<int, int>> edges;
  for (const auto& f : t.faces)
    for (int a = 0; a < 3; ++a)
      edges.insert({std::min(f[a], f[(a + 1) % 3]), std::max(f[a], f[(a + 1) % 3])});
  return t.num_vertices() - static_cast<int>(edges.size()) + t.num_faces();
}

struct Remeshed {
  Tessellation raw, smoothed;
  Quantization quantization;
};

Remeshed remesh(const Layout& layout) {
  Remeshed r;
  r.quantization = quantize(layout, QuantizeOptions{});
  r.raw = tessellate(layout, r.quantization.lengths(), SmoothingOptions{0, 0.5, 0});
  r.smoothed = tessellate(layout, r.quantization.lengths());
  return r;
}

// The conformity, topology and fidelity checks of issue 7 on one layout.
void expect_good_remesh(const Layout& layout, const Remeshed& r, const std::string& name) {
  const QuadMesh& m = r.smoothed.mesh;
  int boundary = -1, euler = 0;
  ASSERT_EQ(check_topology(m, boundary, euler), "") << name;
  EXPECT_EQ(euler, euler_characteristic(layout.mesh)) << name;
  // Watertight where the input was: the boundary is exactly the border subsides' quad edges.
  int64_t border = 0;
  for (size_t s = 0; s < layout.subsides.size(); ++s)
    if (layout.subsides[s].on_border()) border += r.quantization.lengths()[s];
  EXPECT_EQ(boundary, border) << name;
  // Every chart tiled, with the pattern's quads.
  int64_t quads = 0;
  for (size_t c = 0; c < layout.charts.size(); ++c) {
    EXPECT_EQ(r.smoothed.charts[c].quads > 0, !layout.charts[c].empty()) << name << " " << c;
    quads += r.smoothed.charts[c].quads;
  }
  EXPECT_EQ(quads, m.num_quads());
  // On the surface; smoothing moves vertices but never adds inverted quads, and lowers no
  // quad's scaled Jacobian below min(its worst before, 0.5).
  const QuadMeshMetrics raw = measure_quad_mesh(r.raw.mesh);
  const QuadMeshMetrics smooth = measure_quad_mesh(m, &layout.mesh);
  EXPECT_LT(smooth.hausdorff_relative, 0.02) << name;
  EXPECT_GE(smooth.scaled_jacobian_min, std::min(raw.scaled_jacobian_min, 0.5)) << name;
  EXPECT_LE(smooth.inverted, raw.inverted) << name;
  EXPECT_EQ(smooth.degenerate, 0) << name;
  EXPECT_GT(smooth.scaled_jacobian_mean, raw.scaled_jacobian_mean) << name;
}

TEST(Remesh, BundledLayoutBecomesAClosedConformingQuadMesh) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  const Remeshed r = remesh(layout);
  expect_good_remesh(layout, r, "npm_bunny");
  // Regular charts: the tessellation has exactly the quad count the flow's strips predict.
  EXPECT_EQ(r.smoothed.mesh.num_quads(),
            std::llround(r.quantization.final_round().estimated_quads));
  for (const ChartTiling& c : r.smoothed.charts) EXPECT_EQ(c.kind, PatternKind::Regular);
}

// Every inverted quad left must be forced by the layout: its layout mesh vertices are feature
// corners (fixed), and no placement of its other vertices — those on subsides anywhere along
// their subside (in any order), those inside anywhere on their chart's triangles — gives the
// quad alone a scaled Jacobian of kFixable. Ignoring the neighbours and the order makes this
// a necessary condition for any tessellation with these patterns to do better.
void expect_inverted_quads_forced(const Layout& layout, const Tessellation& t,
                                  const std::string& name) {
  constexpr double kFixable = 0.05;
  const std::set<int> feature_corner(layout.feature_corners.begin(), layout.feature_corners.end());
  for (int f = 0; f < t.mesh.num_quads(); ++f) {
    const auto& q = t.mesh.quads[f];
    QuadMesh one;
    for (int v : q) one.vertices.push_back(t.mesh.vertices[v]);
    one.quads = {{0, 1, 2, 3}};
    if (bimdf::detail::degenerate(one, one.quads[0]) ||
        bimdf::detail::scaled_jacobian(one, one.quads[0]) >= 0)
      continue;
    std::vector<std::vector<std::array<double, 3>>> candidates(4);
    int inside = 0;
    for (int a = 0; a < 4; ++a) inside += t.origin[q[a]].chart >= 0;
    const int c = t.mesh.quad_patch[f];
    const double triangles = static_cast<double>(layout.charts[c].faces.size());
    int g = 24;  // triangle grid resolution: at most ~4·10⁶ placements in all
    while (g > 2 &&
           std::pow(41.0, 4 - inside) * std::pow(triangles * (g + 1) * (g + 2) / 2, inside) > 4e6)
      --g;
    for (int a = 0; a < 4; ++a) {
      const VertexOrigin& o = t.origin[q[a]];
      if (o.mesh_vertex >= 0) {
        EXPECT_TRUE(feature_corner.count(o.mesh_vertex))
            << name << ": inverted quad " << f << " has a layout vertex that could move";
        candidates[a] = {t.mesh.vertices[q[a]]};
      } else if (o.subside >= 0) {
        const std::vector<int>& chain = layout.subsides[o.subside].vertices;
        for (int k = 0; k <= 40; ++k) {
          const double s = (chain.size() - 1) * k / 40.0;
          const size_t i = std::min(static_cast<size_t>(s), chain.size() - 2);
          const auto& x = layout.mesh.vertices[chain[i]];
          const auto& y = layout.mesh.vertices[chain[i + 1]];
          candidates[a].push_back({x[0] + (s - i) * (y[0] - x[0]), x[1] + (s - i) * (y[1] - x[1]),
                                   x[2] + (s - i) * (y[2] - x[2])});
        }
      } else {
        for (int tf : layout.charts[o.chart].faces) {
          const auto& tri = layout.mesh.faces[tf];
          for (int i = 0; i <= g; ++i)
            for (int j = 0; i + j <= g; ++j) {
              std::array<double, 3> p;
              for (int d = 0; d < 3; ++d)
                p[d] = (1 - double(i + j) / g) * layout.mesh.vertices[tri[0]][d] +
                       double(i) / g * layout.mesh.vertices[tri[1]][d] +
                       double(j) / g * layout.mesh.vertices[tri[2]][d];
              candidates[a].push_back(p);
            }
        }
      }
    }
    double best = -1;
    for (const auto& p0 : candidates[0])
      for (const auto& p1 : candidates[1])
        for (const auto& p2 : candidates[2])
          for (const auto& p3 : candidates[3]) {
            one.vertices = {p0, p1, p2, p3};
            best = std::max(best, bimdf::detail::scaled_jacobian(one, one.quads[0]));
          }
    EXPECT_LT(best, kFixable) << name << ": inverted quad " << f << " (chart " << c
                              << ") could have a scaled Jacobian of " << best;
  }
}

// ... and as good as QuadWild's final meshes by the scaled Jacobian (quadwild_quality.tsv:
// mean and p5 at least its 4-digit figures, minimum too or above 0.2; issue 24).
TEST(RemeshShared, EveryLayoutBecomesAConformingQuadMeshOfTheReferenceSize) {
  REQUIRE_SHARED_LAYOUTS();
  const std::vector<testing::Reference> refs = testing::references();
  ASSERT_EQ(refs.size(), 23u);
  const std::map<std::string, bench::QuadWildQuality> quadwild =
      bench::read_quadwild_quality(testing::kLayouts);
  ASSERT_EQ(quadwild.size(), 23u);
  // Every layout in the plain run; an evenly spread subset in the (slow) sanitizer run.
  const size_t stride = refs.size() / std::max<size_t>(1, testing::scaled(23));
  for (size_t i = 0; i < refs.size(); i += std::max<size_t>(1, stride)) {
    const testing::Reference& ref = refs[i];
    const Layout layout = read_quadwild_layout(testing::layout_path(ref.mesh));
    const Remeshed r = remesh(layout);
    expect_good_remesh(layout, r, ref.mesh);
    expect_inverted_quads_forced(layout, r.smoothed, ref.mesh);
    EXPECT_NEAR(r.smoothed.mesh.num_quads(), ref.align_quads, 0.1 * ref.align_quads) << ref.mesh;
    for (const ChartTiling& c : r.smoothed.charts) EXPECT_NE(c.kind, PatternKind::Fan) << ref.mesh;
    const QuadMeshMetrics m = measure_quad_mesh(r.smoothed.mesh);
    // None left: bull's last one (forced while feature corners stayed put) goes once the
    // feature vertices at it may leave the features (inverted_cleanup.hpp).
    EXPECT_EQ(m.inverted, 0) << ref.mesh;
    if (ref.mesh == "bull") {
      EXPECT_GT(r.smoothed.released_from_features, 0);
      EXPECT_LT(r.smoothed.released_max_offset, 0.5);  // 0.18 edge lengths measured
    }
    const bench::QuadWildQuality& qw = quadwild.at(ref.mesh);
    EXPECT_TRUE(bench::at_least_quadwild(m.scaled_jacobian_min, m.scaled_jacobian_mean,
                                         m.scaled_jacobian_p5, qw))
        << ref.mesh << ": ours " << m.scaled_jacobian_min << " / " << m.scaled_jacobian_mean
        << " / " << m.scaled_jacobian_p5 << ", QuadWild " << qw.min << " / " << qw.mean << " / "
        << qw.p5;
  }
}

// Smoothing's untangling, without ../shared: every interior vertex of the bunny's largest
// chart is pushed 90% of the way to a random neighbour, which folds many of its quads (local
// tangles, as a distorting flattening makes), and smoothing must leave no inverted or
// degenerate quad anywhere.
// feature_edges_of: on the bundled bunny (feature curves, no border), exactly the quad edges
// the feature subsides were tessellated into — as many as their lengths add up to — each with
// both ends on the layout's feature polylines; and the file written for them reads back as the
// same edges (what `remesh --feature-out` hands to `requantize --feature`).
TEST(Remesh, FeatureEdgesOfTheBunnyAreItsFeatureSubsidesTessellated) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  const Remeshed r = remesh(layout);
  const std::vector<std::array<int, 2>> edges = feature_edges_of(layout, r.smoothed);
  std::set<std::pair<int, int>> feature;
  for (const auto& e : layout.feature_edges)
    feature.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  int64_t expected = 0;
  for (size_t s = 0; s < layout.subsides.size(); ++s) {
    const Subside& sub = layout.subsides[s];
    bool along = !sub.on_border();
    for (size_t i = 0; along && i + 1 < sub.vertices.size(); ++i)
      along = feature.count({std::min(sub.vertices[i], sub.vertices[i + 1]),
                             std::max(sub.vertices[i], sub.vertices[i + 1])}) > 0;
    if (along) expected += r.quantization.lengths()[s];
  }
  ASSERT_GT(expected, 100);
  EXPECT_EQ(static_cast<int64_t>(edges.size()), expected);
  EXPECT_EQ(r.smoothed.released_from_features, 0);
  const auto distance_to_features = [&](const std::array<double, 3>& p) {
    double best = INFINITY;
    for (const auto& [a, b] : feature)
      best = std::min(best, tmesh::testsupport::distance_to_segment(p, layout.mesh.vertices[a],
                                                                    layout.mesh.vertices[b]));
    return best;
  };
  for (const auto& [a, b] : edges) {
    EXPECT_LT(distance_to_features(r.smoothed.mesh.vertices[a]), 1e-9) << a;
    EXPECT_LT(distance_to_features(r.smoothed.mesh.vertices[b]), 1e-9) << b;
  }
  std::ostringstream file;
  tmesh::write_quad_feature_file(file, r.smoothed.mesh, edges);
  const std::string path =
      (std::filesystem::temp_directory_path() / "bimdf_remesh_bunny_quads.feature").string();
  std::ofstream(path) << file.str();
  std::vector<std::array<int, 2>> back = tmesh::read_quad_feature_file(path, r.smoothed.mesh);
  for (auto& e : back) e = {std::min(e[0], e[1]), std::max(e[0], e[1])};
  std::sort(back.begin(), back.end());
  EXPECT_EQ(back, edges);
}

TEST(Remesh, SmoothingUntanglesAFoldedChart) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  const std::vector<int64_t> lengths = quantize(layout, QuantizeOptions{}).lengths();
  Tessellation t = tessellate(layout, lengths, SmoothingOptions{0, 0.5, 0});
  std::vector<std::vector<int>> interior(layout.charts.size());
  for (int v = 0; v < t.mesh.num_vertices(); ++v)
    if (t.origin[v].chart >= 0) interior[t.origin[v].chart].push_back(v);
  const std::vector<int>& chart =
      *std::max_element(interior.begin(), interior.end(),
                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  ASSERT_GT(chart.size(), 50u);
  std::vector<std::vector<int>> neighbours(t.mesh.num_vertices());
  for (const auto& q : t.mesh.quads)
    for (int a = 0; a < 4; ++a) neighbours[q[a]].push_back(q[(a + 1) % 4]);
  std::mt19937 random(7);
  for (int v : chart) {
    const int w = neighbours[v][random() % neighbours[v].size()];
    for (int d = 0; d < 3; ++d)
      t.mesh.vertices[v][d] += 0.9 * (t.mesh.vertices[w][d] - t.mesh.vertices[v][d]);
  }
  const QuadMeshMetrics folded = measure_quad_mesh(t.mesh);
  EXPECT_GT(folded.inverted + folded.degenerate, 20);
  smooth_on_surface(layout, t, SmoothingOptions{});
  const QuadMeshMetrics m = measure_quad_mesh(t.mesh, &layout.mesh);
  EXPECT_EQ(m.inverted, 0);
  EXPECT_EQ(m.degenerate, 0);
  EXPECT_LT(m.hausdorff_relative, 0.02);
}

// Smoothing never turns a quad over, even beside slivers: a flat grid of quads 250 times as
// long as wide (corners closer than 1% of the longest edge, which the smoother rates below an
// inverted quad) with its interior vertices jittered. A move that widened the slivers by
// turning a neighbour over would raise that rating; it must still be refused (coarse
// requantizations on long thin parts made hundreds of such quads before it was).
TEST(Remesh, SmoothingNeverTurnsOverAQuadBesideASliver) {
  constexpr int kColumns = 4, kRows = 40;
  constexpr double kHeight = 0.004;  // of a row; columns are 1 wide
  Layout layout;
  layout.mesh.vertices = {
      {0, 0, 0}, {kColumns, 0, 0}, {kColumns, kRows * kHeight, 0}, {0, kRows * kHeight, 0}};
  layout.mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  layout.face_chart = {0, 0};
  layout.charts.resize(1);
  layout.charts[0].faces = {0, 1};
  Tessellation t;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto id = [](int i, int j) { return j * (kColumns + 1) + i; };
  for (int j = 0; j <= kRows; ++j)
    for (int i = 0; i <= kColumns; ++i) {
      const bool inside = i > 0 && i < kColumns && j > 0 && j < kRows;
      t.mesh.vertices.push_back({i + (inside ? 0.3 * unit(random) : 0),
                                 j * kHeight + (inside ? 0.35 * kHeight * unit(random) : 0), 0});
      VertexOrigin origin;
      if (inside) origin.chart = 0;  // the border stays: no chart, no curve
      t.origin.push_back(origin);
    }
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      t.mesh.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      t.mesh.quad_patch.push_back(0);
    }
  ASSERT_EQ(measure_quad_mesh(t.mesh).inverted, 0);
  smooth_on_surface(layout, t, SmoothingOptions{});
  const QuadMeshMetrics m = measure_quad_mesh(t.mesh);
  EXPECT_EQ(m.inverted, 0);
  EXPECT_EQ(m.degenerate, 0);
}

TEST(Remesh, LengthsThatAdmitNoPatternAreRejected) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  std::vector<int64_t> lengths(layout.subsides.size(), 2);
  const auto message = [&](const std::vector<int64_t>& l) -> std::string {
    try {
      tessellate(layout, l);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message(std::vector<int64_t>(3, 2)), "3 subside lengths for 275 subsides");
  lengths[7] = 0;
  EXPECT_EQ(message(lengths), "subside 7: length 0, expected 1 to 2^24");
  lengths[7] = 3;
  const int c = layout.subsides[7].charts[0];
  EXPECT_EQ(message(lengths), "chart " + std::to_string(c) + ": perimeter " +
                                  std::to_string(2 * layout.charts[c].subsides.size() + 1) +
                                  ", expected an even number of at least 4");
}

QuadMesh grid() { return testing::quad_grid_2x2(); }

TEST(QuadObj, WriteThenParseGivesTheSameMeshBitForBit) {
  QuadMesh m = grid();
  m.vertices[4] = {1.0 / 3, std::nextafter(1.0, 2.0), -1e-300};  // needs all 17 digits
  m.vertices[0] = {1e-9, 123456.789012345678, 0.1};
  std::ostringstream out;
  write_obj(out, m, "round trip");
  const QuadMesh back = parse_obj_quads(out.str(), "written.obj");
  EXPECT_EQ(back.vertices, m.vertices);
  EXPECT_EQ(back.quads, m.quads);
  EXPECT_EQ(back.quad_patch, m.quad_patch);
}

TEST(Metrics, GridAndCubeHaveTheirKnownNumbers) {
  TriangleMesh square{{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  QuadMesh g = grid();
  g.vertices[4][2] = 0.5;  // lift the centre: Hausdorff 0.5 to the square, diagonal √8
  const QuadMeshMetrics m = measure_quad_mesh(g, &square);
  EXPECT_EQ(m.faces, 4);
  EXPECT_EQ(m.vertices, 9);
  EXPECT_EQ(m.edges, 12);
  EXPECT_EQ(m.euler_characteristic, 1);
  EXPECT_EQ(m.boundary_edges, 8);
  EXPECT_TRUE(m.manifold());
  EXPECT_EQ(m.interior_singularities, (std::map<int, int>{}));
  EXPECT_EQ(m.boundary_singularities, (std::map<int, int>{{2, 4}}));  // the corners
  EXPECT_EQ(m.base_complex_faces, 1);
  EXPECT_DOUBLE_EQ(m.hausdorff, 0.5);
  EXPECT_NEAR(m.hausdorff_relative, 0.5 / std::sqrt(8.0), 1e-15);
  EXPECT_EQ(m.flipped, 0);
  EXPECT_EQ(m.inverted, 0);
  EXPECT_EQ(m.degenerate, 0);
  EXPECT_LT(m.scaled_jacobian_min, 1);

  QuadMesh turned = grid();
  std::reverse(turned.quads[0].begin(), turned.quads[0].end());
  EXPECT_EQ(measure_quad_mesh(turned, &square).flipped, 1);

  // A cube: eight valence-3 vertices, every edge a separatrix, six base-complex patches.
  QuadMesh cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  cube.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const QuadMeshMetrics c = measure_quad_mesh(cube);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_EQ(c.boundary_edges, 0);
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.interior_singularities, (std::map<int, int>{{3, 8}}));
  EXPECT_EQ(c.base_complex_faces, 6);
  EXPECT_EQ(base_complex_patches(cube), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(base_complex_patches(grid()), (std::vector<int>{0, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(c.scaled_jacobian_min, 1);
  EXPECT_DOUBLE_EQ(c.scaled_jacobian_p5, 1);
  EXPECT_EQ(c.hausdorff, -1);

  // Folding one quad over: inverted; two quads on one edge in the same direction: not manifold.
  QuadMesh folded = grid();
  folded.vertices[0] = {1.5, 1.5, 0};
  EXPECT_EQ(measure_quad_mesh(folded).inverted, 1);
  EXPECT_EQ(measure_quad_mesh(folded).degenerate, 0);
  // Moving a corner onto its neighbour: degenerate, not inverted.
  QuadMesh collapsed = grid();
  collapsed.vertices[0] = collapsed.vertices[1];
  EXPECT_EQ(measure_quad_mesh(collapsed).degenerate, 1);
  EXPECT_EQ(measure_quad_mesh(collapsed).inverted, 0);
  // Almost onto it (10⁻⁹ of the edge, beyond the corner so that the angle is "inverted"): its
  // angles are noise, so degenerate too; 10⁻⁴ away it is a real, inverted quad.
  collapsed.vertices[0] = {1 + 1e-9, 1e-9, 0};
  EXPECT_EQ(measure_quad_mesh(collapsed).degenerate, 1);
  EXPECT_EQ(measure_quad_mesh(collapsed).inverted, 0);
  collapsed.vertices[0] = {1 + 1e-4, 1e-4, 0};
  EXPECT_EQ(measure_quad_mesh(collapsed).degenerate, 0);
  EXPECT_EQ(measure_quad_mesh(collapsed).inverted, 1);
  // Four corners apart but on one line, up to 10⁻¹³ (a quad squeezed along a feature curve):
  // its scaled Jacobian is ±rounding noise, yet it has no area — degenerate.
  QuadMesh line;
  line.vertices = {{0, 0, 0}, {1, 0, 0}, {1.4, 1e-13, 0}, {0.2, -1e-13, 0}};
  line.quads = {{0, 1, 2, 3}};
  line.quad_patch = {0};
  EXPECT_EQ(measure_quad_mesh(line).degenerate, 1);
  EXPECT_EQ(measure_quad_mesh(line).inverted, 0);
  QuadMesh bad = grid();
  bad.quads.push_back({0, 1, 4, 3});
  EXPECT_EQ(measure_quad_mesh(bad).non_manifold_edges, 4);
}

// A remesh's output is checked against its input surface before it is written: the grid over
// the square, the cube's six quads over a triangulated cube; what differs is named.
TEST(Metrics, TopologyDifferenceNamesWhatTheQuadMeshDoesNotKeep) {
  const TriangleMesh square{{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2}, {0, 2, 3}}};
  EXPECT_EQ(measure_quad_mesh(grid()).border_loops, 1);
  EXPECT_EQ(topology_difference(measure_quad_mesh(grid()), square), "");

  QuadMesh cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  cube.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  TriangleMesh surface{cube.vertices, {}};
  for (const auto& q : cube.quads) {
    surface.faces.push_back({q[0], q[1], q[2]});
    surface.faces.push_back({q[0], q[2], q[3]});
  }
  EXPECT_EQ(measure_quad_mesh(cube).border_loops, 0);
  EXPECT_EQ(topology_difference(measure_quad_mesh(cube), surface), "");

  QuadMesh open = cube;
  open.quads.pop_back();
  EXPECT_EQ(topology_difference(measure_quad_mesh(open), surface),
            "Euler characteristic 1, the surface's 2; 1 border loops, the surface has 0");
  EXPECT_EQ(topology_difference(measure_quad_mesh(cube), square),
            "Euler characteristic 2, the surface's 1; 0 border loops, the surface has 1");

  // A pillow: a second quad on the four vertices of a face, the other way round, hangs off
  // the surface (its edges have three quads each).
  QuadMesh pillow = cube;
  pillow.quads.push_back({1, 3, 2, 0});
  EXPECT_EQ(topology_difference(measure_quad_mesh(pillow), surface),
            "not manifold (4 edges, 0 vertices); Euler characteristic 3, the surface's 2");
}

TEST(Render, DrawsTheMeshIntoAValidPng) {
  RenderOptions o;
  o.width = 64, o.height = 48, o.view = {0, 0, -1};
  const Image image = render_quad_mesh(grid(), o);
  ASSERT_EQ(image.rgb.size(), 64u * 48 * 3);
  // The grid fills the middle (patch colours, shaded); the corner is background.
  const auto pixel = [&](int x, int y) {
    const size_t i = (static_cast<size_t>(y) * 64 + x) * 3;
    return std::array<int, 3>{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
  };
  EXPECT_NE(pixel(16, 30), pixel(0, 0));
  EXPECT_NE(pixel(16, 30), pixel(48, 18));  // patches 0 and 1 differ in colour
  const std::string png = encode_png(image);
  ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(static_cast<unsigned char>(png[19]), 64);  // width, big-endian
  EXPECT_EQ(static_cast<unsigned char>(png[23]), 48);
  // The IDAT chunk inflates to one filter byte plus 64 RGB pixels per row.
  const size_t idat = png.find("IDAT");
  const uint32_t length = (uint8_t(png[idat - 4]) << 24) | (uint8_t(png[idat - 3]) << 16) |
                          (uint8_t(png[idat - 2]) << 8) | uint8_t(png[idat - 1]);
  std::vector<unsigned char> raw(48 * (64 * 3 + 1) + 16);
  uLongf raw_size = raw.size();
  ASSERT_EQ(uncompress(raw.data(), &raw_size, reinterpret_cast<const Bytef*>(png.data() + idat + 4),
                       length),
            Z_OK);
  EXPECT_EQ(raw_size, 48u * (64 * 3 + 1));
  EXPECT_EQ(raw[0], 0);
  EXPECT_EQ(raw[1 + (30 * (64 * 3 + 1)) + 16 * 3], pixel(16, 30)[0]);
}

class RemeshCli : public testing::CliFixture {};

// --hold-angle-bound: bear remeshed, coarse at 10° with bounded half-arc drift has a
// separatrix at 10.3° between singular vertices (random meshes never drift that far: 300 seeds
// at 10°, 20°, 35°); held, every one keeps the bound, at some patches' cost.
TEST_F(RemeshCli, HoldAngleBoundKeepsEverySeparatrixWithinTheBound) {
  REQUIRE_SHARED_LAYOUTS();
  ASSERT_EQ(run("remesh " + testing::layout_path("bear") + " -o " + path("bear.obj") +
                " --feature-out " + path("bear.feature"))
                .exit_code,
            0);
  const std::string requantize = "requantize " + path("bear.obj") + " --coarse --max-angle 10 " +
                                 "--feature " + path("bear.feature") + " --sharp-angle 180 --json";
  testing::CliRun r = run(requantize + " -o " + path("free.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json free = nlohmann::json::parse(r.out);
  r = run(requantize + " -o " + path("held.obj") + " --hold-angle-bound");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json held = nlohmann::json::parse(r.out);
  EXPECT_GE(free["separatrix_deviation"]["over_bound"].get<int>(), 1);
  EXPECT_GT(free["separatrix_deviation"]["max_deg"].get<double>(), 10);
  EXPECT_EQ(held["separatrix_deviation"]["over_bound"], 0);
  EXPECT_LE(held["separatrix_deviation"]["max_deg"].get<double>(), 10 + 1e-9);
  EXPECT_GT(held["aligned_two_gons"].get<int>(), free["aligned_two_gons"].get<int>());
  EXPECT_GE(held["base_complex_out"].get<int>(), free["base_complex_out"].get<int>());
  EXPECT_EQ(held["metrics"]["inverted"], 0);
}

// --compare: another mesh's metrics beside the output's, as `bimdf metrics` measures it alone
// against the same reference; here the bunny remeshed without polishing beside the default.
TEST_F(RemeshCli, CompareReportsTheOtherMeshAsMetricsDoes) {
  const std::string layout = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj";
  ASSERT_EQ(run("remesh " + layout + " -o " + path("plain.obj") + " --quality-rounds 0").exit_code,
            0);
  testing::CliRun r = run("remesh " + layout + " -o " + path("polished.obj") +
                          " --json --compare " + path("plain.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  ASSERT_TRUE(report.contains("compare"));
  EXPECT_EQ(report["compare"]["mesh"], path("plain.obj"));
  const nlohmann::json other = report["compare"]["metrics"];

  r = run("metrics " + path("plain.obj") + " --reference " + layout + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json alone = nlohmann::json::parse(r.out);
  alone.erase("mesh");
  alone.erase("reference");
  EXPECT_EQ(other, alone);
  // Polishing is what differs: a better mean and 5th percentile, the same quads.
  EXPECT_EQ(report["metrics"]["faces"], other["faces"]);
  EXPECT_GT(report["metrics"]["scaled_jacobian"]["p5"].get<double>(),
            other["scaled_jacobian"]["p5"].get<double>());

  r = run("metrics " + path("polished.obj") + " --compare " + path("plain.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("compared      this mesh       " + path("plain.obj") + "\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\nquads         5996            5996\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("Hausdorff %"), std::string::npos) << "no reference, no distance";

  r = run("metrics " + path("polished.obj") + " --compare " + path("missing.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "error: " + path("missing.obj") + ": cannot open file: No such file or directory\n");
}

// --feature-out: the remeshed bunny's feature edges, as requantize --feature reads them; with
// the file (and no dihedral test) requantize traces from other seeds than with the curves it
// finds at 35° on the quads itself. Never over an input, never the mesh's own path.
TEST_F(RemeshCli, FeatureOutIsWhatRequantizeReads) {
  const std::string layout = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj";
  testing::CliRun r =
      run("remesh " + layout + " -o " + path("m.obj") + " --feature-out " + path("m.feature"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const QuadMesh m = read_obj_quads(path("m.obj"));
  const auto edges = tmesh::read_quad_feature_file(path("m.feature"), m);
  EXPECT_GT(edges.size(), 100u);
  r = run("requantize " + path("m.obj") + " --feature " + path("m.feature") +
          " --sharp-angle 180 --coarse --max-angle 45 -o " + path("c.obj") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["singularities_in"], j["singularities_out"]);
  r = run("requantize " + path("m.obj") + " --coarse --max-angle 45 -o " + path("c2.obj") +
          " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(nlohmann::json::parse(r.out)["seeds"], j["seeds"]);

  // --feature-traces: auto keeps the run with traces ending at the curves exactly when its base
  // complex is smaller, it has no more inverted or degenerate quads, a mean scaled Jacobian at
  // most 0.05 lower (prefer_coarser_layout) and no more separatrices above the angle bound, and
  // reports the other run.
  std::map<std::string, nlohmann::json> run_with;
  for (const std::string mode : {"cross", "stop", "auto"}) {
    r = run("requantize " + path("m.obj") + " --feature " + path("m.feature") +
            " --sharp-angle 180 --coarse --max-angle 45 --json -o " + path(mode + ".obj") +
            " --feature-traces " + mode);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    run_with[mode] = nlohmann::json::parse(r.out);
  }
  const auto& cross = run_with["cross"];
  const auto& stop = run_with["stop"];
  const auto& chosen = run_with["auto"];
  EXPECT_EQ(cross["feature_traces"], "cross");
  EXPECT_EQ(stop["feature_traces"], "stop");
  const auto bad = [](const nlohmann::json& x) {
    return x["metrics"]["inverted"].get<int>() + x["metrics"]["degenerate"].get<int>();
  };
  const auto mean = [](const nlohmann::json& x) {
    return x["metrics"]["scaled_jacobian"]["mean"].get<double>();
  };
  const auto over = [](const nlohmann::json& x) {
    return x["separatrix_deviation"]["over_bound"].get<int>();
  };
  const bool stop_wins = stop["base_complex_out"] < cross["base_complex_out"] &&
                         bad(stop) <= bad(cross) && mean(stop) >= mean(cross) - 0.05 &&
                         over(stop) <= over(cross);
  const auto& winner = stop_wins ? stop : cross;
  const auto& loser = stop_wins ? cross : stop;
  EXPECT_EQ(chosen["feature_traces"], winner["feature_traces"]);
  EXPECT_EQ(chosen["base_complex_out"], winner["base_complex_out"]);
  EXPECT_EQ(chosen["feature_traces_other"]["base_complex"], loser["base_complex_out"]);
  EXPECT_EQ(chosen["feature_traces_other"]["over_bound"], over(loser));
  // auto is the default with --coarse: the first run above, without the option, is this one.
  EXPECT_EQ(j["feature_traces"], chosen["feature_traces"]);
  EXPECT_EQ(j["base_complex_out"], chosen["base_complex_out"]);
  EXPECT_EQ(slurp(path("auto.obj")),
            slurp(path((stop_wins ? "stop" : "cross") + std::string(".obj"))));

  const std::string before = slurp(layout);
  r = run("remesh " + layout + " -o " + path("m2.obj") + " --feature-out " + layout);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: output file " + layout + " is the input file " + layout +
                       "; refusing to overwrite an input\n");
  EXPECT_FALSE(std::filesystem::exists(path("m2.obj")));
  EXPECT_EQ(slurp(layout), before);
  r = run("remesh " + layout + " -o " + path("m3.obj") + " --feature-out " + path("m3.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: --feature-out and --output name the same file " + path("m3.obj") + "\n");
  EXPECT_FALSE(std::filesystem::exists(path("m3.obj")));
}

TEST_F(RemeshCli, TessellateReadsQuantizeOutputAndReportsBadLengths) {
  const std::string layout = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj";
  ASSERT_EQ(run("quantize " + layout + " -o " + path("q.json")).exit_code, 0);
  testing::CliRun r = run("tessellate " + layout + " " + path("q.json") + " -o " + path("m.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("5996 quads"), std::string::npos) << r.out;
  const QuadMesh m = read_obj_quads(path("m.obj"));
  EXPECT_EQ(m.num_quads(), 5996);
  EXPECT_EQ(std::set<int>(m.quad_patch.begin(), m.quad_patch.end()).size(), 104u);

  write("short.json", R"({"subside_lengths": [1, 2, 3]})");
  r = run("tessellate " + layout + " " + path("short.json") + " -o " + path("m2.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + path("short.json") +
                       ": /subside_lengths: 3 lengths, but the layout has 275 subsides\n");
  EXPECT_FALSE(std::filesystem::exists(path("m2.obj")));

  r = run("metrics " + path("q.json"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + path("q.json") + ": no faces: expected an OBJ quad mesh\n");

  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  r = run("metrics " + path("tri.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + path("tri.obj") + ":4: face 0 has 3 vertices, expected a quad\n");

  r = run("metrics " + path("m.obj") + " --reference " + layout + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["faces"], 5996);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_EQ(j["manifold"], true);
  EXPECT_LT(j["hausdorff_relative"].get<double>(), 0.02);

  r = run("render " + path("m.obj") + " -o " + path("m.png") + " --width 320 --height 240");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(path("m.png")).substr(1, 3), "PNG");
  // The base complex's patches coloured: as many as metrics counts, each quad in one.
  const std::vector<int> patches = base_complex_patches(read_obj_quads(path("m.obj")));
  ASSERT_EQ(patches.size(), 5996u);
  EXPECT_EQ(*std::max_element(patches.begin(), patches.end()) + 1, j["base_complex_faces"]);
  r = run("render " + path("m.obj") + " -o " + path("b.png") + " --width 320 --height 240" +
          " --base-complex");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "picture       " + path("b.png") + ": 320 x 240 pixels, 5996 quads, " +
                       std::to_string(j["base_complex_faces"].get<int>()) +
                       " base-complex patches\n");
  EXPECT_NE(slurp(path("b.png")), slurp(path("m.png")));  // other colours
  r = run("render " + path("m.obj") + " -o " + path("c.png") + " --base-complex --no-patches");
  EXPECT_EQ(r.exit_code, 2);
  r = run("render " + path("m.obj") + " -o " + path("m.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("refusing to overwrite an input"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace bimdf::quant
