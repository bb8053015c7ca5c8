// Cutting a triangle mesh along polylines (src/layout/mesh_cutting.cpp): the refined mesh
// covers the input exactly (area, orientation, parent faces, topology), keeps what no polyline
// touches, and every polyline runs along its edges; broken promises are internal errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "layout/mesh_cutting.hpp"
#include "mesh/vec3.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

using detail::Vec3;
using layout::SurfacePoint;
using layout::SurfaceTopology;
using Polylines = std::vector<std::vector<SurfacePoint>>;

double face_area(const TriangleMesh& m, int f) {
  return 0.5 * detail::norm(detail::triangle_normal(m, f));
}

// Barycentric coordinates of x, assumed in the plane of face f.
std::array<double, 3> barycentric(const TriangleMesh& m, int f, const Vec3& x) {
  const Vec3 n = detail::triangle_normal(m, f);
  std::array<double, 3> w;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &b = m.vertices[m.faces[f][(k + 1) % 3]], &c = m.vertices[m.faces[f][(k + 2) % 3]];
    w[k] = detail::dot(detail::cross(detail::sub(b, x), detail::sub(c, x)), n) / detail::dot(n, n);
  }
  return w;
}

double plane_distance(const TriangleMesh& m, int f, const Vec3& x) {
  const Vec3 n = detail::normalized(detail::triangle_normal(m, f));
  return std::fabs(detail::dot(detail::sub(x, m.vertices[m.faces[f][0]]), n));
}

// What a tracer would give for the straight segment p → q on a flat part of the mesh: p, q and
// every mesh vertex or edge crossing between them, in order.
std::vector<SurfacePoint> straight_polyline(const SurfaceTopology& top, const Vec3& p,
                                            const Vec3& q) {
  const TriangleMesh& m = top.mesh();
  const double eps = 1e-12;
  const Vec3 d = detail::sub(q, p);
  std::vector<std::pair<double, SurfacePoint>> events;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const double s = detail::dot(detail::sub(m.vertices[v], p), d) / detail::dot(d, d);
    if (s > -eps && s < 1 + eps &&
        detail::norm(detail::sub(m.vertices[v], detail::along(p, s, d))) < eps)
      events.push_back({s, SurfacePoint::at_vertex(v)});
  }
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e);
    const Vec3& a = m.vertices[top.from(h)];
    const Vec3 ab = detail::sub(m.vertices[top.to(h)], a), r = detail::sub(a, p);
    const Vec3 c = detail::cross(d, ab);
    const double cc = detail::dot(c, c);
    if (cc < 1e-20 || std::fabs(detail::dot(r, c)) > eps * std::sqrt(cc)) continue;
    const double s = detail::dot(detail::cross(r, ab), c) / cc;
    const double u = detail::dot(detail::cross(r, d), c) / cc;
    if (s > -eps && s < 1 + eps && u > eps && u < 1 - eps)
      events.push_back({s, SurfacePoint::on_edge(e, u)});
  }
  for (const auto& [x, s] : {std::pair{p, 0.0}, std::pair{q, 1.0}}) {
    if (std::any_of(events.begin(), events.end(),
                    [&](const auto& ev) { return std::fabs(ev.first - s) < 1e-9; }))
      continue;
    for (int e = 0; e < top.num_edges(); ++e) {  // on an edge the segment runs along
      const int h = top.edge_half_edge(e);
      const Vec3& a = m.vertices[top.from(h)];
      const Vec3 ab = detail::sub(m.vertices[top.to(h)], a);
      const double u = detail::dot(detail::sub(x, a), ab) / detail::dot(ab, ab);
      if (u > eps && u < 1 - eps && detail::norm(detail::sub(x, detail::along(a, u, ab))) < eps)
        events.push_back({s, SurfacePoint::on_edge(e, u)});
    }
    for (int f = 0; f < m.num_faces(); ++f) {
      const auto w = barycentric(m, f, x);
      if (plane_distance(m, f, x) < eps && w[0] > 0 && w[1] > 0 && w[2] > 0)
        events.push_back({s, SurfacePoint::in_face(f, w)});
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<SurfacePoint> line;
  for (size_t i = 0; i < events.size(); ++i)
    if (i == 0 || events[i].first > events[i - 1].first + 1e-9) line.push_back(events[i].second);
  return line;
}

// A polyline on any mesh: from face(h)'s centroid across `steps` edges, turning alternately
// left and right so that it runs on roughly straight, to the last face's centroid.
std::vector<SurfacePoint> strip_polyline(const SurfaceTopology& top, int h, int steps) {
  std::vector<SurfacePoint> line{SurfacePoint::in_face(h / 3, {1 / 3.0, 1 / 3.0, 1 / 3.0})};
  for (int k = 0; k < steps; ++k) {
    const int e = top.edge(h);
    const double s = k % 2 ? 0.35 : 0.6;  // from from(h)
    line.push_back(SurfacePoint::on_edge(e, top.edge_half_edge(e) == h ? s : 1 - s));
    const int g = top.opposite(h);
    h = k % 2 ? SurfaceTopology::next(g) : SurfaceTopology::prev(g);
  }
  line.push_back(SurfacePoint::in_face(h / 3, {0.2, 0.3, 0.5}));
  return line;
}

// The square grid with its inner vertices moved (deterministically) within their cells.
TriangleMesh jittered_square() {
  TriangleMesh m = test::square(1, 4);
  for (int i = 1; i < 4; ++i)
    for (int j = 1; j < 4; ++j) {
      auto& v = m.vertices[i * 5 + j];
      v[0] += 0.04 * std::sin(7.0 * i + 3 * j);
      v[1] += 0.04 * std::cos(5.0 * i + 11 * j);
    }
  return m;
}

// How far x is from the polyline through `line`; `at` receives the arc length of x's first
// place on it beyond `after` (a polyline may come back to its own points).
double distance_to_polyline(const std::vector<Vec3>& line, const Vec3& x, double after = -1,
                            double* at = nullptr) {
  double best = INFINITY, arc = 0;
  bool placed = false;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3 d = detail::sub(line[i + 1], line[i]);
    const double s =
        std::clamp(detail::dot(detail::sub(x, line[i]), d) / detail::dot(d, d), 0.0, 1.0);
    const double dist = detail::norm(detail::sub(x, detail::along(line[i], s, d)));
    const double here = arc + s * detail::norm(d);
    if (at && !placed && dist < 1e-12 && here > after) *at = here, placed = true;
    best = std::min(best, dist);
    arc += detail::norm(d);
  }
  return best;
}

// Cuts, and checks everything the result promises. Returns it for the test's own checks.
layout::CutMesh cut_and_check(const TriangleMesh& mesh, const Polylines& polylines) {
  const SurfaceTopology top(mesh);
  layout::CutMesh cut = layout::cut_along_polylines(top, polylines);
  const TriangleMesh& out = cut.mesh;
  const int V = mesh.num_vertices();

  // The input's vertices first and unchanged.
  EXPECT_GE(out.num_vertices(), V);
  for (int v = 0; v < V; ++v) EXPECT_EQ(out.vertices[v], mesh.vertices[v]) << "vertex " << v;

  // Faces: positive area, the parent's orientation, inside the parent; areas add up.
  EXPECT_EQ(static_cast<int>(cut.parent_face.size()), out.num_faces());
  double area_in = 0, area_out = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) area_in += face_area(mesh, f);
  for (int f = 0; f < out.num_faces(); ++f) {
    const int p = cut.parent_face[f];
    EXPECT_GT(face_area(out, f), 1e-12 * face_area(mesh, p)) << "face " << f;
    EXPECT_GT(detail::dot(detail::triangle_normal(out, f), detail::triangle_normal(mesh, p)), 0)
        << "face " << f;
    Vec3 centroid{0, 0, 0};
    for (int v : out.faces[f])
      for (int c = 0; c < 3; ++c) centroid[c] += out.vertices[v][c] / 3;
    const auto w = barycentric(mesh, p, centroid);
    EXPECT_LT(plane_distance(mesh, p, centroid), 1e-12) << "face " << f;
    EXPECT_GT(std::min({w[0], w[1], w[2]}), 0) << "face " << f << " outside its parent " << p;
    area_out += face_area(out, f);
  }
  EXPECT_NEAR(area_out, area_in, 1e-12 * area_in);

  // A manifold oriented mesh of the same topology.
  const SurfaceTopology cut_top(out);
  EXPECT_EQ(out.num_vertices() - cut_top.num_edges() + out.num_faces(),
            V - top.num_edges() + mesh.num_faces());
  EXPECT_EQ(cut_top.border_loops().size(), top.border_loops().size());
  EXPECT_EQ(cut_top.num_components(), top.num_components());

  // Faces with no new vertex on or in them are kept as they were.
  for (int f = 0; f < mesh.num_faces(); ++f) {
    bool touched = false;
    for (int v = V; v < out.num_vertices(); ++v) {
      const auto w = barycentric(mesh, f, out.vertices[v]);
      touched |=
          plane_distance(mesh, f, out.vertices[v]) < 1e-12 && std::min({w[0], w[1], w[2]}) > -1e-12;
    }
    if (touched) continue;
    std::vector<std::array<int, 3>> children;
    for (int g = 0; g < out.num_faces(); ++g)
      if (cut.parent_face[g] == f) children.push_back(out.faces[g]);
    EXPECT_EQ(children, (std::vector<std::array<int, 3>>{mesh.faces[f]})) << "face " << f;
  }

  // Each polyline runs along mesh edges through its own points, in order.
  std::set<std::pair<int, int>> edges;
  for (const auto& t : out.faces)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  EXPECT_EQ(cut.polyline_vertices.size(), polylines.size());
  for (size_t i = 0; i < polylines.size() && i < cut.polyline_vertices.size(); ++i) {
    const std::vector<int>& chain = cut.polyline_vertices[i];
    std::vector<Vec3> line;
    for (const SurfacePoint& p : polylines[i]) line.push_back(layout::position(top, p));
    // (Points within 1e-12 along an edge are one, placed where the first of them is.)
    EXPECT_LT(detail::norm(detail::sub(out.vertices[chain.front()], line.front())), 1e-12);
    EXPECT_LT(detail::norm(detail::sub(out.vertices[chain.back()], line.back())), 1e-12);
    double previous = -1;
    for (size_t k = 0; k < chain.size(); ++k) {
      double at = -1;
      EXPECT_LT(distance_to_polyline(line, out.vertices[chain[k]], previous, &at), 1e-12);
      EXPECT_GT(at, previous) << "polyline " << i << " goes back at " << k;
      previous = at;
      if (k == 0) continue;
      EXPECT_TRUE(edges.count(std::minmax(chain[k - 1], chain[k])))
          << "polyline " << i << ": vertices " << chain[k - 1] << " and " << chain[k];
      const Vec3 mid =
          detail::along(out.vertices[chain[k - 1]], 0.5,
                        detail::sub(out.vertices[chain[k]], out.vertices[chain[k - 1]]));
      EXPECT_LT(distance_to_polyline(line, mid), 1e-12);
    }
    for (const Vec3& x : line)  // every point of the polyline is one of its vertices
      EXPECT_TRUE(std::any_of(chain.begin(), chain.end(), [&](int v) {
        return detail::norm(detail::sub(out.vertices[v], x)) < 1e-12;
      }));
  }

  // Inside each input face the triangulation is Delaunay but for the polylines' edges: no
  // vertex inside the circle of the triangle across an edge the cut was free to choose.
  std::map<std::pair<int, int>, int> face_of_edge;
  for (int f = 0; f < out.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) face_of_edge[{out.faces[f][k], out.faces[f][(k + 1) % 3]}] = f;
  std::set<std::pair<int, int>> polyline_edges;
  for (const auto& chain : cut.polyline_vertices)
    for (size_t k = 0; k + 1 < chain.size(); ++k)
      polyline_edges.insert(std::minmax(chain[k], chain[k + 1]));
  for (const auto& [edge, f] : face_of_edge) {
    const auto other = face_of_edge.find({edge.second, edge.first});
    if (other == face_of_edge.end() || cut.parent_face[f] != cut.parent_face[other->second] ||
        polyline_edges.count(std::minmax(edge.first, edge.second)))
      continue;
    const int parent = cut.parent_face[f];
    const auto in_plane = [&](int v) {  // 2D coordinates in the parent's plane
      const Vec3 n = detail::normalized(detail::triangle_normal(mesh, parent));
      const Vec3 x = detail::normalized(
          detail::sub(mesh.vertices[mesh.faces[parent][1]], mesh.vertices[mesh.faces[parent][0]]));
      const Vec3 d = detail::sub(out.vertices[v], mesh.vertices[mesh.faces[parent][0]]);
      return std::array<double, 2>{detail::dot(d, x), detail::dot(d, detail::cross(n, x))};
    };
    const auto third = [&](int g, int a, int b) {
      for (int v : out.faces[g])
        if (v != a && v != b) return v;
      return -1;
    };
    const auto a = in_plane(edge.first), b = in_plane(edge.second);
    const auto c = in_plane(third(f, edge.first, edge.second));
    const auto d = in_plane(third(other->second, edge.first, edge.second));
    double m[3][3], size = 0;
    for (int r = 0; r < 3; ++r) {
      const auto& p = r == 0 ? a : r == 1 ? b : c;
      const double x = p[0] - d[0], y = p[1] - d[1];
      m[r][0] = x, m[r][1] = y, m[r][2] = x * x + y * y;
      size = std::max(size, std::hypot(x, y));
    }
    const double incircle = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    EXPECT_LE(incircle, 1e-9 * std::pow(size, 4))
        << "edge " << edge.first << "–" << edge.second << " in face " << parent;
  }
  return cut;
}

TEST(LayoutCutting, StraightChordAcrossSeveralFaces) {
  for (const TriangleMesh& mesh : {test::square(1, 4), jittered_square()}) {
    const SurfaceTopology top(mesh);
    const auto line = straight_polyline(top, {0, 0.3, 0}, {1, 0.55, 0});
    ASSERT_GE(line.size(), 9u);  // crosses 4 columns, each through a vertical and a diagonal
    const layout::CutMesh cut = cut_and_check(mesh, {line});
    // Every point is new (on an edge, none at a vertex) and every crossed face is split.
    EXPECT_EQ(cut.mesh.num_vertices(), mesh.num_vertices() + static_cast<int>(line.size()));
    EXPECT_EQ(cut.polyline_vertices[0].size(), line.size());
    // A point on an edge adds one face per face of the edge: two inside, one on the border.
    EXPECT_EQ(cut.mesh.num_faces(), mesh.num_faces() + 2 * static_cast<int>(line.size()) - 2);
  }
}

TEST(LayoutCutting, PolylineThroughAMeshVertex) {
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  const auto line = straight_polyline(top, {0.1, 0, 0}, {0.9, 1, 0});
  const layout::CutMesh cut = cut_and_check(mesh, {line});
  const std::vector<int>& chain = cut.polyline_vertices[0];
  EXPECT_NE(std::find(chain.begin(), chain.end(), 2 * 5 + 2), chain.end());  // (0.5, 0.5)
  EXPECT_EQ(cut.mesh.num_vertices(), mesh.num_vertices() + static_cast<int>(line.size()) - 1);
}

TEST(LayoutCutting, PolylinesAlongMeshEdgesOnlySplitThoseEdges) {
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  // Vertex to vertex along the grid line y = 0.5: nothing to do.
  const auto along_edges = straight_polyline(top, {0, 0.5, 0}, {1, 0.5, 0});
  ASSERT_EQ(along_edges.size(), 5u);
  layout::CutMesh cut = cut_and_check(mesh, {along_edges});
  EXPECT_EQ(cut.mesh.faces, mesh.faces);
  EXPECT_EQ(cut.polyline_vertices[0], (std::vector<int>{2, 7, 12, 17, 22}));
  // From inside one edge to inside another along x = 0.25: two edge points, each splitting
  // the two faces of its edge in two.
  const auto partly = straight_polyline(top, {0.25, 0.1, 0}, {0.25, 0.6, 0});
  ASSERT_EQ(partly.size(), 4u);
  cut = cut_and_check(mesh, {partly});
  EXPECT_EQ(cut.mesh.num_vertices(), mesh.num_vertices() + 2);
  EXPECT_EQ(cut.mesh.num_faces(), mesh.num_faces() + 4);
  EXPECT_EQ(cut.polyline_vertices[0], (std::vector<int>{25, 6, 7, 26}));
}

TEST(LayoutCutting, TJunctionInsideAFaceSplitsTheOtherPolyline) {
  for (const TriangleMesh& mesh : {test::square(1, 4), jittered_square()}) {
    const SurfaceTopology top(mesh);
    const auto a = straight_polyline(top, {0, 0.3, 0}, {1, 0.55, 0});
    const Vec3 junction{0.6, 0.3 + 0.25 * 0.6, 0};  // on a, inside a face
    const auto b = straight_polyline(top, {0.6, 1, 0}, junction);
    ASSERT_EQ(b.back().kind, SurfacePoint::Kind::Face);
    const layout::CutMesh cut = cut_and_check(mesh, {a, b});
    const int end = cut.polyline_vertices[1].back();
    const std::vector<int>& first = cut.polyline_vertices[0];
    EXPECT_NE(std::find(first.begin(), first.end(), end), first.end());
    EXPECT_EQ(first.size(), a.size() + 1);
  }
}

TEST(LayoutCutting, PolylineEndingOnItsOwnSegment) {
  // Up, right, down, and back left onto its own first segment (inside a face).
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  const std::vector<Vec3> corners = {
      {0.3, 0, 0}, {0.3, 0.7, 0}, {0.65, 0.7, 0}, {0.65, 0.45, 0}, {0.3, 0.45, 0}};
  std::vector<SurfacePoint> line;
  for (size_t k = 0; k + 1 < corners.size(); ++k) {
    const auto piece = straight_polyline(top, corners[k], corners[k + 1]);
    line.insert(line.end(), piece.begin() + (k > 0), piece.end());
  }
  ASSERT_EQ(line.back().kind, SurfacePoint::Kind::Face);
  const layout::CutMesh cut = cut_and_check(mesh, {line});
  const std::vector<int>& chain = cut.polyline_vertices[0];
  EXPECT_EQ(chain.size(), line.size() + 1);
  EXPECT_EQ(std::count(chain.begin(), chain.end(), chain.back()), 2);
}

TEST(LayoutCutting, SegmentsStayEdgesBetweenCloseEndsOnEitherSide) {
  // Two traces end just above and just below a third's segment in the same face: the short
  // edge between their ends, which a Delaunay triangulation would take, crosses that segment.
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  const Polylines lines = {straight_polyline(top, {0, 0.3, 0}, {1, 0.55, 0}),
                           straight_polyline(top, {0.6, 1, 0}, {0.6, 0.453, 0}),
                           straight_polyline(top, {0.61, 0, 0}, {0.61, 0.4495, 0})};
  ASSERT_EQ(lines[1].back().kind, SurfacePoint::Kind::Face);
  ASSERT_EQ(lines[2].back().id, lines[1].back().id);
  const layout::CutMesh cut = cut_and_check(mesh, lines);
  EXPECT_EQ(cut.polyline_vertices[0].size(), lines[0].size());
}

TEST(LayoutCutting, PolylinesSharingAnEndPointMeetAtOneVertex) {
  const TriangleMesh mesh = jittered_square();
  const SurfaceTopology top(mesh);
  // Three traces leave one point inside a face (a singularity), a fourth a corner vertex.
  const Vec3 centre{0.45, 0.4, 0};
  const Polylines lines = {
      straight_polyline(top, centre, {0, 0.1, 0}), straight_polyline(top, centre, {0.8, 0, 0}),
      straight_polyline(top, centre, {0.7, 1, 0}), straight_polyline(top, {1, 1, 0}, {0.7, 1, 0})};
  ASSERT_EQ(lines[0].front().kind, SurfacePoint::Kind::Face);
  const layout::CutMesh cut = cut_and_check(mesh, lines);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(cut.polyline_vertices[i].front(), cut.polyline_vertices[0].front());
  EXPECT_EQ(cut.polyline_vertices[3].back(), cut.polyline_vertices[2].back());
  int points = 0;
  for (const auto& line : lines) points += static_cast<int>(line.size());
  // Not new: the start's two repetitions, the top border point's one, the two mesh vertices.
  EXPECT_EQ(lines[3].size(), 3u);
  EXPECT_EQ(cut.mesh.num_vertices(), mesh.num_vertices() + points - 2 - 1 - 2);
}

TEST(LayoutCutting, PiecesInsideOneFace) {
  // A trace with a single segment at a singular point, and one that stays inside its face.
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  const Polylines lines = {straight_polyline(top, {0.55, 0.3, 0}, {0.8, 0.3, 0}),
                           straight_polyline(top, {0.3, 0.7, 0}, {0.45, 0.73, 0})};
  ASSERT_EQ(lines[1].size(), 2u);
  cut_and_check(mesh, lines);
}

// A number in [0, 1) from two integers, the same on every platform.
double pseudo_random(int seed, int k) {
  const double x = std::sin(12.9898 * k + 78.233 * seed) * 43758.5453;
  return x - std::floor(x);
}

TEST(LayoutCutting, ManyCloseParallelPolylinesWithTJunctionsBetweenThem) {
  // Parallel lines y = c + m x at random heights, two of them very close, and between
  // neighbouring lines upright traces ending on both: T-junctions anywhere, several in one
  // face, many points on one edge. On the regular grids some lines and traces run along mesh
  // edges or end at mesh vertices.
  for (int seed = 0; seed < 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const int n = 3 + seed % 7;
    const bool regular = seed % 2 == 0;
    const TriangleMesh mesh = regular ? test::square(1, n) : jittered_square();
    const SurfaceTopology top(mesh);
    const double m = seed % 3 == 0 ? 0.0 : pseudo_random(seed, 999) - 0.5;
    std::vector<double> heights;
    for (int k = 0; k < 6; ++k) {
      double c = 0.05 + std::max(-m, 0.0) + (0.85 - std::fabs(m)) * pseudo_random(seed, k);
      if (regular && m == 0 && k % 2) c = std::round(c * n) / n;  // along mesh edges
      if (std::find(heights.begin(), heights.end(), c) == heights.end()) heights.push_back(c);
    }
    heights.push_back(heights[0] + std::pow(10.0, -2 - 3 * pseudo_random(seed, 77)));
    std::sort(heights.begin(), heights.end());
    Polylines lines;
    for (double c : heights) lines.push_back(straight_polyline(top, {0, c, 0}, {1, c + m, 0}));
    for (size_t k = 0; k + 1 < heights.size(); ++k)
      for (int j = 0; j < 2; ++j) {
        double x = 0.05 + 0.9 * pseudo_random(seed, 100 + 2 * static_cast<int>(k) + j);
        if (regular && j) x = std::round(x * n) / n;  // along mesh edges
        lines.push_back(
            straight_polyline(top, {x, heights[k] + m * x, 0}, {x, heights[k + 1] + m * x, 0}));
      }
    const layout::CutMesh cut = cut_and_check(mesh, lines);
    // Each upright trace's ends are on the lines below and above it.
    for (size_t i = heights.size(); i < lines.size(); ++i) {
      const size_t below = (i - heights.size()) / 2;
      for (const auto& [end, line] : {std::pair{cut.polyline_vertices[i].front(), below},
                                      std::pair{cut.polyline_vertices[i].back(), below + 1}}) {
        const std::vector<int>& on = cut.polyline_vertices[line];
        EXPECT_NE(std::find(on.begin(), on.end(), end), on.end()) << "trace " << i;
      }
    }
  }
}

TEST(LayoutCutting, AcrossCurvedSurfacesAndCreases) {
  for (const TriangleMesh& mesh : {test::cube(3), test::icosphere(2)}) {
    const SurfaceTopology top(mesh);
    const Polylines lines = {strip_polyline(top, 0, 9), strip_polyline(top, 3 * 40 + 1, 6)};
    const layout::CutMesh cut = cut_and_check(mesh, lines);
    EXPECT_EQ(cut.polyline_vertices[0].size(), 11u);
  }
  // On the cube, a strip from the x = 1 side's first face crosses onto another side.
  const TriangleMesh cube = test::cube(3);
  const SurfaceTopology top(cube);
  const auto line = strip_polyline(top, 0, 9);
  std::set<int> sides;
  for (const SurfacePoint& p : line)
    if (p.kind == SurfacePoint::Kind::Face) sides.insert(p.id / 18);
  EXPECT_GE(sides.size(), 2u);
}

TEST(LayoutCutting, BrokenPromisesAreInternalErrors) {
  const TriangleMesh mesh = test::square(1, 4);
  const SurfaceTopology top(mesh);
  const auto cut = [&](const Polylines& lines) { return layout::cut_along_polylines(top, lines); };
  const auto message = [&](const Polylines& lines) -> std::string {
    try {
      cut(lines);
    } catch (const std::logic_error& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(message({{SurfacePoint::at_vertex(0), SurfacePoint::at_vertex(1)},
                     {SurfacePoint::at_vertex(0), SurfacePoint::at_vertex(24)}}),
            "cut_along_polylines: polyline 1: points 0 and 1 share no face");
  // Two polylines crossing inside face 19 (the crossing is at (0.6, 0.45)).
  EXPECT_EQ(message({straight_polyline(top, {0, 0.3, 0}, {1, 0.55, 0}),
                     straight_polyline(top, {0.6, 0, 0}, {0.6, 1, 0})}),
            "cut_along_polylines: two segments cross in face 19");
  // Points that are not where their kind says.
  EXPECT_THROW(cut({{SurfacePoint::at_vertex(0), SurfacePoint::on_edge(0, 0)}}), std::logic_error);
  EXPECT_THROW(cut({{SurfacePoint::in_face(0, {0.5, 0.5, 0})}}), std::logic_error);
  EXPECT_THROW(cut({{SurfacePoint::at_vertex(25)}}), std::logic_error);
}

}  // namespace
}  // namespace bimdf
