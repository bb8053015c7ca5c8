// The T-mesh model: validation (every rule, exact messages), incidence, side lengths and the
// JSON form (exact round trips, exact error messages).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "bimdf/error.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace {

using bimdf::InputError;
using bimdf::tmesh::PatchGrid;
using bimdf::tmesh::TMesh;
using bimdf::tmesh::TMeshIncidence;

// Three patches on a 2×2 quad grid (mesh vertex (x, y) = 3y + x): a tall patch P0 on the left,
// P1 and P2 stacked on the right. Their shared corner, vertex 7, lies inside P0's side 1: a
// T-junction. Every outer arc is a border arc.
//
//   6 ---a5--- 5 ---a4--- 4
//   |          |          |
//   a6   P0    a8   P2    a3
//   |          |          |
//   |          7 ---a9--- 3
//   |          |          |
//   |          a7   P1    a2
//   |          |          |
//   0 ---a0--- 1 ---a1--- 2
TMesh t_junction_tmesh() {
  TMesh t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0},
                {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {1, 1, 0.1}};
  t.vertex_mesh_vertex = {0, 1, 2, 5, 8, 7, 6, 4};
  t.arc_ends = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 0}, {1, 7}, {7, 5}, {7, 3}};
  t.arc_target = {1.25, 0.75, 1, 1, 0.75, 1.25, 2.5, 1.1, 0.9, 0.8};
  t.arc_chain = {{0, 1}, {1, 2}, {2, 5}, {5, 8}, {8, 7}, {7, 6}, {6, 3, 0}, {1, 4}, {4, 7}, {4, 5}};
  t.arc_feature = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  t.patch_sides = {{{{0}, {14, 16}, {10}, {12}}},  // 0 → 1 → 7 → 5 → 6 → 0
                   {{{2}, {4}, {19}, {15}}},       // 1 → 2 → 3 → 7 → 1
                   {{{18}, {6}, {8}, {17}}}};      // 7 → 3 → 4 → 5 → 7
  t.patch_grid = {PatchGrid{1, 2, {0, 1, 3, 4, 6, 7}}, PatchGrid{1, 1, {1, 2, 4, 5}},
                  PatchGrid{1, 1, {4, 5, 7, 8}}};
  t.nonzero_paths = {{14, 16}, {0, 2}, {18, 6}};
  return t;
}

void expect_same(const TMesh& a, const TMesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.vertex_mesh_vertex, b.vertex_mesh_vertex);
  EXPECT_EQ(a.arc_ends, b.arc_ends);
  EXPECT_EQ(a.arc_target, b.arc_target);  // exact: doubles must survive the text form
  EXPECT_EQ(a.arc_chain, b.arc_chain);
  EXPECT_EQ(a.arc_feature, b.arc_feature);
  EXPECT_EQ(a.patch_sides, b.patch_sides);
  ASSERT_EQ(a.patch_grid.size(), b.patch_grid.size());
  for (size_t p = 0; p < a.patch_grid.size(); ++p) {
    EXPECT_EQ(a.patch_grid[p].width, b.patch_grid[p].width) << "patch " << p;
    EXPECT_EQ(a.patch_grid[p].height, b.patch_grid[p].height) << "patch " << p;
    EXPECT_EQ(a.patch_grid[p].vertices, b.patch_grid[p].vertices) << "patch " << p;
  }
  EXPECT_EQ(a.nonzero_paths, b.nonzero_paths);
}

std::string to_json(const TMesh& t) {
  std::ostringstream out;
  bimdf::tmesh::write_tmesh_json(out, t);
  return out.str();
}

std::string validation_error(const TMesh& t) {
  try {
    bimdf::tmesh::validate_tmesh(t, "fixture");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string json_error(const std::string& text) {
  try {
    bimdf::tmesh::parse_tmesh_json(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TMeshModel, TJunctionFixtureValidatesWithExpectedIncidence) {
  const TMesh t = t_junction_tmesh();
  const TMeshIncidence inc = bimdf::tmesh::validate_tmesh(t);
  ASSERT_EQ(inc.half_arc_patch.size(), 20u);
  ASSERT_EQ(inc.half_arc_side.size(), 20u);
  const std::vector<int> patch = {0, -1, 1, -1, 1, -1, 2, -1, 2, -1,
                                  0, -1, 0, -1, 0, 1,  0, 2,  2, 1};
  const std::vector<int> side = {0, -1, 0, -1, 1, -1, 1, -1, 2, -1, 2, -1, 3, -1, 1, 3, 1, 3, 0, 2};
  EXPECT_EQ(inc.half_arc_patch, patch);
  EXPECT_EQ(inc.half_arc_side, side);
  for (int h = 0; h < 20; ++h) EXPECT_EQ(inc.is_border(h), h < 14 && h % 2 == 1) << h;
  // The T-junction: vertex 7 is a corner of P1 and P2 and inside P0's side 1.
  EXPECT_EQ(t.half_arc_head(14), 7);
  EXPECT_EQ(t.half_arc_tail(t.patch_sides[1][3][0]), 7);
  EXPECT_EQ(t.half_arc_tail(t.patch_sides[2][0][0]), 7);
  EXPECT_FALSE(bimdf::tmesh::find_tmesh_issue(t).has_value());
}

TEST(TMeshModel, SideLengthSumsTheSidesArcs) {
  const TMesh t = t_junction_tmesh();
  const std::vector<int64_t> length = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  EXPECT_EQ(bimdf::tmesh::side_length(t, 0, 1, length), 8 + 9);
  EXPECT_EQ(bimdf::tmesh::side_length(t, 0, 3, length), 7);
  EXPECT_EQ(bimdf::tmesh::side_length(t, 1, 2, length), 10);
  EXPECT_EQ(bimdf::tmesh::side_length(t, 2, 3, length), 9);
  EXPECT_THROW(bimdf::tmesh::side_length(t, 3, 0, length), std::out_of_range);
  EXPECT_THROW(bimdf::tmesh::side_length(t, 0, 0, {1, 2}), std::invalid_argument);
}

TEST(TMeshModel, GeometryIsOptional) {
  TMesh t = t_junction_tmesh();
  t.patch_grid.clear();
  EXPECT_EQ(validation_error(t), "no error");  // chains without grids
  t.vertex_mesh_vertex.clear();
  EXPECT_EQ(validation_error(t), "no error");  // chains without mesh vertices
  t.arc_chain.clear();
  t.arc_feature.clear();
  t.nonzero_paths.clear();
  EXPECT_EQ(validation_error(t), "no error");  // topology and targets only
  t.vertex_mesh_vertex.assign(8, -1);          // "no mesh vertex" spelled out
  EXPECT_EQ(validation_error(t), "no error");
}

// Each case breaks one rule of the fixture; the message must say exactly what and where.
struct Violation {
  const char* name;
  std::function<void(TMesh&)> edit;
  const char* message;
};

TEST(TMeshModel, EveryRuleViolatedOnceGivesItsMessage) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Violation> cases = {
      {"target count", [](TMesh& t) { t.arc_target.pop_back(); },
       "arc_target has 9 entries for 10 arcs, expected one per arc"},
      {"chain count", [](TMesh& t) { t.arc_chain.pop_back(); },
       "arc_chain has 9 entries for 10 arcs, expected none or one per arc"},
      {"feature count", [](TMesh& t) { t.arc_feature.push_back(0); },
       "arc_feature has 11 entries for 10 arcs, expected none or one per arc"},
      {"mesh vertex count", [](TMesh& t) { t.vertex_mesh_vertex.pop_back(); },
       "vertex_mesh_vertex has 7 entries for 8 vertices, expected none or one per vertex"},
      {"grid count", [](TMesh& t) { t.patch_grid.pop_back(); },
       "patch_grid has 2 entries for 3 patches, expected none or one per patch"},
      {"position", [nan](TMesh& t) { t.vertices[3][1] = nan; },
       "vertex 3: coordinate 1 is nan, expected a finite number"},
      {"mesh vertex id", [](TMesh& t) { t.vertex_mesh_vertex[2] = -2; },
       "vertex 2: mesh vertex -2, expected an id ≥ 0 or -1 (none)"},
      {"arc end range", [](TMesh& t) { t.arc_ends[4][1] = 8; },
       "arc 4: end 1 is vertex 8, out of range [0, 8)"},
      {"arc end negative", [](TMesh& t) { t.arc_ends[0][0] = -1; },
       "arc 0: end 0 is vertex -1, out of range [0, 8)"},
      {"distinct ends",
       [](TMesh& t) {
         t.arc_ends[4] = {4, 4};
       },
       "arc 4: both ends are vertex 4 (an arc joins two distinct vertices)"},
      {"negative target", [](TMesh& t) { t.arc_target[2] = -0.5; },
       "arc 2: target -0.5 is negative, expected a length ≥ 0"},
      {"infinite target", [inf](TMesh& t) { t.arc_target[2] = inf; },
       "arc 2: target inf is not finite, expected a length ≥ 0"},
      {"nan target", [nan](TMesh& t) { t.arc_target[5] = nan; },
       "arc 5: target nan is not finite, expected a length ≥ 0"},
      {"feature flag", [](TMesh& t) { t.arc_feature[6] = 2; },
       "arc 6: feature flag 2, expected 0 or 1"},
      {"short chain", [](TMesh& t) { t.arc_chain[3] = {5}; },
       "arc 3: chain has 1 mesh vertex, expected at least 2 (tail to head)"},
      {"chain id",
       [](TMesh& t) {
         t.arc_chain[6] = {6, -3, 0};
       },
       "arc 6: chain entry 1 is mesh vertex -3, expected an id ≥ 0"},
      {"chain start",
       [](TMesh& t) {
         t.arc_chain[0] = {3, 1};
       },
       "arc 0: chain starts at mesh vertex 3, but its tail, vertex 0, is mesh vertex 0"},
      {"chain end",
       [](TMesh& t) {
         t.arc_chain[7] = {1, 5};
       },
       "arc 7: chain ends at mesh vertex 5, but its head, vertex 7, is mesh vertex 4"},
      {"chain without mesh vertex", [](TMesh& t) { t.vertex_mesh_vertex[7] = -1; },
       "arc 7: chain ends at mesh vertex 4, but its head, vertex 7, is mesh vertex -1"},
      {"empty side", [](TMesh& t) { t.patch_sides[1][2].clear(); },
       "patch 1, side 2: empty, expected at least one half-arc"},
      {"half-arc range", [](TMesh& t) { t.patch_sides[2][1] = {20}; },
       "patch 2, side 1: half-arc 20 is out of range [0, 20)"},
      {"chained inside a side",
       [](TMesh& t) {
         t.patch_sides[0][1] = {14, 17};
       },
       "patch 0, side 1: half-arc 17 starts at vertex 5, but the previous one ends at vertex 7"},
      {"chained corner to corner",
       [](TMesh& t) {
         t.patch_sides[0][1] = {16, 14};
       },
       "patch 0, side 1: half-arc 16 starts at vertex 7, but side 0 ends at vertex 1"},
      {"closed loop", [](TMesh& t) { t.patch_sides[0][0] = {1}; },
       "patch 0, side 0: half-arc 1 starts at vertex 1, but side 3 ends at vertex 0"},
      {"simple loop",
       [](TMesh& t) {
         t.patch_sides[1][2] = {19, 16, 17};
       },
       "patch 1, side 3: half-arc 15 starts at vertex 7, already on side 2 (a patch's boundary "
       "passes each vertex once)"},
      {"clockwise patch",
       [](TMesh& t) {
         t.patch_sides[1] = {{{14}, {18}, {5}, {3}}};
       },
       "patch 1, side 0: half-arc 14 already lies on patch 0, side 1 (a half-arc lies on at most "
       "one side: sides run counter-clockwise, so the patch across arc 7 walks half-arc 15)"},
      {"arc without patch",
       [](TMesh& t) {
         t.arc_ends.push_back({0, 7});
         t.arc_target.push_back(1.4);
         t.arc_chain.push_back({0, 4});
         t.arc_feature.push_back(0);
       },
       "arc 10 (vertices 0 → 7) lies on no patch side (every arc borders one or two patches)"},
      {"chains meet",
       [](TMesh& t) {
         t.vertex_mesh_vertex.clear();
         t.arc_chain[8] = {3, 7};
       },
       "patch 0, side 1: half-arc 16's chain starts at mesh vertex 3, but the previous "
       "half-arc's chain ends at mesh vertex 4"},
      {"grid missing", [](TMesh& t) { t.patch_grid[1] = PatchGrid{}; },
       "patch 1: grid is 0×0, expected at least 1×1 (patch_grid holds a grid for every patch or "
       "for none)"},
      {"grid height", [](TMesh& t) { t.patch_grid[2].height = 0; },
       "patch 2: grid is 1×0, expected at least 1×1 (patch_grid holds a grid for every patch or "
       "for none)"},
      {"grid size", [](TMesh& t) { t.patch_grid[0].vertices.pop_back(); },
       "patch 0: grid has 5 mesh vertices, expected (1 + 1) × (2 + 1) = 6"},
      {"grid id", [](TMesh& t) { t.patch_grid[2].vertices[3] = -1; },
       "patch 2: grid vertex (1, 1) is mesh vertex -1, expected an id ≥ 0"},
      {"grid corner",
       [](TMesh& t) {
         t.patch_grid[2].vertices = {5, 4, 8, 7};
       },
       "patch 2: grid corner (0, 0) is mesh vertex 5, but corner 0, vertex 7, is mesh vertex 4"},
      {"grid border", [](TMesh& t) { t.patch_grid[0].vertices[2] = 9; },
       "patch 0, side 3: mesh vertex 1 along the side is 3 in its arcs' chains, but 9 in the "
       "grid at (0, 1)"},
      {"grid side length",
       [](TMesh& t) {
         t.vertex_mesh_vertex.clear();
         t.patch_grid[0] = PatchGrid{2, 1, {0, 1, 3, 4, 6, 7}};
       },
       "patch 0, side 0: its arcs' chains pass 2 mesh vertices, but the grid's side has 3 "
       "(width 2)"},
      {"empty path", [](TMesh& t) { t.nonzero_paths.push_back({}); },
       "non-zero path 3: empty, expected at least one half-arc"},
      {"path range",
       [](TMesh& t) {
         t.nonzero_paths[1] = {0, -1};
       },
       "non-zero path 1: half-arc -1 is out of range [0, 20)"},
      {"path chained",
       [](TMesh& t) {
         t.nonzero_paths[0] = {14, 6};
       },
       "non-zero path 0: half-arc 6 starts at vertex 3, but the previous one ends at vertex 7"},
  };
  for (const Violation& c : cases) {
    TMesh t = t_junction_tmesh();
    c.edit(t);
    EXPECT_EQ(validation_error(t), std::string("fixture: ") + c.message) << c.name;
    const auto issue = bimdf::tmesh::find_tmesh_issue(t);
    ASSERT_TRUE(issue.has_value()) << c.name;
    EXPECT_EQ(issue->message, c.message) << c.name;
  }
}

TEST(TMeshModel, DefaultSourceNamesTheModel) {
  TMesh t = t_junction_tmesh();
  t.arc_target[0] = -1;
  try {
    bimdf::tmesh::validate_tmesh(t);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "<t-mesh>: arc 0: target -1 is negative, expected a length ≥ 0");
    EXPECT_EQ(e.source(), "<t-mesh>");
    EXPECT_EQ(e.location(), "");
  }
}

// ---- JSON ------------------------------------------------------------------------------------

// The unit square as one patch, with geometry: the smallest complete file, written exactly.
TEST(TMeshJson, WritesTheDocumentedLayout) {
  TMesh t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}};
  t.vertex_mesh_vertex = {0, 1, 3, 2};
  t.arc_ends = {{0, 1}, {1, 2}, {3, 2}, {3, 0}};
  t.arc_target = {1, 0.1, 1, 2.5};
  t.arc_chain = {{0, 1}, {1, 3}, {2, 3}, {2, 0}};
  t.arc_feature = {1, 0, 0, 0};
  t.patch_sides = {{{{0}, {2}, {5}, {6}}}};
  t.patch_grid = {PatchGrid{1, 1, {0, 1, 2, 3}}};
  t.nonzero_paths = {{0, 2}};
  bimdf::tmesh::validate_tmesh(t);
  const std::string expected = R"({
  "format": "bimdf-tmesh",
  "version": 1,
  "vertices": [
    [0.0,0.0,0.0],
    [1.0,0.0,0.0],
    [1.0,1.0,0.0],
    [0.0,1.0,0.5]
  ],
  "vertex_mesh_vertex": [0,1,3,2],
  "arcs": [
    {"ends":[0,1],"target":1.0,"chain":[0,1],"feature":true},
    {"ends":[1,2],"target":0.1,"chain":[1,3],"feature":false},
    {"ends":[3,2],"target":1.0,"chain":[2,3],"feature":false},
    {"ends":[3,0],"target":2.5,"chain":[2,0],"feature":false}
  ],
  "patches": [
    {"sides":[[0],[2],[5],[6]],"grid":{"width":1,"height":1,"vertices":[0,1,2,3]}}
  ],
  "nonzero_paths": [
    [0,2]
  ]
}
)";
  EXPECT_EQ(to_json(t), expected);
  expect_same(bimdf::tmesh::parse_tmesh_json(expected, "square.json"), t);
}

TEST(TMeshJson, FixtureRoundTripsExactly) {
  TMesh t = t_junction_tmesh();
  t.vertices[7] = {1.0 / 3.0, 2.0 / 7.0, -1e-300};
  t.arc_target[3] = 0.1 + 0.2;  // not the double nearest 0.3
  const std::string text = to_json(t);
  const TMesh back = bimdf::tmesh::parse_tmesh_json(text, "fixture.json");
  expect_same(back, t);
  EXPECT_EQ(to_json(back), text);

  // Without optional fields: they stay absent.
  t.vertex_mesh_vertex.clear();
  t.arc_chain.clear();
  t.arc_feature.clear();
  t.patch_grid.clear();
  t.nonzero_paths.clear();
  const std::string bare = to_json(t);
  EXPECT_EQ(bare.find("chain"), std::string::npos);
  EXPECT_EQ(bare.find("grid"), std::string::npos);
  EXPECT_EQ(bare.find("feature"), std::string::npos);
  EXPECT_EQ(bare.find("vertex_mesh_vertex"), std::string::npos);
  expect_same(bimdf::tmesh::parse_tmesh_json(bare, "bare.json"), t);
}

// A k×l grid of patches over a quad mesh whose columns and rows are 1–3 quads wide; some
// horizontally adjacent patches are merged, which turns the vertical arc between them into
// T-junctions above and below. Arcs are randomly oriented, so both half-arc parities occur.
TMesh random_grid_tmesh(std::mt19937& rng, bool geometry, int& border_half_arcs) {
  std::uniform_int_distribution<int> size(1, 4), quads(1, 3), coin(0, 1);
  std::uniform_real_distribution<double> real(-10, 10), target(0, 6);
  const int k = size(rng), l = size(rng);
  border_half_arcs = 2 * (k + l);
  std::vector<int> x0 = {0}, y0 = {0};  // mesh coordinate where column i / row j starts
  for (int i = 0; i < k; ++i) x0.push_back(x0.back() + quads(rng));
  for (int j = 0; j < l; ++j) y0.push_back(y0.back() + quads(rng));
  const int mesh_width = x0.back() + 1;
  auto mesh_vertex = [&](int x, int y) { return y * mesh_width + x; };
  auto vertex = [&](int i, int j) { return j * (k + 1) + i; };

  TMesh t;
  for (int j = 0; j <= l; ++j)
    for (int i = 0; i <= k; ++i) {
      t.vertices.push_back({real(rng), real(rng), real(rng)});
      if (geometry) t.vertex_mesh_vertex.push_back(mesh_vertex(x0[i], y0[j]));
    }
  // merged[j][i]: the patch in row j continues from column i to column i + 1.
  std::vector<std::vector<bool>> merged(l, std::vector<bool>(k, false));
  for (int j = 0; j < l; ++j)
    for (int i = 0; i + 1 < k; ++i) merged[j][i] = coin(rng) && coin(rng);
  const bool features = coin(rng);
  // Adds the arc from grid point (i, j) one step right (or up) and returns its half-arc in
  // that direction.
  auto add_arc = [&](int i, int j, bool right) {
    const int i2 = right ? i + 1 : i, j2 = right ? j : j + 1;
    std::vector<int> chain;
    for (int y = y0[j]; y <= y0[j2]; ++y)
      for (int x = x0[i]; x <= x0[i2]; ++x) chain.push_back(mesh_vertex(x, y));
    const bool flip = coin(rng);
    if (flip) std::reverse(chain.begin(), chain.end());
    const int a = t.num_arcs();
    t.arc_ends.push_back(flip ? std::array<int, 2>{vertex(i2, j2), vertex(i, j)}
                              : std::array<int, 2>{vertex(i, j), vertex(i2, j2)});
    t.arc_target.push_back(target(rng));
    if (geometry) t.arc_chain.push_back(chain);
    if (features) t.arc_feature.push_back(static_cast<uint8_t>(coin(rng)));
    return 2 * a + (flip ? 1 : 0);
  };
  std::vector<std::vector<int>> horizontal(l + 1, std::vector<int>(k));  // (i, j) → (i + 1, j)
  for (int j = 0; j <= l; ++j)
    for (int i = 0; i < k; ++i) horizontal[j][i] = add_arc(i, j, true);
  std::vector<std::vector<int>> vertical(l, std::vector<int>(k + 1, -1));  // (i, j) → (i, j + 1)
  for (int j = 0; j < l; ++j)
    for (int i = 0; i <= k; ++i)
      if (i == 0 || i == k || !merged[j][i - 1]) vertical[j][i] = add_arc(i, j, false);
  for (int j = 0; j < l; ++j)
    for (int i = 0; i < k;) {
      int i2 = i + 1;
      while (i2 < k && merged[j][i2 - 1]) ++i2;
      std::array<std::vector<int>, 4> sides;
      for (int c = i; c < i2; ++c) sides[0].push_back(horizontal[j][c]);
      sides[1] = {vertical[j][i2]};
      for (int c = i2 - 1; c >= i; --c) sides[2].push_back(TMesh::opposite(horizontal[j + 1][c]));
      sides[3] = {TMesh::opposite(vertical[j][i])};
      t.patch_sides.push_back(sides);
      if (geometry) {
        PatchGrid g{x0[i2] - x0[i], y0[j + 1] - y0[j], {}};
        for (int y = y0[j]; y <= y0[j + 1]; ++y)
          for (int x = x0[i]; x <= x0[i2]; ++x) g.vertices.push_back(mesh_vertex(x, y));
        t.patch_grid.push_back(std::move(g));
      }
      i = i2;
    }
  // Non-zero paths: random runs along rows and up the left column.
  std::uniform_int_distribution<int> row(0, l), column(0, k - 1);
  for (int n = coin(rng) + coin(rng); n > 0; --n) {
    const int j = row(rng), a = column(rng), b = column(rng);
    std::vector<int> path;
    for (int c = std::min(a, b); c <= std::max(a, b); ++c) path.push_back(horizontal[j][c]);
    t.nonzero_paths.push_back(path);
  }
  if (coin(rng)) {
    std::vector<int> path;
    for (int j = 0; j < l; ++j) path.push_back(vertical[j][0]);
    t.nonzero_paths.push_back(path);
  }
  return t;
}

TEST(TMeshJson, RandomGridTMeshesValidateAndRoundTrip) {
  std::mt19937 rng(2023);
  int merged_patches = 0;  // patches with T-junctions on their sides
  for (int round = 0; round < 200; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    int border_half_arcs = 0;
    const TMesh t = random_grid_tmesh(rng, round % 3 != 0, border_half_arcs);
    const TMeshIncidence inc = bimdf::tmesh::validate_tmesh(t);
    // Every side's half-arc is recorded where it lies; the border half-arcs are exactly the
    // perimeter's 2k + 2l outer ones.
    for (int p = 0; p < t.num_patches(); ++p)
      for (int s = 0; s < 4; ++s)
        for (int h : t.patch_sides[p][s]) {
          EXPECT_EQ(inc.half_arc_patch[h], p);
          EXPECT_EQ(inc.half_arc_side[h], s);
        }
    int border = 0;
    for (int h = 0; h < t.num_half_arcs(); ++h) border += inc.is_border(h);
    EXPECT_EQ(border, border_half_arcs);
    for (const auto& sides : t.patch_sides) merged_patches += sides[0].size() > 1;
    const std::string text = to_json(t);
    const TMesh back = bimdf::tmesh::parse_tmesh_json(text, "random.json");
    expect_same(back, t);
    EXPECT_EQ(to_json(back), text);
  }
  EXPECT_GT(merged_patches, 50);
}

// Bad input never crashes: random single edits of valid T-meshes (ids, sizes, grids) are either
// still valid — and then round-trip — or reported.
TEST(TMeshModel, RandomEditsAreValidatedWithoutCrashing) {
  std::mt19937 rng(7);
  int reported = 0;
  for (int round = 0; round < 2000; ++round) {
    int border = 0;
    TMesh t = random_grid_tmesh(rng, round % 4 != 0, border);
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    auto any_id = [&](int n) { return pick(n + 5) - 2; };  // a few out of range either way
    auto& side = t.patch_sides[pick(t.num_patches())][pick(4)];
    switch (pick(7)) {
      case 0:
        side[pick(static_cast<int>(side.size()))] = any_id(t.num_half_arcs());
        break;
      case 1:
        side.pop_back();
        break;
      case 2:
        t.arc_ends[pick(t.num_arcs())][pick(2)] = any_id(t.num_vertices());
        break;
      case 3:
        if (!t.arc_chain.empty()) t.arc_chain[pick(t.num_arcs())].pop_back();
        break;
      case 4:
        if (!t.patch_grid.empty()) {
          PatchGrid& g = t.patch_grid[pick(t.num_patches())];
          (pick(2) ? g.width : g.height) += pick(3) - 1;
        }
        break;
      case 5:
        if (!t.nonzero_paths.empty()) t.nonzero_paths[0].push_back(any_id(t.num_half_arcs()));
        break;
      default:
        if (!t.vertex_mesh_vertex.empty())
          t.vertex_mesh_vertex[pick(t.num_vertices())] = any_id(t.num_vertices());
    }
    if (bimdf::tmesh::find_tmesh_issue(t)) {
      ++reported;
      EXPECT_THROW(bimdf::tmesh::parse_tmesh_json(to_json(t), "edited.json"), InputError);
    } else {
      expect_same(bimdf::tmesh::parse_tmesh_json(to_json(t), "edited.json"), t);
    }
  }
  EXPECT_GT(reported, 1000);
}

}  // namespace

namespace {

// The unit square as one patch, without geometry; `arc2` replaces arc 2's object.
std::string square_json(const std::string& arc2 = R"({"ends": [2, 3], "target": 1})",
                        const std::string& head = R"("format": "bimdf-tmesh", "version": 1)") {
  return "{" + head + R"(,
 "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
 "arcs": [{"ends": [0, 1], "target": 1}, {"ends": [1, 2], "target": 1}, )" +
         arc2 + R"(, {"ends": [3, 0], "target": 1}],
 "patches": [{"sides": [[0], [2], [4], [6]]}]})";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(TMeshJson, SquareParses) {
  const TMesh t = bimdf::tmesh::parse_tmesh_json(square_json(), "t.json");
  EXPECT_EQ(t.num_vertices(), 4);
  EXPECT_EQ(t.num_arcs(), 4);
  EXPECT_EQ(t.num_patches(), 1);
  EXPECT_TRUE(t.arc_chain.empty());
  EXPECT_TRUE(t.patch_grid.empty());
  EXPECT_TRUE(t.nonzero_paths.empty());
}

TEST(TMeshJson, MalformedFilesGiveExactMessages) {
  const std::string head = R"("format": "bimdf-tmesh", "version": 1)";
  const std::string arc = R"({"ends": [2, 3], "target": 1})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"",
       "t.json:1: invalid JSON: syntax error while parsing value - unexpected end of input; "
       "expected '[', '{', or a literal"},
      {"[]", R"(t.json: /: expected a JSON object with "vertices", "arcs" and "patches")"},
      // Format and version.
      {square_json(arc, R"("format": "bimdf-tmesh", "version": 2)"),
       "t.json: /version: unsupported version 2, expected 1"},
      {square_json(arc, R"("format": "bimdf-problem", "version": 1)"),
       R"(t.json: /format: expected "bimdf-tmesh", got "bimdf-problem")"},
      {square_json(arc, R"("version": 1)"),
       R"(t.json: /format: missing: expected the format name "bimdf-tmesh")"},
      {square_json(arc, R"("format": "bimdf-tmesh")"),
       "t.json: /version: missing: expected the format version 1"},
      // Missing fields.
      {replaced(square_json(), R"(,
 "patches": [{"sides": [[0], [2], [4], [6]]}])",
                ""),
       "t.json: /patches: missing: expected an array of patches"},
      {square_json(R"({"ends": [2, 3]})"),
       "t.json: /arcs/2/target: missing: expected the arc's target length"},
      {square_json(R"({"target": 1})"),
       "t.json: /arcs/2/ends: missing: expected the arc's two vertices [tail, head]"},
      {replaced(square_json(), R"({"sides": [[0], [2], [4], [6]]})", "{}"),
       "t.json: /patches/0/sides: missing: expected the patch's four sides"},
      // Wrong types and shapes.
      {square_json(R"({"ends": [2, 3], "target": "1"})"),
       R"(t.json: /arcs/2/target: expected a target length (a number), got "1")"},
      {square_json(R"({"ends": [2], "target": 1})"),
       "t.json: /arcs/2/ends: expected the arc's two vertices [tail, head], got [2]"},
      {square_json(R"({"ends": [2, 3.0], "target": 1})"),
       "t.json: /arcs/2/ends/1: expected a vertex id (an integer), got 3.0"},
      {square_json(R"({"ends": [2, 4294967296], "target": 1})"),
       "t.json: /arcs/2/ends/1: expected a vertex id, got 4294967296 (out of range)"},
      {square_json(R"({"ends": [2, 3], "target": 1, "lenght": 2})"),
       R"(t.json: /arcs/2/lenght: unknown key "lenght" (expected one of: ends, target, chain, feature))"},
      {square_json(R"({"ends": [2, 3], "target": 1, "feature": true})"),
       "t.json: /arcs/2/feature: unexpected: arc 0 has no feature flag, so no arc may have one"},
      {square_json(R"({"ends": [2, 3], "target": 1, "chain": [3, 2]})"),
       "t.json: /arcs/2/chain: unexpected: arc 0 has no chain, so no arc may have one"},
      {replaced(square_json(), "[0, 1, 0]]", "[0, 1]]"),
       "t.json: /vertices/3: expected a position [x, y, z], got [0,1]"},
      {replaced(square_json(), "[1, 1, 0]", R"([1, 1, null])"),
       "t.json: /vertices/2/2: expected a coordinate (a number), got null"},
      {replaced(square_json(), "[[0], [2], [4], [6]]", "[[0], [2], [4]]"),
       "t.json: /patches/0/sides: expected four sides (arrays of half-arc ids), got [[0],[2],[4]]"},
      {replaced(square_json(), "[[0], [2], [4], [6]]", "[[0], [2], [4], 6]"),
       "t.json: /patches/0/sides/3: expected a side (an array of half-arc ids), got 6"},
      {replaced(square_json(), "[[0], [2], [4], [6]]", "[[0], [2], [4], [-6.5]]"),
       "t.json: /patches/0/sides/3/0: expected a half-arc id (an integer), got -6.5"},
      {replaced(square_json(), R"("patches")", R"("nonzero_paths": [[0], 2], "patches")"),
       "t.json: /nonzero_paths/1: expected a non-zero path (an array of half-arc ids), got 2"},
      {replaced(square_json(), R"("patches")", R"("nonzero_paths": {}, "patches")"),
       "t.json: /nonzero_paths: expected an array of non-zero paths (arrays of half-arc ids), got "
       "{}"},
      // Non-finite numbers: JSON has no NaN or infinity, so these fail in the parser.
      {square_json(R"({"ends": [2, 3], "target": NaN})"),
       "t.json:3: invalid JSON: syntax error while parsing value - invalid literal; last read: "
       "'\"target\": N'"},
      {square_json(R"({"ends": [2, 3], "target": 1e400})"),
       "t.json: invalid JSON: number overflow parsing '1e400'"},
      {square_json(R"({"ends": [2, 3], "target": "nan"})"),
       R"(t.json: /arcs/2/target: expected a target length (a number), got "nan")"},
      // Model rules, located in the file.
      {square_json(R"({"ends": [2, 3], "target": -1})"),
       "t.json: /arcs/2/target: arc 2: target -1 is negative, expected a length ≥ 0"},
      {replaced(square_json(), "[6]]", "[8]]"),
       "t.json: /patches/0/sides/3/0: patch 0, side 3: half-arc 8 is out of range [0, 8)"},
      {square_json(R"({"ends": [3, 2], "target": 1})"),
       "t.json: /patches/0/sides/2/0: patch 0, side 2: half-arc 4 starts at vertex 3, but side 1 "
       "ends at vertex 2"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(json_error(text), message) << text;
}

TEST(TMeshJson, GeometryErrorsGiveExactMessages) {
  using nlohmann::json;
  const json fixture = json::parse(to_json(t_junction_tmesh()));
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& j) { j["patches"][1].erase("grid"); },
       "t.json: /patches/1/grid: missing: patch 0 has a grid, so every patch needs one"},
      {[](json& j) { j["arcs"][3].erase("chain"); },
       "t.json: /arcs/3/chain: missing: arc 0 has a chain, so every arc needs one"},
      {[](json& j) { j["arcs"][3]["feature"] = 1; },
       "t.json: /arcs/3/feature: expected true or false, got 1"},
      {[](json& j) { j["patches"][0]["grid"]["width"] = "1"; },
       R"(t.json: /patches/0/grid/width: expected a width (an integer), got "1")"},
      {[](json& j) { j["patches"][0]["grid"].erase("vertices"); },
       "t.json: /patches/0/grid/vertices: missing: expected the grid's mesh vertices, row by row"},
      {[](json& j) { j["patches"][2]["grid"] = json::array(); },
       R"(t.json: /patches/2/grid: expected a grid like {"width": 2, "height": 1, "vertices": )"
       R"([0, 1, 2, 3, 4, 5]}, got [])"},
      {[](json& j) { j["vertex_mesh_vertex"] = 5; },
       "t.json: /vertex_mesh_vertex: expected an array of mesh vertex ids, one per vertex, got 5"},
      {[](json& j) { j["vertex_mesh_vertex"].erase(7); },
       "t.json: /vertex_mesh_vertex: vertex_mesh_vertex has 7 entries for 8 vertices, expected "
       "none or one per vertex"},
      {[](json& j) { j["patches"][0]["grid"]["vertices"][2] = 9; },
       "t.json: /patches/0/grid/vertices/2: patch 0, side 3: mesh vertex 1 along the side is 3 "
       "in its arcs' chains, but 9 in the grid at (0, 1)"},
      {[](json& j) {
         j["arcs"][7]["chain"] = {1, 5};
       },
       "t.json: /arcs/7/chain/1: arc 7: chain ends at mesh vertex 5, but its head, vertex 7, is "
       "mesh vertex 4"},
  };
  for (const auto& [edit, message] : cases) {
    json j = fixture;
    edit(j);
    EXPECT_EQ(json_error(j.dump()), message);
  }
}

TEST(TMeshJson, ErrorsCarryTheJsonPath) {
  try {
    bimdf::tmesh::parse_tmesh_json(square_json(R"({"ends": [2, 2], "target": 1})"), "t.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "t.json");
    EXPECT_EQ(e.location(), "/arcs/2/ends");
    EXPECT_EQ(e.description(),
              "arc 2: both ends are vertex 2 (an arc joins two distinct vertices)");
  }
}

TEST(TMeshJson, ReadsFilesAndNamesUnreadableOnes) {
  const std::string path = testing::TempDir() + "bimdf_tmesh_model_fixture.json";
  {
    std::ofstream out(path);
    bimdf::tmesh::write_tmesh_json(out, t_junction_tmesh());
  }
  expect_same(bimdf::tmesh::read_tmesh_json(path), t_junction_tmesh());
  std::remove(path.c_str());
  try {
    bimdf::tmesh::read_tmesh_json(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open file: No such file or directory");
    EXPECT_EQ(e.source(), path);
  }
}

}  // namespace
