// The standalone remesher's input stage (src/layout/surface.cpp, src/mesh/polygon_formats.cpp,
// src/layout/features.cpp): formats, repairs, refusals with their messages, topology counts,
// sharp features.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bimdf/error.hpp"
#include "bimdf/layout/features.hpp"
#include "bimdf/layout/surface.hpp"
#include "layout/feature_flags.hpp"
#include "layout/surface_topology.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

PolygonMesh as_polygons(const TriangleMesh& m) {
  PolygonMesh p;
  p.vertices = m.vertices;
  for (const auto& f : m.faces) p.faces.push_back({f[0], f[1], f[2]});
  return p;
}

std::string message_of(const PolygonMesh& m) {
  try {
    layout::prepare_surface(m, "in.obj");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LayoutSurface, TopologyOfClosedOpenAndSeveralPieces) {
  const auto info = [](const TriangleMesh& m) {
    return layout::describe_surface(layout::prepare_surface(as_polygons(m), "m").mesh);
  };
  const layout::SurfaceInfo sphere = info(test::icosphere(3));
  EXPECT_EQ(sphere.components, 1);
  EXPECT_EQ(sphere.euler_characteristic, 2);
  EXPECT_EQ(sphere.border_loops, 0);
  EXPECT_EQ(sphere.component_genus, std::vector<int>{0});
  EXPECT_NEAR(sphere.area, 4 * M_PI, 0.1);

  const layout::SurfaceInfo torus = info(test::torus(3, 1, 24, 12));
  EXPECT_EQ(torus.euler_characteristic, 0);
  EXPECT_EQ(torus.component_genus, std::vector<int>{1});

  const layout::SurfaceInfo cylinder = info(test::cylinder(2, 16, 4));
  EXPECT_EQ(cylinder.border_loops, 2);
  EXPECT_EQ(cylinder.component_genus, std::vector<int>{0});
  EXPECT_EQ(cylinder.component_border_loops, std::vector<int>{2});

  const TriangleMesh three = test::combine(
      test::combine(test::icosphere(1), test::torus(3, 1, 12, 8), 5), test::square(1, 3), 12);
  const layout::SurfaceInfo pieces = info(three);
  EXPECT_EQ(pieces.components, 3);
  EXPECT_EQ(pieces.euler_characteristic, 2 + 0 + 1);
  EXPECT_EQ(pieces.component_genus, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(pieces.component_border_loops, (std::vector<int>{0, 0, 1}));
}

TEST(LayoutSurface, RepairsPolygonsOrientationUnusedAndPinchedVertices) {
  // Two squares sharing an edge, the second written clockwise, plus an unused vertex.
  PolygonMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}, {9, 9, 9}};
  m.faces = {{0, 1, 2, 3}, {1, 2, 5, 4}};
  const layout::Surface s = layout::prepare_surface(m, "m");
  EXPECT_EQ(s.mesh.num_faces(), 4);
  EXPECT_EQ(s.repairs.triangulated_polygons, 2);
  EXPECT_EQ(s.repairs.flipped_faces, 2);
  EXPECT_EQ(s.repairs.unreferenced_vertices, 1);
  EXPECT_EQ(s.mesh.num_vertices(), 6);
  EXPECT_EQ(s.input_face, (std::vector<int>{0, 0, 1, 1}));
  // Every triangle now faces +z.
  for (const auto& f : s.mesh.faces) {
    const auto& a = s.mesh.vertices[f[0]];
    const auto& b = s.mesh.vertices[f[1]];
    const auto& c = s.mesh.vertices[f[2]];
    EXPECT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0);
  }
  EXPECT_EQ(layout::describe_surface(s.mesh).component_genus, std::vector<int>{0});

  // Two triangles touching at one vertex: the vertex is split, one copy per fan.
  PolygonMesh bow;
  bow.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bow.faces = {{0, 1, 2}, {0, 3, 4}};
  const layout::Surface b = layout::prepare_surface(bow, "bow");
  EXPECT_EQ(b.repairs.split_vertices, 1);
  EXPECT_EQ(b.mesh.num_vertices(), 6);
  EXPECT_EQ(b.input_vertex[5], 0);
  EXPECT_EQ(layout::describe_surface(b.mesh).components, 2);
}

TEST(LayoutSurface, RefusesWhatCannotBeRepaired) {
  PolygonMesh empty;
  empty.vertices = {{0, 0, 0}};
  EXPECT_EQ(message_of(empty),
            "in.obj: the mesh has no faces, expected a triangle or polygon mesh");

  PolygonMesh fin;  // three triangles on one edge
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(message_of(fin),
            "in.obj: the mesh edge between vertices 0 and 1 has 3 faces, expected at most 2 "
            "(non-manifold)");

  PolygonMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  flat.faces = {{0, 1, 3}, {0, 1, 2}};
  flat.face_line = {5, 6};
  EXPECT_EQ(message_of(flat),
            "in.obj: face 1 (line 6) has zero area (its vertices are collinear), expected a "
            "proper triangle: remove or merge it first");
  flat.vertices[2] = flat.vertices[1];
  EXPECT_EQ(message_of(flat),
            "in.obj: face 1 (line 6) has zero area (two of its vertices are at the same "
            "position), expected a proper triangle: remove or merge it first");

  // A Möbius strip: a band of 5 quads glued with a half twist.
  PolygonMesh mobius;
  const int n = 5;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * M_PI * i / n, c = std::cos(u / 2), s = std::sin(u / 2);
    for (double t : {-0.3, 0.3})
      mobius.vertices.push_back({(2 + t * c) * std::cos(u), (2 + t * c) * std::sin(u), t * s});
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    const int c = i + 1 < n ? 2 * i + 2 : 1, d = i + 1 < n ? 2 * i + 3 : 0;  // twisted at the end
    mobius.faces.push_back({a, c, d, b});
  }
  EXPECT_EQ(message_of(mobius),
            "in.obj: the mesh is not orientable (around face 0's piece, faces cannot agree on a "
            "side), expected an orientable surface");
}

class TempDir {
 public:
  TempDir()
      : path_(std::filesystem::temp_directory_path() /
              ("bimdf_layout_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = (path_ / name).string();
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

 private:
  std::filesystem::path path_;
};

std::string read_error(const std::string& path) {
  try {
    read_polygon_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LayoutSurface, ReadsObjOffAndPlyAlike) {
  const TempDir dir;
  const std::string obj = dir.write("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const std::string off = dir.write(
      "q.off", "OFF\n# a comment\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n");
  const std::string ply_ascii = dir.write(
      "q.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty "
      "float z\nproperty uchar red\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0 7\n1 0 0 7\n1 1 0 7\n0 1 0 7\n4 0 1 2 3\n");
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty "
      "double y\nproperty double z\nelement face 1\nproperty list uchar uint vertex_indices\n"
      "end_header\n";
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  binary.push_back(4);
  const uint32_t idx[4] = {0, 1, 2, 3};
  binary.append(reinterpret_cast<const char*>(idx), sizeof idx);
  const std::string ply_binary = dir.write("b.PLY", binary);
  for (const std::string& path : {obj, off, ply_ascii, ply_binary}) {
    SCOPED_TRACE(path);
    const PolygonMesh m = read_polygon_mesh(path);
    ASSERT_EQ(m.num_vertices(), 4);
    ASSERT_EQ(m.num_faces(), 1);
    EXPECT_EQ(m.faces[0], (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(m.vertices[2], (std::array<double, 3>{1, 1, 0}));
  }
  EXPECT_EQ(layout::read_surface(off).mesh.num_faces(), 2);

  EXPECT_EQ(
      read_error(dir.write("x.stl", "solid")),
      dir.write("x.stl", "solid") + ": unknown mesh format 'stl', expected .obj, .off or .ply");
  const std::string short_off = dir.write("s.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_EQ(read_error(short_off), short_off + ": the file ends after 2 of 3 vertices");
  const std::string bad_index = dir.write("i.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_EQ(read_error(bad_index),
            bad_index + ":6: face 0: vertex index 3 is out of range (3 vertices)");
  const std::string no_end = dir.write("n.ply", "ply\nformat ascii 1.0\nelement vertex 0\n");
  EXPECT_EQ(read_error(no_end), no_end + ": the header has no end_header line");
  const std::string truncated = dir.write("t.ply", binary.substr(0, binary.size() - 3));
  EXPECT_EQ(read_error(truncated), truncated + ": element face 0: the file ends early");
  const std::string two = dir.write("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  EXPECT_EQ(read_error(two), two + ":3: face 0 has 2 vertices, expected at least 3");
}

// The undirected edge of `top` between vertices a and b.
int edge_between(const layout::SurfaceTopology& top, int a, int b) {
  for (int h : top.outgoing(a))
    if (top.to(h) == b) return top.edge(h);
  for (int h : top.outgoing(b))
    if (top.to(h) == a) return top.edge(h);
  ADD_FAILURE() << a << "-" << b << " is no edge";
  return 0;
}

TEST(LayoutFeatures, NoiseIsCleanedAndLongCurvesKeepTheirLength) {
  // A 20 × 20 grid (vertex (i, j) is i·21 + j) with hand-set sharp edges: a long curve along
  // j = 10 with a short spur, a lone spiky triangle, the four edges of one cell (a small loop)
  // and a short open curve. Four erosions keep only the long curve, at its full length.
  const TriangleMesh grid = test::square(1, 20);
  const layout::SurfaceTopology top(grid);
  const auto id = [](int i, int j) { return i * 21 + j; };
  const auto edge = [&](int a, int b) { return edge_between(top, a, b); };
  std::vector<bool> sharp(top.num_edges(), false), expected = sharp;
  for (int i = 2; i < 18; ++i) sharp[edge(id(i, 10), id(i + 1, 10))] = true;
  expected = sharp;
  sharp[edge(id(10, 10), id(10, 11))] = sharp[edge(id(10, 11), id(10, 12))] = true;
  for (auto [a, b] : {std::pair{id(3, 3), id(4, 3)},
                      {id(4, 3), id(4, 4)},
                      {id(3, 3), id(4, 4)},
                      {id(15, 15), id(16, 15)},
                      {id(16, 15), id(16, 16)},
                      {id(16, 16), id(15, 16)},
                      {id(15, 16), id(15, 15)}})
    sharp[edge(a, b)] = true;
  for (int j = 12; j < 18; ++j) sharp[edge(id(5, j), id(5, j + 1))] = true;
  EXPECT_EQ(layout::clean_sharp_edges(top, sharp, 4), expected);
  EXPECT_EQ(layout::clean_sharp_edges(top, sharp, 0), sharp);
}

TEST(LayoutFeatures, OfALensOnlyTheSideThatBendsMoreIsKept) {
  // A 20 × 20 grid folded into a valley along j = 10 (a crease of ~33° from border to border)
  // where a second curve leaves the crease at (6, 10) and joins it again at (10, 10) over
  // j = 10.8: between them a lens of 6 triangles with 2 turns (38.7° at both ends), its flat
  // side dropped. The same second curve over a rectangle (right angles at both ends) bounds 4
  // turns and stays.
  TriangleMesh grid = test::square(1, 20);
  const auto id = [](int i, int j) { return i * 21 + j; };
  // Cell (9, 10) cut along its other diagonal, so that (9, 11)-(10, 10) is an edge.
  const int cell = 2 * (9 * 20 + 10);
  grid.faces[cell] = {id(9, 10), id(10, 10), id(9, 11)};
  grid.faces[cell + 1] = {id(10, 10), id(10, 11), id(9, 11)};
  for (int i = 7; i <= 9; ++i) grid.vertices[id(i, 11)][1] = 10.8 / 20;
  for (auto& p : grid.vertices) p[2] = 0.3 * std::fabs(p[1] - 0.5);
  const layout::SurfaceTopology top(grid);
  const auto edge = [&](int a, int b) { return edge_between(top, a, b); };
  std::vector<bool> crease(top.num_edges(), false);
  for (int i = 0; i < 20; ++i) crease[edge(id(i, 10), id(i + 1, 10))] = true;
  std::vector<bool> lens = crease;
  lens[edge(id(6, 10), id(7, 11))] = lens[edge(id(9, 11), id(10, 10))] = true;
  for (int i = 7; i < 9; ++i) lens[edge(id(i, 11), id(i + 1, 11))] = true;
  EXPECT_EQ(layout::clean_sharp_edges(top, lens, 4), crease);

  std::vector<bool> box = crease;
  box[edge(id(6, 10), id(6, 11))] = box[edge(id(10, 11), id(10, 10))] = true;
  for (int i = 6; i < 10; ++i) box[edge(id(i, 11), id(i + 1, 11))] = true;
  EXPECT_EQ(layout::clean_sharp_edges(top, box, 4), box);
}

TEST(LayoutFeatures, CubeCreasesAndCorners) {
  const TriangleMesh cube = test::cube(3);
  const layout::Features f = layout::detect_features(cube, {});
  EXPECT_EQ(f.sharp_edges.size(), 12u * 3);
  EXPECT_EQ(f.corners.size(), 8u);
  EXPECT_EQ(f.border_edges, 0);
  for (int v : f.corners)
    for (double c : cube.vertices[v]) EXPECT_EQ(std::fabs(c), 1.0);
  // Nothing is sharp on a fine sphere; everything above 90° on the cube is not.
  EXPECT_TRUE(layout::detect_features(test::icosphere(3), {}).sharp_edges.empty());
  layout::FeatureOptions blunt;
  blunt.sharp_angle_deg = 95;
  EXPECT_TRUE(layout::detect_features(cube, blunt).sharp_edges.empty());

  // The square: no sharp edges, its border's four turns are the corners.
  const layout::Features sq = layout::detect_features(test::square(1, 4), {});
  EXPECT_EQ(sq.border_edges, 16);
  EXPECT_EQ(sq.corners, (std::vector<int>{0, 4, 20, 24}));

  // Given edges: one crease of the cube only; a pair that is not an edge is refused.
  const auto one = layout::features_from_edges(cube, {f.sharp_edges[0]}, {}, "c.feature");
  EXPECT_EQ(one.sharp_edges.size(), 1u);
  EXPECT_EQ(one.corners.size(), 2u);  // the crease's two ends
  try {
    layout::features_from_edges(cube, {{0, 0}}, {}, "c.feature");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "c.feature: feature edge 0-0 is not an edge of the mesh");
  }
}

}  // namespace
}  // namespace bimdf
