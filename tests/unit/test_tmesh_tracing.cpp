// T-meshes traced from quad meshes (issue 21, from_quad_mesh.hpp): the motorcycle graph, its
// patches as rectangles of the input grid, arcs and their targets, non-zero paths, features
// and bad input. Rectangles and partitions are checked here independently of the library's
// own bookkeeping: from the patch grids and the mesh's quads alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "bimdf/error.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "test_helpers.hpp"
#include "tmesh/quad_mesh_topology.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh {
namespace {

using bimdf::testing::input_error_of;
using test::grid_mesh;

TraceOptions no_sharp() {
  TraceOptions o;
  o.sharp_angle_deg = 180;
  return o;
}

std::string temp_file(const std::string& name, const std::string& content) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto path = std::filesystem::temp_directory_path() /
                    ("bimdf_tracing_" + std::string(info->name()) + "_" + name);
  std::ofstream(path) << content;
  return path.string();
}

// Every property that does not depend on which mesh it is; returns a failure description
// (empty when all hold), so that loops over many meshes report the mesh.
std::string check_traced(const QuadMesh& mesh, const TracedTMesh& r, double density) {
  const TMesh& tm = r.tmesh;
  try {
    validate_tmesh(tm, "check");
  } catch (const InputError& e) {
    return std::string("validate_tmesh: ") + e.what();
  }
  // Patches: grids of mesh quads, oriented like the mesh, partitioning it.
  std::map<std::pair<int, int>, int> directed_edge_face;
  for (int f = 0; f < mesh.num_quads(); ++f)
    for (int k = 0; k < 4; ++k)
      directed_edge_face[{mesh.quads[f][k], mesh.quads[f][(k + 1) % 4]}] = f;
  std::vector<int> face_patch(mesh.num_quads(), -1);
  std::set<std::pair<int, int>> arc_edges;
  for (const auto& chain : tm.arc_chain)
    for (size_t i = 0; i + 1 < chain.size(); ++i)
      arc_edges.insert({std::min(chain[i], chain[i + 1]), std::max(chain[i], chain[i + 1])});
  auto on_arc = [&](int a, int b) { return arc_edges.count({std::min(a, b), std::max(a, b)}) > 0; };
  int area = 0;
  for (int p = 0; p < tm.num_patches(); ++p) {
    const PatchGrid& g = tm.patch_grid[p];
    if (g.width < 1 || g.height < 1) return "patch " + std::to_string(p) + ": empty grid";
    std::set<int> distinct(g.vertices.begin(), g.vertices.end());
    if (distinct.size() != g.vertices.size())
      return "patch " + std::to_string(p) + ": repeated vertex";
    for (int j = 0; j < g.height; ++j)
      for (int i = 0; i < g.width; ++i) {
        const std::array<int, 4> cell{g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1),
                                      g.at(i, j + 1)};
        const auto it = directed_edge_face.find({cell[0], cell[1]});
        if (it == directed_edge_face.end())
          return "patch " + std::to_string(p) + ": cell not a quad";
        const auto& q = mesh.quads[it->second];
        const int k0 = static_cast<int>(std::find(q.begin(), q.end(), cell[0]) - q.begin());
        for (int k = 0; k < 4; ++k)
          if (q[(k0 + k) % 4] != cell[k]) return "patch " + std::to_string(p) + ": cell not a quad";
        if (face_patch[it->second] >= 0)
          return "quad " + std::to_string(it->second) + " in two patches";
        face_patch[it->second] = p;
        ++area;
        // Edges inside the rectangle are on no arc; its border edges are.
        if (on_arc(cell[0], cell[1]) != (j == 0) ||
            on_arc(cell[1], cell[2]) != (i == g.width - 1) ||
            on_arc(cell[2], cell[3]) != (j == g.height - 1) || on_arc(cell[3], cell[0]) != (i == 0))
          return "patch " + std::to_string(p) + ": arcs do not follow the rectangle's border";
      }
  }
  if (area != mesh.num_quads()) return "patches cover " + std::to_string(area) + " quads";
  // Arcs: targets, and only their ends are T-mesh vertices.
  std::set<int> tverts(tm.vertex_mesh_vertex.begin(), tm.vertex_mesh_vertex.end());
  for (int a = 0; a < tm.num_arcs(); ++a) {
    const auto& chain = tm.arc_chain[a];
    if (tm.arc_target[a] != density * double(chain.size() - 1))
      return "arc " + std::to_string(a) + ": target " + std::to_string(tm.arc_target[a]);
    for (size_t i = 1; i + 1 < chain.size(); ++i)
      if (tverts.count(chain[i])) return "arc " + std::to_string(a) + " passes a T-mesh vertex";
  }
  for (int s : r.seeds)
    if (!tverts.count(s)) return "seed " + std::to_string(s) + " is no T-mesh vertex";
  // Traces: the simple one is a prefix of the extended one; the M1 paths follow them.
  if (r.trace_vertices.size() != size_t(r.traces) ||
      r.extended_trace_vertices.size() != size_t(r.traces))
    return "trace counts differ";
  for (int t = 0; t < r.traces; ++t) {
    const auto& s = r.trace_vertices[t];
    const auto& x = r.extended_trace_vertices[t];
    if (s.size() > x.size() || !std::equal(s.begin(), s.end(), x.begin()))
      return "trace " + std::to_string(t) + " is not a prefix of its extension";
  }
  if (tm.nonzero_paths.size() != r.nonzero_path_trace.size()) return "path/trace counts differ";
  size_t half_loops = 0;
  for (size_t k = 0; k < tm.nonzero_paths.size(); ++k) {
    const auto& path = tm.nonzero_paths[k];
    const int from = r.nonzero_path_trace[k];
    if (from == -2) {  // a border or feature curve piece: connected, on curves, seed to seed
      const TMeshIncidence inc = validate_tmesh(tm);
      const auto is_seed = [&](int tv) {
        return std::count(r.seeds.begin(), r.seeds.end(), tm.vertex_mesh_vertex[tv]) > 0;
      };
      if (path.empty() || !is_seed(tm.half_arc_tail(path[0])))
        return "curve path " + std::to_string(k) + " does not start at a seed";
      for (size_t i = 0; i < path.size(); ++i) {
        const int a = TMesh::arc_of(path[i]);
        if (!tm.arc_feature[a] && !inc.is_border(2 * a) && !inc.is_border(2 * a + 1))
          return "curve path " + std::to_string(k) + " leaves the border and features";
        if (i > 0 && tm.half_arc_tail(path[i]) != tm.half_arc_head(path[i - 1]))
          return "curve path " + std::to_string(k) + " is not connected";
      }
      continue;
    }
    if (from < 0 && half_loops >= r.cylinder_half_loops.size()) return "too many half-loop paths";
    const auto& trace = from >= 0 ? r.trace_vertices[from] : r.cylinder_half_loops[half_loops++];
    if (path.empty()) return "empty non-zero path";
    if (tm.vertex_mesh_vertex[tm.half_arc_tail(path[0])] != trace[0])
      return "path " + std::to_string(k) + " does not start at its seed";
    std::vector<int> walked{trace[0]};
    for (size_t i = 0; i < path.size(); ++i) {
      if (i > 0 && tm.half_arc_tail(path[i]) != tm.half_arc_head(path[i - 1]))
        return "path " + std::to_string(k) + " is not connected";
      std::vector<int> chain = tm.arc_chain[TMesh::arc_of(path[i])];
      if (path[i] & 1) std::reverse(chain.begin(), chain.end());
      walked.insert(walked.end(), chain.begin() + 1, chain.end());
    }
    if (walked.size() < trace.size() || !std::equal(trace.begin(), trace.end(), walked.begin()))
      return "path " + std::to_string(k) + " does not follow its trace";
    if (walked.size() - trace.size() >= tm.arc_chain[TMesh::arc_of(path.back())].size() - 1)
      return "path " + std::to_string(k) + " runs past its trace";
  }
  if (half_loops != r.cylinder_half_loops.size()) return "a half-loop has no path";
  for (int t = 0; t < r.traces; ++t)
    if (r.trace_vertices[t].size() >= 2 &&
        std::find(r.nonzero_path_trace.begin(), r.nonzero_path_trace.end(), t) ==
            r.nonzero_path_trace.end())
      return "trace " + std::to_string(t) + " has no non-zero path";
  return {};
}

int patch_with_corner(const TMesh& tm, int mesh_vertex) {
  for (int p = 0; p < tm.num_patches(); ++p)
    if (tm.patch_grid[p].at(0, 0) == mesh_vertex) return p;
  return -1;
}

TEST(TraceTMesh, RegularGridIsOnePatch) {
  const QuadMesh mesh = grid_mesh(5, 3);
  TraceOptions o;
  o.density = 1.5;
  const TracedTMesh r = trace_tmesh(mesh, o, "grid");
  EXPECT_EQ(check_traced(mesh, r, 1.5), "");
  const TMesh& tm = r.tmesh;
  ASSERT_EQ(tm.num_patches(), 1);
  EXPECT_EQ(tm.patch_grid[0].width, 5);
  EXPECT_EQ(tm.patch_grid[0].height, 3);
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 5; ++i) EXPECT_EQ(tm.patch_grid[0].at(i, j), 6 * j + i);
  EXPECT_EQ(r.seeds, (std::vector<int>{0, 5, 18, 23}));  // the corners, border valence 2
  EXPECT_EQ(r.traces, 0);
  EXPECT_EQ(tm.num_arcs(), 4);
  EXPECT_EQ(tm.num_vertices(), 4);
  // No trace, but each border side between two corners is a curve path.
  ASSERT_EQ(tm.nonzero_paths.size(), 4u);
  for (const auto& path : tm.nonzero_paths) EXPECT_EQ(path.size(), 1u);
  std::multiset<double> targets(tm.arc_target.begin(), tm.arc_target.end());
  EXPECT_EQ(targets, (std::multiset<double>{4.5, 4.5, 7.5, 7.5}));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(tm.patch_sides[0][k].size(), 1u);
}

TEST(TraceTMesh, SubdividedCubeHasSixPatches) {
  for (int level = 1; level <= 4; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const QuadMesh mesh = test::subdivided_cube(level);
    // Level 1's dihedral angles are 41°–43°, all sharp at the default 35° (see below).
    std::vector<TraceOptions> options{no_sharp()};
    if (level > 1) options.push_back(TraceOptions{});
    for (const TraceOptions& o : options) {
      const TracedTMesh r = trace_tmesh(mesh, o, "cube");
      EXPECT_EQ(check_traced(mesh, r, 1), "");
      EXPECT_EQ(r.tmesh.num_patches(), 6);
      EXPECT_EQ(r.tmesh.num_arcs(), 12);
      EXPECT_EQ(r.tmesh.num_vertices(), 8);
      EXPECT_EQ(r.seeds, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
      const detail::QuadMeshTopology topo(mesh, "cube");
      for (int s : r.seeds) EXPECT_EQ(topo.valence(s), 3);
      const int n = 1 << level;
      for (int p = 0; p < 6; ++p) {
        EXPECT_EQ(r.tmesh.patch_grid[p].width, n);
        EXPECT_EQ(r.tmesh.patch_grid[p].height, n);
      }
      for (double t : r.tmesh.arc_target) EXPECT_EQ(t, n);
    }
    const TracedTMesh r = trace_tmesh(mesh, no_sharp(), "cube");
    EXPECT_TRUE(r.feature_edges.empty());
    EXPECT_EQ(r.traces, 24);  // three per corner; they meet head-on along each cube edge
    EXPECT_EQ(r.tmesh.nonzero_paths.size(), 24u);
  }
}

TEST(TraceTMesh, CubeLevelOneIsAllFeatureAtTheDefaultAngle) {
  const QuadMesh mesh = test::subdivided_cube(1);
  const TracedTMesh r = trace_tmesh(mesh, {}, "cube");
  EXPECT_EQ(check_traced(mesh, r, 1), "");
  EXPECT_EQ(r.feature_edges.size(), 48u);
  EXPECT_EQ(r.seeds.size(), 26u);
  EXPECT_EQ(r.traces, 0);
  EXPECT_EQ(r.tmesh.num_patches(), 24);
  TraceOptions o;
  o.sharp_angle_deg = 45;
  EXPECT_EQ(trace_tmesh(mesh, o, "cube").tmesh.num_patches(), 6);
}

TEST(TraceTMesh, ThinStripBecomesAOneQuadWidePatch) {
  const QuadMesh mesh = test::thin_strip_mesh();
  const TracedTMesh r = trace_tmesh(mesh, {}, "strip");
  ASSERT_EQ(check_traced(mesh, r, 1), "");
  const int a = test::thin_strip_vertex(3, 3), b = test::thin_strip_vertex(7, 4);
  EXPECT_TRUE(std::find(r.seeds.begin(), r.seeds.end(), a) != r.seeds.end());
  EXPECT_TRUE(std::find(r.seeds.begin(), r.seeds.end(), b) != r.seeds.end());
  EXPECT_EQ(r.traces, 4);  // two from each reflex corner; the convex corners emit none
  const int p = patch_with_corner(r.tmesh, a);
  ASSERT_GE(p, 0);
  const PatchGrid& g = r.tmesh.patch_grid[p];
  EXPECT_EQ(g.width, 4);
  EXPECT_EQ(g.height, 1);
  EXPECT_EQ(g.at(4, 1), test::thin_strip_vertex(7, 4));
  int thin = 0;
  for (const auto& grid : r.tmesh.patch_grid) thin += std::min(grid.width, grid.height) == 1;
  EXPECT_EQ(thin, 1);
}

TEST(TraceTMesh, ClosedGridWithoutSeedsIsRefused) {
  const std::string expected =
      "torus: the mesh has no irregular vertex, border or feature: its grid lines close on "
      "themselves, so there is no layout to quantize";
  for (int shift : {0, 1, 5, 7, -3}) {
    SCOPED_TRACE("shift " + std::to_string(shift));
    const QuadMesh torus = test::torus_mesh(16, 12, shift);
    EXPECT_EQ(input_error_of([&] { trace_tmesh(torus, {}, "torus"); }), expected);
  }
}

TEST(TraceTMesh, CylinderIsCutInTwo) {
  QuadMesh tube = test::torus_mesh(12, 12);
  tube.quads.resize(12 * 11);  // drop the last ring: an open cylinder, border valence 3
  const TracedTMesh r = trace_tmesh(tube, {}, "tube");
  ASSERT_EQ(check_traced(tube, r, 1), "");
  EXPECT_TRUE(r.seeds.empty());
  EXPECT_EQ(r.cylinder_cuts, 2);
  EXPECT_EQ(r.traces, 2);
  ASSERT_EQ(r.tmesh.num_patches(), 2);
  for (const auto& g : r.tmesh.patch_grid)
    EXPECT_EQ(std::make_pair(std::min(g.width, g.height), std::max(g.width, g.height)),
              std::make_pair(6, 11));
  // The cuts start at vertex 0 and half-way round the same border curve, and cross the tube.
  EXPECT_EQ(r.trace_vertices[0].front(), 0);
  EXPECT_EQ(r.trace_vertices[0].size(), 12u);
  EXPECT_EQ(r.trace_vertices[1].size(), 12u);
  ASSERT_EQ(r.cylinder_half_loops.size(), 1u);
  EXPECT_EQ(r.cylinder_half_loops[0].size(), 7u);
  EXPECT_EQ(r.nonzero_path_trace, (std::vector<int>{0, 1, -1}));
  EXPECT_EQ(r.tmesh.num_arcs(), 6);
}

TEST(TraceTMesh, RingCrossedOnceIsCutAgain) {
  // An open 12 × 11 tube with one feature line along it (column 0): a single region whose
  // rectangle is glued to itself along that line; it is cut again half-way round.
  QuadMesh tube = test::torus_mesh(12, 12);
  tube.quads.resize(12 * 11);
  TraceOptions o;
  for (int y = 0; y < 11; ++y) o.feature_edges.push_back({12 * y, 12 * (y + 1)});
  const TracedTMesh r = trace_tmesh(tube, o, "tube");
  ASSERT_EQ(check_traced(tube, r, 1), "");
  EXPECT_EQ(r.feature_corners, (std::vector<int>{0, 132}));
  EXPECT_EQ(r.cylinder_cuts, 1);
  EXPECT_TRUE(r.cylinder_half_loops.empty());
  ASSERT_EQ(r.tmesh.num_patches(), 2);
  for (const auto& g : r.tmesh.patch_grid)
    EXPECT_EQ(std::make_pair(std::min(g.width, g.height), std::max(g.width, g.height)),
              std::make_pair(6, 11));
  ASSERT_EQ(r.trace_vertices.size(), 1u);
  EXPECT_EQ(r.trace_vertices[0].size(), 12u);
  EXPECT_EQ(r.trace_vertices[0].front() % 12, 6);
}

TEST(TraceTMesh, TubesBetweenFeatureLoopsAreCut) {
  // Rows y = 0 and y = 6 of a 16 × 12 torus given as features: two annuli, four rectangles.
  const QuadMesh torus = test::torus_mesh(16, 12, 0);
  TraceOptions o;
  for (int y : {0, 6})
    for (int x = 0; x < 16; ++x) o.feature_edges.push_back({16 * y + x, 16 * y + (x + 1) % 16});
  const TracedTMesh r = trace_tmesh(torus, o, "torus");
  ASSERT_EQ(check_traced(torus, r, 1), "");
  EXPECT_EQ(r.cylinder_cuts, 4);
  EXPECT_EQ(r.tmesh.num_patches(), 4);
  for (const auto& g : r.tmesh.patch_grid) EXPECT_EQ(g.width * g.height, 8 * 6);
  // A torus, plain or helical, cut by one feature loop (row 0): one annulus whose two borders
  // are the loop's two sides. The closed line half-way across is cut first: two annuli with
  // distinct borders, then four rectangles.
  for (auto [w, h, shift] : {std::array<int, 3>{16, 12, 0}, {16, 12, 5}, {15, 11, 7}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " shift " + std::to_string(shift));
    const QuadMesh mesh = test::torus_mesh(w, h, shift);
    TraceOptions one = no_sharp();  // the shear of a helix sharpens the inner equator
    for (int x = 0; x < w; ++x) one.feature_edges.push_back({x, (x + 1) % w});
    const TracedTMesh r1 = trace_tmesh(mesh, one, "helix");
    ASSERT_EQ(check_traced(mesh, r1, 1), "");
    EXPECT_EQ(r1.cylinder_cuts, 4);
    EXPECT_EQ(r1.tmesh.num_patches(), 4);
    EXPECT_EQ(r1.cylinder_half_loops.size(), 2u);
  }
}

TEST(TraceTMesh, ClosedComponentBesideAnOpenOneIsRefused) {
  QuadMesh mesh = grid_mesh(2, 2);
  const QuadMesh torus = test::torus_mesh(12, 12, 3);
  const int offset = mesh.num_vertices();
  for (const auto& p : torus.vertices) mesh.vertices.push_back(p);
  for (auto q : torus.quads) {
    for (int& v : q) v += offset;
    mesh.quads.push_back(q);
  }
  EXPECT_EQ(input_error_of([&] { trace_tmesh(mesh, {}, "two"); }),
            "two: the 144 quads connected to quad 4 across uncut edges have no irregular vertex, "
            "border or feature: its grid lines close on themselves, so there is no layout to "
            "quantize");
}

TEST(TraceTMesh, RandomMeshes) {
  const int count = bimdf::testing::scaled(240);
  int with_traces = 0, not_planar = 0, thin = 0, with_cuts = 0;
  for (int seed = 0; seed < count; ++seed) {
    std::string what;
    const QuadMesh mesh = test::random_quad_mesh(seed, &what, /*with_tubes=*/true);
    SCOPED_TRACE(what);
    TraceOptions o;
    o.density = 0.5 + seed % 3;
    TracedTMesh r;
    try {
      r = trace_tmesh(mesh, o, "random");
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ASSERT_EQ(check_traced(mesh, r, o.density), "");
    const TracedTMesh again = trace_tmesh(mesh, o, "random");
    EXPECT_EQ(again.tmesh.arc_chain, r.tmesh.arc_chain);
    EXPECT_EQ(again.tmesh.patch_sides, r.tmesh.patch_sides);
    EXPECT_EQ(again.tmesh.nonzero_paths, r.tmesh.nonzero_paths);
    int on_traces = 0;
    for (const auto& t : r.trace_vertices) on_traces += static_cast<int>(t.size()) - 1;
    EXPECT_GE(r.extended_trace_edges, on_traces);
    with_traces += r.traces > 0;
    not_planar += what.find("gonal") != std::string::npos;
    with_cuts += r.cylinder_cuts > 0;
    for (const auto& g : r.tmesh.patch_grid) thin += std::min(g.width, g.height) == 1;
  }
  // The fixtures exercise what they are meant to.
  EXPECT_GT(with_traces, count / 2);
  EXPECT_GT(not_planar, count / 8);
  EXPECT_GT(thin, 0);
  if (count >= 200) {
    EXPECT_GT(with_cuts, 0);
  }
}

TEST(TraceTMesh, SharpFold) {
  const QuadMesh mesh = test::folded_grid(6, 4, 3, 60);
  const TracedTMesh r = trace_tmesh(mesh, {}, "fold");
  ASSERT_EQ(check_traced(mesh, r, 1), "");
  std::set<std::pair<int, int>> features;
  for (auto [a, b] : r.feature_edges) features.insert({std::min(a, b), std::max(a, b)});
  EXPECT_EQ(features, (std::set<std::pair<int, int>>{{3, 10}, {10, 17}, {17, 24}, {24, 31}}));
  EXPECT_EQ(r.feature_corners, (std::vector<int>{3, 31}));
  EXPECT_EQ(r.traces, 0);
  EXPECT_EQ(r.tmesh.num_patches(), 2);
  EXPECT_EQ(r.tmesh.num_arcs(), 7);
  int feature_arcs = 0;
  for (int a = 0; a < r.tmesh.num_arcs(); ++a)
    if (r.tmesh.arc_feature[a]) {
      ++feature_arcs;
      EXPECT_EQ(r.tmesh.arc_chain[a].size(), 5u);
    }
  EXPECT_EQ(feature_arcs, 1);
  // Below the threshold: no feature, one patch.
  const TracedTMesh flat = trace_tmesh(test::folded_grid(6, 4, 3, 30), {}, "fold");
  EXPECT_TRUE(flat.feature_edges.empty());
  EXPECT_EQ(flat.tmesh.num_patches(), 1);
  TraceOptions lower;
  lower.sharp_angle_deg = 20;
  EXPECT_EQ(trace_tmesh(test::folded_grid(6, 4, 3, 30), lower, "fold").tmesh.num_patches(), 2);
}

TEST(TraceTMesh, FeatureFile) {
  const QuadMesh mesh = grid_mesh(6, 4);
  // Quad 6y + 3, edge 3: from its corner 3 (3, y+1) to corner 0 (3, y).
  const std::string path = temp_file("fold.feature", "4\n3,3\n9,3\n15,3\n21,3\n");
  const auto given = read_quad_feature_file(path, mesh);
  EXPECT_EQ(given, (std::vector<std::array<int, 2>>{{10, 3}, {17, 10}, {24, 17}, {31, 24}}));
  TraceOptions o;
  o.feature_edges = given;
  const TracedTMesh r = trace_tmesh(mesh, o, "grid");
  ASSERT_EQ(check_traced(mesh, r, 1), "");
  EXPECT_EQ(r.feature_edges.size(), 4u);
  EXPECT_EQ(r.tmesh.num_patches(), 2);
  EXPECT_EQ(r.tmesh.num_arcs(), 7);
}

// write_quad_feature_file writes what read_quad_feature_file reads: per edge its lowest quad.
TEST(TraceTMesh, FeatureFileWrittenReadsBack) {
  const QuadMesh mesh = grid_mesh(6, 4);
  std::ostringstream out;
  write_quad_feature_file(out, mesh, {{10, 3}, {17, 10}, {24, 17}, {31, 24}});
  // Edge (3, 10) is quad 2's edge 1 (corner 1 (3, 0) to corner 2 (3, 1)), and so on up.
  EXPECT_EQ(out.str(), "4\n2,1\n8,1\n14,1\n20,1\n");
  const auto back = read_quad_feature_file(temp_file("written.feature", out.str()), mesh);
  EXPECT_EQ(back, (std::vector<std::array<int, 2>>{{3, 10}, {10, 17}, {17, 24}, {24, 31}}));
  std::ostringstream none;
  write_quad_feature_file(none, mesh, {});
  EXPECT_EQ(none.str(), "0\n");
  try {
    std::ostringstream bad;
    write_quad_feature_file(bad, mesh, {{0, 1}, {0, 8}});
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "write_quad_feature_file: vertices 0 and 8 are not an edge of the mesh");
  }
}

TEST(TraceTMesh, FeatureCurveEndsAndTurns) {
  const QuadMesh mesh = grid_mesh(6, 6);
  auto v = [](int x, int y) { return 7 * y + x; };
  // From the border at (3, 0) up to (3, 2), then right to (5, 2): an end on the border, a
  // turn at (3, 2), an end inside at (5, 2).
  TraceOptions o;
  o.feature_edges = {
      {v(3, 0), v(3, 1)}, {v(3, 1), v(3, 2)}, {v(3, 2), v(4, 2)}, {v(4, 2), v(5, 2)}};
  const TracedTMesh r = trace_tmesh(mesh, o, "grid");
  ASSERT_EQ(check_traced(mesh, r, 1), "");
  EXPECT_EQ(r.feature_corners, (std::vector<int>{v(3, 0), v(3, 2), v(5, 2)}));
  // The turn emits left and up, the inner end right, up and down.
  EXPECT_EQ(r.traces, 5);
  int feature_arcs = 0;
  for (uint8_t f : r.tmesh.arc_feature) feature_arcs += f;
  EXPECT_GE(feature_arcs, 2);
  for (const auto& g : r.tmesh.patch_grid) EXPECT_GE(std::min(g.width, g.height), 1);
}

TEST(TraceTMesh, FeatureFileErrors) {
  const QuadMesh mesh = grid_mesh(6, 4);
  auto message = [&](const std::string& name, const std::string& content) {
    const std::string path = temp_file(name, content);
    const std::string m = input_error_of([&] { read_quad_feature_file(path, mesh); });
    return m.substr(m.find(name));
  };
  EXPECT_EQ(message("a.feature", "2\n3,3\n99,0\n"),
            "a.feature:3: feature edge 1 (face,edge): face 99 edge 0 is out of range (quads "
            "0..23, edges 0..3)");
  EXPECT_EQ(message("b.feature", "1\n3;3\n"),
            "b.feature:2: feature edge 0 (face,edge): expected two integers separated by a "
            "comma, found '3;3'");
  EXPECT_EQ(message("c.feature", "1\n3,4\n"),
            "c.feature:2: feature edge 0 (face,edge): face 3 edge 4 is out of range (quads "
            "0..23, edges 0..3)");
  EXPECT_EQ(message("d.feature", "1\n3,3\n4,3\n"),
            "d.feature:3: unexpected '4,3' after the last feature edge");
  EXPECT_EQ(message("e.feature", "-1\n"),
            "e.feature:1: the feature edge count -1 is out of range (expected 0..96)");
  TraceOptions o;
  o.feature_edges = {{0, 1}, {0, 8}};
  EXPECT_EQ(input_error_of([&] { trace_tmesh(mesh, o, "grid.obj"); }),
            "grid.obj: feature edge 1 (0, 8) is not an edge of the mesh");
}

TEST(TraceTMesh, BadMeshes) {
  auto message = [](const QuadMesh& m) {
    return input_error_of([&] { trace_tmesh(m, {}, "bad.obj"); });
  };
  EXPECT_EQ(message(QuadMesh{}), "bad.obj: the mesh has no quads");

  QuadMesh flipped = grid_mesh(2, 2);
  flipped.quads[3] = {flipped.quads[3][3], flipped.quads[3][2], flipped.quads[3][1],
                      flipped.quads[3][0]};
  EXPECT_EQ(message(flipped),
            "bad.obj: quads 1 and 3 both run from vertex 5 to vertex 4 along their shared edge: "
            "the mesh is not consistently oriented");

  QuadMesh fin = grid_mesh(2, 1);  // a third quad on edge (1, 4), sticking up
  fin.vertices.push_back({1, 0, 1});
  fin.vertices.push_back({1, 1, 1});
  fin.quads.push_back({1, 4, 7, 6});
  EXPECT_EQ(message(fin),
            "bad.obj: edge (1, 4) is shared by 3 quads (0, 1, 2): the mesh is not manifold");

  QuadMesh bowtie = grid_mesh(1, 1);  // a second quad touching the first at vertex 3 only
  for (auto p : std::vector<std::array<double, 3>>{{2, 1, 0}, {2, 2, 0}, {1, 2, 0}})
    bowtie.vertices.push_back(p);
  bowtie.quads.push_back({3, 4, 5, 6});
  EXPECT_EQ(message(bowtie),
            "bad.obj: the quads around vertex 3 do not form a single fan: the mesh is not "
            "manifold there");

  QuadMesh degenerate = grid_mesh(2, 1);
  degenerate.quads[1][2] = degenerate.quads[1][0];
  EXPECT_EQ(message(degenerate), "bad.obj: quad 1 repeats vertex 1 (a degenerate quad)");

  QuadMesh out_of_range = grid_mesh(1, 1);
  out_of_range.quads[0][1] = 9;
  EXPECT_EQ(message(out_of_range),
            "bad.obj: quad 0: vertex index 9 is out of range (the mesh has 4 vertices)");
}

TEST(TraceTMesh, UnusedVerticesAreIgnored) {
  QuadMesh mesh = grid_mesh(3, 3);
  mesh.vertices.push_back({9, 9, 9});
  const TracedTMesh r = trace_tmesh(mesh, {}, "grid");
  EXPECT_EQ(check_traced(mesh, r, 1), "");
  EXPECT_EQ(r.tmesh.num_patches(), 1);
  EXPECT_EQ(r.seeds.size(), 4u);
}

TEST(QuadMeshTopology, RingsAndStraightOn) {
  const QuadMesh mesh = grid_mesh(2, 2);
  const detail::QuadMeshTopology topo(mesh, "grid");
  EXPECT_EQ(topo.num_edges(), 12);
  EXPECT_EQ(topo.valence(4), 4);
  EXPECT_FALSE(topo.is_border_vertex(4));
  EXPECT_EQ(topo.valence(1), 3);
  EXPECT_TRUE(topo.is_border_vertex(1));
  EXPECT_TRUE(topo.is_regular(1));
  EXPECT_FALSE(topo.is_regular(0));
  // Counter-clockwise around the centre: 5, 7, 3, 1 (or a rotation of it).
  std::vector<int> around;
  for (int e : topo.vertex_edges(4)) around.push_back(topo.other_vertex(e, 4));
  const std::vector<int> ccw{5, 7, 3, 1};
  const auto start = std::find(ccw.begin(), ccw.end(), around[0]);
  ASSERT_NE(start, ccw.end());
  std::vector<int> rotated(start, ccw.end());
  rotated.insert(rotated.end(), ccw.begin(), start);
  EXPECT_EQ(around, rotated);
  EXPECT_EQ(topo.straight_on(4, topo.find_edge(4, 5)), topo.find_edge(4, 3));
  EXPECT_EQ(topo.straight_on(1, topo.find_edge(1, 0)), topo.find_edge(1, 2));
  EXPECT_EQ(topo.straight_on(1, topo.find_edge(1, 4)), -1);
  EXPECT_EQ(topo.straight_on(0, topo.find_edge(0, 1)), -1);
  // A border vertex's ring starts with its outgoing border edge: 1 → 2 leaves quad 1's fan.
  EXPECT_EQ(topo.other_vertex(topo.vertex_edges(1)[0], 1), 2);
  EXPECT_EQ(topo.find_edge(0, 4), -1);
}

}  // namespace
}  // namespace bimdf::tmesh
