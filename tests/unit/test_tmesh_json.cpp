// The JSON form of T-meshes (bimdf/tmesh/tmesh.hpp): the documented layout, exact round trips of
// fixed and random grid T-meshes, exact messages for malformed files and broken rules located
// by their JSON path, and reading files.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bimdf/error.hpp"
#include "bimdf/tmesh/tmesh.hpp"
#include "tmesh_test_support.hpp"

namespace {

using bimdf::InputError;
using bimdf::tmesh::PatchGrid;
using bimdf::tmesh::TMesh;
using bimdf::tmesh::TMeshIncidence;
using bimdf::tmesh::testsupport::expect_same;
using bimdf::tmesh::testsupport::random_grid_tmesh;
using bimdf::tmesh::testsupport::t_junction_tmesh;
using bimdf::tmesh::testsupport::to_json;

std::string json_error(const std::string& text) {
  try {
    bimdf::tmesh::parse_tmesh_json(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

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
