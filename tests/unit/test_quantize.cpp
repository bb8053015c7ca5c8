// The QuadWild-layout quantizer (include/bimdf/quant): the reader's invariants on every shared
// layout, the generated Bi-MDF models against the reference quantizer's own models (the same
// multiset of cost terms), optima and energies against the reference results, feasibility of
// every quantization, and exact error messages for broken layouts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "bimdf/flow.hpp"
#include "bimdf/io.hpp"
#include "bimdf/quant/quantize.hpp"
#include "bimdf/solve.hpp"
#include "cli_fixture.hpp"
#include "shared_layouts.hpp"
#include "surface_fixtures.hpp"

namespace bimdf::quant {
namespace {

namespace fs = std::filesystem;

const fs::path kInstances = fs::path(BIMDF_SHARED_DATA_DIR) / "instances";
using testing::kLayouts;
using testing::layout_path;
using testing::Reference;
using testing::references;

// 6 significant digits, as the reference table prints its energies.
void expect_printed(double ours, double printed, const std::string& what) {
  EXPECT_NEAR(ours, printed, 6e-6 * std::max(std::fabs(printed), 1e-3)) << what;
}

// Checks the layout against the mesh on its own terms, independently of the reader's logic.
void expect_consistent(const Layout& L, const std::string& mesh) {
  const TriangleMesh& m = L.mesh;
  std::map<std::pair<int, int>, int> directed;  // half-edge → face
  for (int f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i) directed[{m.faces[f][i], m.faces[f][(i + 1) % 3]}] = f;
  ASSERT_EQ(directed.size(), 3u * m.num_faces()) << mesh << ": orientation not coherent";
  std::vector<int> appearances(L.subsides.size(), 0);
  for (size_t c = 0; c < L.charts.size(); ++c) {
    const Chart& chart = L.charts[c];
    if (chart.empty()) continue;
    // Disk: Euler characteristic 1.
    std::set<int> vertices;
    std::set<std::pair<int, int>> edges;
    for (int f : chart.faces)
      for (int i = 0; i < 3; ++i) {
        const int a = m.faces[f][i], b = m.faces[f][(i + 1) % 3];
        vertices.insert(a);
        edges.insert({std::min(a, b), std::max(a, b)});
      }
    EXPECT_EQ(static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) +
                  static_cast<int>(chart.faces.size()),
              1)
        << mesh << " chart " << c;
    ASSERT_GE(chart.valence(), 3);
    ASSERT_LE(chart.valence(), 6);
    ASSERT_EQ(chart.corners.size(), chart.sides.size());
    // Walking the sides' subsides in order gives a closed loop of border half-edges of the
    // chart (chart on the left), from corner to corner.
    for (int j = 0; j < chart.valence(); ++j) {
      const Side& side = chart.sides[j];
      int at = chart.corners[j];
      for (size_t i = 0; i < side.subsides.size(); ++i) {
        const int s = side.subsides[i];
        const Subside& sub = L.subsides[s];
        ++appearances[s];
        const int slot = side.reversed[i] ? 1 : 0;
        EXPECT_EQ(sub.charts[slot], static_cast<int>(c)) << mesh << " subside " << s;
        EXPECT_EQ(sub.sides[slot], j) << mesh << " subside " << s;
        std::vector<int> chain = sub.vertices;
        if (side.reversed[i]) std::reverse(chain.begin(), chain.end());
        EXPECT_EQ(chain.front(), at) << mesh << " chart " << c << " side " << j;
        for (size_t k = 0; k + 1 < chain.size(); ++k) {
          const auto it = directed.find({chain[k], chain[k + 1]});
          ASSERT_TRUE(it != directed.end()) << mesh << " subside " << s << " leaves the mesh";
          EXPECT_EQ(L.face_chart[it->second], static_cast<int>(c)) << mesh << " subside " << s;
          const auto back = directed.find({chain[k + 1], chain[k]});
          const int across = back == directed.end() ? -1 : L.face_chart[back->second];
          EXPECT_NE(across, static_cast<int>(c)) << mesh << " subside " << s << " is interior";
          EXPECT_EQ(across, sub.charts[1 - slot]) << mesh << " subside " << s;
        }
        at = chain.back();
      }
      EXPECT_EQ(at, chart.corners[(j + 1) % chart.valence()]) << mesh << " chart " << c;
    }
  }
  for (size_t s = 0; s < L.subsides.size(); ++s)
    EXPECT_EQ(appearances[s], L.subsides[s].on_border() ? 1 : 2) << mesh << " subside " << s;
}

TEST(QuantizeShared, LayoutsReadConsistently) {
  REQUIRE_SHARED_LAYOUTS();
  int layouts = 0;
  for (const Reference& r : references()) {
    const Layout L = read_quadwild_layout(layout_path(r.mesh));
    int charts = 0;
    for (const Chart& c : L.charts) charts += !c.empty();
    EXPECT_EQ(charts, r.patches) << r.mesh;
    expect_consistent(L, r.mesh);
    ++layouts;
  }
  EXPECT_EQ(layouts, 23);
}

// The cost terms of a model, as a sorted list of comparable tuples (node ids differ only by
// numbering, so they are left out): end kinds, bounds, cost kind and parameters.
using Term = std::tuple<int, int64_t, int64_t, std::string, long long, long long>;
std::vector<Term> terms(const Problem& p) {
  std::vector<Term> out;
  for (int e = 0; e < p.num_edges(); ++e) {
    const int ends = (p.end_a[e].head ? 1 : 0) + (p.end_b[e].head ? 1 : 0) +
                     (p.end_a[e].node == p.end_b[e].node ? 10 : 0);
    const Cost& c = p.cost[e];
    std::string kind(cost_kind_name(c.kind()));
    double target = 0, weight = 0;
    if (c.kind() == CostKind::Zero) {
      kind = "zero";  // the guess is only a starting point
    } else {
      target = c.target();
      weight = c.weight();
    }
    // Seven decimals: our weights use alpha as a double, the reference's a float (2e-8
    // relative), which must not count as a difference.
    out.emplace_back(ends, p.lower[e], p.upper[e], kind, std::llround(target * 1e7),
                     std::llround(weight * 1e7));
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(QuantizeShared, ModelsEqualTheReferenceQuantizersModels) {
  REQUIRE_SHARED_LAYOUTS();
  int compared = 0;
  for (const Reference& r : references()) {
    const Layout L = read_quadwild_layout(layout_path(r.mesh));
    for (bool align : {false, true}) {
      QuantizeOptions o;
      o.align = align;
      o.second_round = false;
      const Quantization q = quantize(L, o);
      const Problem reference = read_problem_file(
          (kInstances / (r.mesh + (align ? "__flow_0.bimdf" : "__flow_noalign_lemon_0.bimdf")))
              .string());
      const Problem& ours = q.final_round().model.problem;
      EXPECT_EQ(ours.num_nodes(), reference.num_nodes()) << r.mesh << " align " << align;
      EXPECT_EQ(ours.num_edges(), reference.num_edges()) << r.mesh << " align " << align;
      EXPECT_TRUE(terms(ours) == terms(reference)) << r.mesh << " align " << align;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 46);
}

// Every rule a quantization keeps, recomputed from the model's flow.
void expect_valid(const Layout& L, const Quantization& q, const std::string& mesh) {
  const QuantizationRound& last = q.final_round();
  EXPECT_TRUE(check_flow(last.model.problem, last.solution.flow).feasible()) << mesh;
  for (size_t s = 0; s < L.subsides.size(); ++s) EXPECT_GE(q.lengths()[s], 1) << mesh;
  for (size_t c = 0; c < L.charts.size(); ++c) {
    if (L.charts[c].empty()) continue;
    int64_t perimeter = 0;
    for (int64_t side : side_lengths(L, static_cast<int>(c), q.lengths())) {
      EXPECT_GE(side, 1) << mesh << " chart " << c;
      perimeter += side;
    }
    EXPECT_EQ(perimeter % 2, 0) << mesh << " chart " << c;
    EXPECT_GE(perimeter, 4) << mesh << " chart " << c;
  }
}

TEST(QuantizeShared, WithoutAlignmentOptimaAndEnergiesEqualTheReference) {
  REQUIRE_SHARED_LAYOUTS();
  for (const Reference& r : references()) {
    const Layout L = read_quadwild_layout(layout_path(r.mesh));
    QuantizeOptions o;
    o.align = false;
    const Quantization q = quantize(L, o);
    ASSERT_EQ(q.rounds.size(), 1u);
    EXPECT_EQ(q.final_round().solution.status, SolveStatus::Optimal) << r.mesh;
    // 2.3e-8 relative: the reference reads alpha as a float.
    EXPECT_NEAR(q.final_round().solution.objective, r.noalign_opt, 5e-8 * r.noalign_opt) << r.mesh;
    const Energies& e = q.final_round().energies;
    expect_printed(e.isometry, r.noalign_iso, r.mesh + " isometry");
    expect_printed(e.regularity, r.noalign_reg, r.mesh + " regularity");
    // The pattern count from the flow's strips is exact on regular charts: within 1% of the
    // quads the reference wrote (most agree exactly).
    EXPECT_NEAR(q.final_round().estimated_quads, r.noalign_quads, 0.011 * r.noalign_quads)
        << r.mesh;
    // Without alignment the model's optimum is exactly the IQP energy of its result.
    EXPECT_NEAR(e.isometry + e.regularity, q.final_round().solution.objective, 1e-9 * r.noalign_opt)
        << r.mesh;
    expect_valid(L, q, r.mesh);
  }
}

TEST(QuantizeShared, WithAlignmentOptimaEnergiesAndPairsEqualTheReference) {
  REQUIRE_SHARED_LAYOUTS();
  for (const Reference& r : references()) {
    const Layout L = read_quadwild_layout(layout_path(r.mesh));
    const Quantization q = quantize(L, QuantizeOptions{});
    EXPECT_EQ(q.rounds.size(), fs::exists(kInstances / (r.mesh + "__flow_1.bimdf")) ? 2u : 1u)
        << r.mesh;
    EXPECT_NEAR(q.final_round().solution.objective, r.align_opt, 5e-8 * r.align_opt) << r.mesh;
    const Energies& e = q.final_round().energies;
    expect_printed(e.alignment, r.align_energy, r.mesh + " alignment");
    expect_printed(e.regularity, r.align_reg, r.mesh + " regularity");
    EXPECT_EQ(e.aligned_pairs, r.aligned) << r.mesh;
    EXPECT_EQ(e.pairs, r.pairs) << r.mesh;
    EXPECT_NEAR(q.final_round().estimated_quads, r.align_quads, 0.011 * r.align_quads) << r.mesh;
    expect_valid(L, q, r.mesh);
  }
}

// A hand-made layout: an nx × ny grid of unit squares, each split into two triangles, with a
// patch id per square and corners per patch; written as NAME.obj/.patch/.corners.
struct GridLayout {
  int nx, ny;
  std::vector<int> square_patch;
  std::vector<std::vector<int>> corners;
  int vertex(int x, int y) const { return y * (nx + 1) + x; }

  void write(const fs::path& obj) const {
    std::ofstream o(obj);
    for (int y = 0; y <= ny; ++y)
      for (int x = 0; x <= nx; ++x) o << "v " << x << " " << y << " 0\n";
    std::ofstream p(fs::path(obj).replace_extension(".patch"));
    p << 2 * nx * ny << "\n";
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const int a = vertex(x, y) + 1, b = vertex(x + 1, y) + 1, c = vertex(x + 1, y + 1) + 1,
                  d = vertex(x, y + 1) + 1;
        o << "f " << a << " " << b << " " << c << "\nf " << a << " " << c << " " << d << "\n";
        p << square_patch[y * nx + x] << "\n" << square_patch[y * nx + x] << "\n";
      }
    std::ofstream c(fs::path(obj).replace_extension(".corners"));
    c << corners.size() << "\n";
    for (const auto& list : corners) {
      c << list.size() << "\n";
      for (int v : list) c << v << "\n";
    }
  }
};

// Two 2×2 quads side by side: a 4 × 2 grid, patches 0 (left) and 1 (right).
GridLayout two_quads() {
  GridLayout g{4, 2, {0, 0, 1, 1, 0, 0, 1, 1}, {}};
  g.corners = {{g.vertex(0, 0), g.vertex(2, 0), g.vertex(2, 2), g.vertex(0, 2)},
               {g.vertex(2, 0), g.vertex(4, 0), g.vertex(4, 2), g.vertex(2, 2)}};
  return g;
}

class QuantizeFiles : public testing::CliFixture {
 protected:
  std::string write_layout(const GridLayout& g) {
    const std::string obj = path("grid.obj");
    g.write(obj);
    return obj;
  }
  // The message read_quadwild_layout throws for `obj`, or "" when it reads.
  std::string error_of(const std::string& obj) {
    try {
      read_quadwild_layout(obj);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(QuantizeFiles, HandMadeLayoutQuantizesToTheRegularGrid) {
  const std::string obj = write_layout(two_quads());
  const Layout L = read_quadwild_layout(obj);
  ASSERT_EQ(L.charts.size(), 2u);
  EXPECT_EQ(L.charts[0].valence(), 4);
  EXPECT_EQ(L.subsides.size(), 7u);  // the shared side and three border sides per chart
  expect_consistent(L, "grid");
  QuantizeOptions o;
  o.edge_length = 0.5;  // every side of length 2 should get 4 quads
  const Quantization q = quantize(L, o);
  for (int64_t x : q.lengths()) EXPECT_EQ(x, 4);
  EXPECT_NEAR(q.final_round().solution.objective, 0, 1e-12);
  EXPECT_EQ(q.final_round().energies.regular_charts, 2);
  expect_valid(L, q, "grid");
}

TEST_F(QuantizeFiles, TargetEdgeLengthOptions) {
  const Layout L = read_quadwild_layout(write_layout(two_quads()));
  // The grid's triangles have edges 1, 1 and √2: the average edge is (2 + √2)/3.
  EXPECT_NEAR(L.average_edge_length, (2 + std::sqrt(2.0)) / 3, 1e-6);
  QuantizeOptions o;
  o.scale = 2;
  EXPECT_NEAR(target_edge_length(L, o), 2 * L.average_edge_length, 1e-12);
  o.target_faces = 32;  // area 8: squares of side 0.5
  EXPECT_NEAR(target_edge_length(L, o), 0.5, 1e-12);
  o.edge_length = 0.25;  // wins over the others
  EXPECT_EQ(target_edge_length(L, o), 0.25);
}

TEST_F(QuantizeFiles, BrokenLayoutsGetExactErrors) {
  GridLayout g = two_quads();
  const std::string obj = write_layout(g);
  const std::string stem = path("grid");
  EXPECT_EQ(error_of(obj), "");

  write("grid.patch", "15\n");
  EXPECT_EQ(error_of(obj), stem + ".patch:1: the face count is 15, but " + obj + " has 16 faces");

  g.square_patch[0] = 7;
  write_layout(g);
  EXPECT_EQ(error_of(obj),
            stem + ".corners:1: the patch count is 2, but " + stem + ".patch uses patch id 7");

  g = two_quads();
  g.corners[1][2] = 99;
  write_layout(g);
  EXPECT_EQ(error_of(obj),
            stem + ".corners:10: corner 2 of patch 1: 99 is out of range (expected 0..14)");

  g = two_quads();
  g.corners[0] = {g.vertex(0, 0), g.vertex(2, 2)};
  write_layout(g);
  EXPECT_EQ(error_of(obj), obj + ": chart 0 has 2 corners on its boundary, expected 3 to 6");

  // A ring of eight squares around a ninth: the ring is not a disk.
  GridLayout ring{3, 3, {0, 0, 0, 0, 1, 0, 0, 0, 0}, {}};
  ring.corners = {{ring.vertex(0, 0), ring.vertex(3, 0), ring.vertex(3, 3), ring.vertex(0, 3)},
                  {ring.vertex(1, 1), ring.vertex(2, 1), ring.vertex(2, 2), ring.vertex(1, 2)}};
  write_layout(ring);
  EXPECT_EQ(error_of(obj), obj + ": chart 0 is not a disk: Euler characteristic 0, expected 1");

  fs::remove(stem + ".corners");
  EXPECT_EQ(error_of(obj).rfind(stem + ".corners: cannot open file", 0), 0u) << error_of(obj);
}

TEST(QuantizeExample, TargetFacesGivesAboutThatManyQuads) {
  const Layout L =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  for (int64_t wanted : {3000, 20000}) {
    QuantizeOptions o;
    o.target_faces = wanted;
    const Quantization q = quantize(L, o);
    EXPECT_NEAR(q.final_round().estimated_quads, wanted, 0.01 * wanted);
    expect_valid(L, q, "npm_bunny");
  }
}

TEST_F(QuantizeFiles, CornerInsideItsChartIsIgnoredWithAWarning) {
  GridLayout g = two_quads();
  g.corners[0].push_back(g.vertex(1, 1));  // interior to chart 0
  const Layout L = read_quadwild_layout(write_layout(g));
  EXPECT_EQ(L.charts[0].valence(), 4);
  ASSERT_EQ(L.warnings.size(), 1u);
  EXPECT_EQ(L.warnings[0], "chart 0: corner vertex " + std::to_string(g.vertex(1, 1)) +
                               " is not on the chart's boundary; ignored");
}

TEST_F(QuantizeFiles, CliQuantizesTheBundledExampleAndExportsItsModel) {
  const std::string example = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj";
  const testing::CliRun r =
      run("quantize --no-align --json " + example + " --write-bimdf " + path("model.bimdf"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "optimal");
  EXPECT_NEAR(j["objective"].get<double>(), 0.886439270369, 5e-8);
  EXPECT_EQ(j["charts"], 104);
  EXPECT_EQ(j["subside_lengths"].size(), j["subsides"].get<size_t>());
  // The exported model solves to the same optimum, and equals the reference model's terms.
  const Problem exported = read_problem_file(path("model.bimdf"));
  Solver again(exported);
  ASSERT_EQ(again.run(), SolveStatus::Optimal);
  EXPECT_NEAR(again.solution().objective, j["objective"].get<double>(), 1e-12);
  EXPECT_TRUE(terms(exported) ==
              terms(read_problem_file(std::string(BIMDF_EXAMPLES_DIR) +
                                      "/npm_bunny__flow_noalign_lemon_0.bimdf")));
  // Never over an input.
  const testing::CliRun clash = run("quantize " + example + " -o " + example);
  EXPECT_EQ(clash.exit_code, 2);
  const testing::CliRun missing = run("quantize " + path("nothing.obj"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err.rfind("error: " + path("nothing.obj") + ": cannot open file", 0), 0u)
      << missing.err;
}

}  // namespace
// An open cylinder as two charts (its halves): each border circle is two border subsides
// whose targets are about one edge each. Quantized as the reference does, each circle gets two
// edges (a hole a quad mesh cannot keep); with min_border_loop 3, at least three.
TEST(QuantizeModel, BorderLoopsKeepAtLeastTheirMinimum) {
  const TriangleMesh m = test::cylinder(1, 12, 3);
  std::vector<int> face_chart;
  for (const auto& f : m.faces) {
    double x = 0, y = 0;
    for (int v : f) x += m.vertices[v][0], y += m.vertices[v][1];
    face_chart.push_back(std::atan2(y, x) > 0 ? 0 : 1);
  }
  // Vertex (i, j) is i·4 + j: angle 30°·i, height j/3. The halves meet at i = 0 and i = 6.
  const std::vector<int> corners = {0, 3, 24, 27};
  const Layout L = build_layout(m, face_chart, {corners, corners}, "<cylinder>");
  for (int minimum : {1, 3}) {
    QuantizeOptions o;
    o.edge_length = 3;
    o.model.min_border_loop = minimum;
    const Quantization q = quantize(L, o);
    std::map<int, int64_t> circle;  // height of the circle → its quantized length
    for (size_t s = 0; s < L.subsides.size(); ++s)
      if (L.subsides[s].on_border())
        circle[static_cast<int>(std::lround(3 * m.vertices[L.subsides[s].vertices[0]][2]))] +=
            q.lengths()[s];
    ASSERT_EQ(circle.size(), 2u);
    for (const auto& [height, length] : circle) {
      if (minimum == 1)
        EXPECT_EQ(length, 2) << "circle at height " << height;
      else
        EXPECT_GE(length, 3) << "circle at height " << height;
    }
  }
}

}  // namespace bimdf::quant
