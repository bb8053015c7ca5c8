// The T-mesh model: validation (every rule, exact messages), incidence, side lengths, and random
// edits of valid T-meshes that must be reported or still round-trip. The JSON form itself is
// tested in test_tmesh_json.cpp.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
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

std::string validation_error(const TMesh& t) {
  try {
    bimdf::tmesh::validate_tmesh(t, "fixture");
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
