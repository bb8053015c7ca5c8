// Cutting a triangle mesh along polylines on its surface (mesh_cutting.hpp).
//
// Each input face is re-triangulated on its own, in 2D coordinates of its plane, and nothing
// is remeshed globally: the points the polylines put on an edge are shared by the edge's two
// faces, so each face's new triangles meet their neighbours' exactly, faces no polyline touches
// keep their vertex ids, and a point's position comes from its SurfacePoint alone (never from
// an intersection computed here). Inside a face the triangulation grows point by point (its
// sides split at their points, then each interior point put into the triangle or onto the
// inner edge holding it), then segment by segment, each made an edge by flipping the edges it
// crosses (Sloan's constraint recovery), and last unconstrained edges are flipped towards
// Delaunay to keep slivers out. Working with triangles throughout, rather than cutting the
// face's polygon by chords, needs no special case for what polylines do inside a face (a
// T-junction, a trace with a single segment at an interior start, points collinear on a side
// or a segment, pieces not connected to the face's border), and a flip is only made across a
// strictly convex quadrilateral, so no triangle becomes flat. Segments are split beforehand at
// every interior point lying on them (within 1e-9 of the face's size), so that a polyline's
// vertex list and the triangulation agree on where a T-junction is.
#include "layout/mesh_cutting.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace bimdf::layout {
namespace {

using detail::Vec3;
using Point2 = std::array<double, 2>;

// Relative to a face's longest side: how far off a line an interior point may be and still be
// on a segment (or a triangulation edge, which is then split instead of its triangle).
constexpr double kNearLine = 1e-9;
// Relative to the face's longest side: how far off a line a point must be to count as on one
// side of it (positions carry rounding errors of about 1e-16 of that). A vertex closer to a
// segment being inserted lies on it, and no flip makes a triangle flatter than this.
constexpr double kOffLine = 1e-13;
constexpr double kSamePoint = 1e-9;  // mesh_cutting.hpp: points within this are one point

[[noreturn]] void internal_error(const std::string& what) {
  throw std::logic_error("cut_along_polylines: " + what);
}

// Twice the signed area of triangle a, b, c: positive when counter-clockwise.
double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double distance(const Point2& a, const Point2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

// Positive when d lies inside the circle through the counter-clockwise triangle a, b, c.
double incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0], by = b[1] - d[1];
  const double cx = c[0] - d[0], cy = c[1] - d[1];
  return (ax * ax + ay * ay) * (bx * cy - cx * by) + (bx * bx + by * by) * (cx * ay - ax * cy) +
         (cx * cx + cy * cy) * (ax * by - bx * ay);
}

// The triangulation of one input face, in its plane, refined point by point and segment by
// segment. A face holds few points, so triangles are found by scanning the list.
class FaceTriangulation {
 public:
  // Starts as the face's triangle, the first three points (counter-clockwise).
  FaceTriangulation(int face, std::vector<Point2> xy, double scale)
      : face_(face), xy_(std::move(xy)), scale_(scale), triangles_{{0, 1, 2}} {}

  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

  // Puts point p on the existing edge a–b, splitting the triangle on each side of it.
  void split_edge(int a, int b, int p) {
    for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      const auto [t, k] = find_edge(x, y);
      if (t < 0) continue;
      const int apex = triangles_[t][(k + 2) % 3];
      triangles_[t] = {x, p, apex};
      triangles_.push_back({p, y, apex});
    }
  }

  // Inserts a point strictly inside the face: into the triangle that holds it, or onto the
  // inner edge it lies on.
  void insert_interior_point(int p) {
    int best = -1, best_side = 0;
    double best_clearance = -std::numeric_limits<double>::infinity();
    for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
      int side = 0;
      double clearance = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) {
        const Point2 &a = xy_[triangles_[t][k]], &b = xy_[triangles_[t][(k + 1) % 3]];
        const double d = orient(a, b, xy_[p]) / distance(a, b);
        if (d < clearance) clearance = d, side = k;
      }
      if (clearance > best_clearance) best = t, best_side = side, best_clearance = clearance;
    }
    const int a = triangles_[best][best_side], b = triangles_[best][(best_side + 1) % 3];
    if (best_clearance <= kNearLine * scale_ && find_edge(b, a).first >= 0) {
      split_edge(a, b, p);
      return;
    }
    const auto [x, y, z] = triangles_[best];
    triangles_[best] = {x, y, p};
    triangles_.push_back({y, z, p});
    triangles_.push_back({z, x, p});
  }

  // Makes u–v an edge that later flips keep, by flipping the edges that cross it (Sloan: one
  // whose two triangles form a strictly convex quadrilateral always exists; an edge still
  // crossing after its flip waits its turn again). Throws if u–v crosses an earlier segment or
  // passes through a point.
  void insert_segment(int u, int v) {
    const Point2 &pu = xy_[u], &pv = xy_[v];
    const double length = distance(pu, pv);
    const auto crosses = [&](int a, int b) {
      return side(pu, pv, xy_[a]) * side(pu, pv, xy_[b]) < 0 &&
             side(xy_[a], xy_[b], pu) * side(xy_[a], xy_[b], pv) < 0;
    };
    std::deque<std::pair<int, int>> crossing;
    for (const auto& t : triangles_)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double along =
            ((xy_[a][0] - pu[0]) * (pv[0] - pu[0]) + (xy_[a][1] - pu[1]) * (pv[1] - pu[1])) /
            (length * length);
        if (a != u && a != v && along > 0 && along < 1 && side(pu, pv, xy_[a]) == 0)
          internal_error("a segment in face " + std::to_string(face_) +
                         " runs through a point it does not stop at (segments cross)");
        if (a < b && crosses(a, b)) {
          if (constrained_.count({a, b}))
            internal_error("two segments cross in face " + std::to_string(face_));
          crossing.push_back({a, b});
        }
      }
    const size_t n = crossing.size(), max_steps = 100 + 10 * n * n * n;
    for (size_t step = 0; !crossing.empty(); ++step) {
      const auto [a, b] = crossing.front();
      crossing.pop_front();
      const Quadrilateral q = quadrilateral(a, b);
      if (q.t2 < 0 || step > max_steps)
        internal_error("cannot make a segment an edge in face " + std::to_string(face_));
      if (!flippable(a, b, q)) {
        crossing.push_back({a, b});
        continue;
      }
      flip(a, b, q);
      if (crosses(q.c, q.d)) crossing.push_back({q.c, q.d});
    }
    if (find_edge(u, v).first < 0 && find_edge(v, u).first < 0)
      internal_error("cannot make a segment an edge in face " + std::to_string(face_));
    constrained_.insert(std::minmax(u, v));
  }

  // Flips unconstrained inner edges whose two triangles are not Delaunay (Lawson), keeping
  // slivers out where the points allow.
  void flip_towards_delaunay() {
    const int max_passes = 10 + 2 * static_cast<int>(triangles_.size());
    for (int pass = 0; pass < max_passes; ++pass) {
      bool flipped = false;
      std::set<std::pair<int, int>> edges;
      for (const auto& t : triangles_)
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
      for (const auto& [a, b] : edges) {
        const Quadrilateral q = quadrilateral(a, b);
        if (q.t1 < 0 || q.t2 < 0 || constrained_.count({a, b})) continue;
        // Only what is clearly not Delaunay (relative to the quadrilateral's size).
        const double size = std::max(distance(xy_[a], xy_[b]), distance(xy_[q.c], xy_[q.d]));
        if (incircle(xy_[a], xy_[b], xy_[q.c], xy_[q.d]) <= 1e-10 * std::pow(size, 4) ||
            !flippable(a, b, q))
          continue;
        flip(a, b, q);
        flipped = true;
      }
      if (!flipped) break;
    }
  }

  // Throws unless every triangle is counter-clockwise with positive area.
  void check_orientation() const {
    for (const auto& t : triangles_)
      if (!(orient(xy_[t[0]], xy_[t[1]], xy_[t[2]]) > 0))
        internal_error("re-triangulating face " + std::to_string(face_) +
                       " made a triangle of zero or negative area");
  }

 private:
  // The triangle holding directed edge a→b and the corner a is at, or (−1, −1).
  std::pair<int, int> find_edge(int a, int b) const {
    for (int t = 0; t < static_cast<int>(triangles_.size()); ++t)
      for (int k = 0; k < 3; ++k)
        if (triangles_[t][k] == a && triangles_[t][(k + 1) % 3] == b) return {t, k};
    return {-1, -1};
  }

  // The quadrilateral around edge a→b: its triangles (a, b, c) = t1 and (b, a, d) = t2, −1
  // where there is none.
  struct Quadrilateral {
    int t1 = -1, c = -1, t2 = -1, d = -1;
  };
  Quadrilateral quadrilateral(int a, int b) const {
    Quadrilateral q;
    const auto [t1, k1] = find_edge(a, b);
    const auto [t2, k2] = find_edge(b, a);
    if (t1 >= 0) q.t1 = t1, q.c = triangles_[t1][(k1 + 2) % 3];
    if (t2 >= 0) q.t2 = t2, q.d = triangles_[t2][(k2 + 2) % 3];
    return q;
  }
  // Which side of line p→q point x is on: ±1, or 0 within kOffLine of the line, where
  // rounding decides the sign (consecutive pieces of one segment are collinear, for one).
  int side(const Point2& p, const Point2& q, const Point2& x) const {
    const double o = orient(p, q, x), tolerance = kOffLine * scale_ * distance(p, q);
    return o > tolerance ? 1 : o < -tolerance ? -1 : 0;
  }
  // Whether the quadrilateral around edge a–b is convex enough for the flip's two triangles to
  // be clearly not flat: each corner off the line of the opposite (longest) side.
  bool flippable(int a, int b, const Quadrilateral& q) const {
    const auto clearly_ccw = [&](int x, int y, int z) {
      const double longest =
          std::max({distance(xy_[x], xy_[y]), distance(xy_[y], xy_[z]), distance(xy_[z], xy_[x])});
      return orient(xy_[x], xy_[y], xy_[z]) > kOffLine * scale_ * longest;
    };
    return q.t1 >= 0 && q.t2 >= 0 && clearly_ccw(a, q.d, q.c) && clearly_ccw(b, q.c, q.d);
  }
  // Replaces edge a–b by c–d in its two triangles.
  void flip(int a, int b, const Quadrilateral& q) {
    triangles_[q.t1] = {a, q.d, q.c};
    triangles_[q.t2] = {b, q.c, q.d};
  }

  int face_;
  std::vector<Point2> xy_;
  double scale_;
  std::vector<std::array<int, 3>> triangles_;
  std::set<std::pair<int, int>> constrained_;
};

// The polyline points as vertices of the refined mesh: the input's vertices, then one new
// vertex per distinct edge or face point, in the order the polylines first name them.
class PointVertices {
 public:
  PointVertices(const SurfaceTopology& top, std::vector<Vec3>& positions)
      : top_(top),
        positions_(positions),
        input_vertices_(top.mesh().num_vertices()),
        on_edge_(top.num_edges()),
        in_face_(top.mesh().num_faces()) {}

  // The vertex of p, made if new; `where` names p in messages.
  int vertex_of(const SurfacePoint& p, const std::string& where) {
    const auto fail = [&](const std::string& what) { internal_error(where + " " + what); };
    switch (p.kind) {
      case SurfacePoint::Kind::Vertex:
        if (p.id < 0 || p.id >= input_vertices_) fail("names no vertex");
        return p.id;
      case SurfacePoint::Kind::Edge:
        if (p.id < 0 || p.id >= top_.num_edges()) fail("names no edge");
        if (!(p.t > 0 && p.t < 1)) fail("is not strictly inside its edge");
        for (const auto& [t, v] : on_edge_[p.id])
          if (std::fabs(t - p.t) <= kSamePoint) return v;
        on_edge_[p.id].push_back({p.t, add(p)});
        return on_edge_[p.id].back().second;
      case SurfacePoint::Kind::Face: {
        if (p.id < 0 || p.id >= static_cast<int>(in_face_.size())) fail("names no face");
        const auto& b = p.bary;
        if (!(b[0] > 0 && b[1] > 0 && b[2] > 0 && std::fabs(b[0] + b[1] + b[2] - 1) < 1e-9))
          fail("is not strictly inside its face");
        for (int v : in_face_[p.id]) {
          const auto& c = origin(v).bary;
          if (std::max({std::fabs(c[0] - b[0]), std::fabs(c[1] - b[1]), std::fabs(c[2] - b[2])}) <=
              kSamePoint)
            return v;
        }
        in_face_[p.id].push_back(add(p));
        return in_face_[p.id].back();
      }
    }
    return -1;
  }

  // The point a new vertex stands for (the first one named, of the points merged into it).
  const SurfacePoint& origin(int v) const { return origins_[v - input_vertices_]; }
  // The new vertices on edge e, ordered by t (from(edge_half_edge(e)) to its to()).
  std::vector<std::pair<double, int>> on_edge(int e) const {
    std::vector<std::pair<double, int>> sorted = on_edge_[e];
    std::sort(sorted.begin(), sorted.end());
    return sorted;
  }
  const std::vector<int>& in_face(int f) const { return in_face_[f]; }

 private:
  int add(const SurfacePoint& p) {
    positions_.push_back(position(top_, p));
    origins_.push_back(p);
    return static_cast<int>(positions_.size()) - 1;
  }

  const SurfaceTopology& top_;
  std::vector<Vec3>& positions_;
  int input_vertices_;
  std::vector<SurfacePoint> origins_;
  std::vector<std::vector<std::pair<double, int>>> on_edge_;
  std::vector<std::vector<int>> in_face_;
};

// Face f laid out in its plane: corner 0 at the origin, corner 1 on the x axis, corner 2 above
// it, so that counter-clockwise about the face's normal is counter-clockwise here.
struct FacePlane {
  std::array<Point2, 3> corner;
  double scale;  // the longest side
};

FacePlane face_plane(const TriangleMesh& mesh, int f) {
  const Vec3& a = mesh.vertices[mesh.faces[f][0]];
  const Vec3 ab = detail::sub(mesh.vertices[mesh.faces[f][1]], a);
  const Vec3 ac = detail::sub(mesh.vertices[mesh.faces[f][2]], a);
  const double l = detail::norm(ab), height = detail::norm(detail::cross(ab, ac)) / l;
  if (!(l > 0 && height > 0)) internal_error("face " + std::to_string(f) + " has zero area");
  FacePlane plane{{Point2{0, 0}, Point2{l, 0}, Point2{detail::dot(ab, ac) / l, height}}, 0};
  plane.scale = std::max({l, detail::norm(ac), detail::norm(detail::sub(ab, ac))});
  return plane;
}

class Cutter {
 public:
  explicit Cutter(const SurfaceTopology& top) : top_(top), mesh_(top.mesh()), out_() {
    out_.mesh.vertices = mesh_.vertices;
  }

  CutMesh run(const std::vector<std::vector<SurfacePoint>>& polylines) {
    PointVertices points(top_, out_.mesh.vertices);
    std::vector<std::vector<int>> ids(polylines.size());
    for (size_t i = 0; i < polylines.size(); ++i)
      for (size_t j = 0; j < polylines[i].size(); ++j)
        ids[i].push_back(points.vertex_of(
            polylines[i][j], "polyline " + std::to_string(i) + ", point " + std::to_string(j)));
    points_ = &points;
    segments_.assign(mesh_.num_faces(), {});
    for (size_t i = 0; i < polylines.size(); ++i)
      out_.polyline_vertices.push_back(route(i, polylines[i], ids[i]));
    for (int f = 0; f < mesh_.num_faces(); ++f) refine_face(f);
    return std::move(out_);
  }

 private:
  // The mesh vertices polyline i runs through once cut: its points, and on each segment the
  // points of other polylines lying on it. Records each segment inside a face for the face.
  std::vector<int> route(size_t i, const std::vector<SurfacePoint>& line,
                         const std::vector<int>& ids) {
    std::vector<int> vertices;
    for (size_t j = 0; j < ids.size(); ++j) {
      if (j > 0 && ids[j] == ids[j - 1]) continue;
      if (j > 0) {
        const int a = ids[j - 1], b = ids[j];
        const int e = first_common(edges_around(line[j - 1]), edges_around(line[j]));
        const int f = e >= 0 ? -1 : first_common(faces_around(line[j - 1]), faces_around(line[j]));
        if (e < 0 && f < 0)
          internal_error("polyline " + std::to_string(i) + ": points " + std::to_string(j - 1) +
                         " and " + std::to_string(j) + " share no face");
        const std::vector<int> inner = e >= 0 ? between_on_edge(e, a, b) : on_chord(f, a, b);
        if (f >= 0) {
          segments_[f].push_back({a});
          segments_[f].back().insert(segments_[f].back().end(), inner.begin(), inner.end());
          segments_[f].back().push_back(b);
        }
        vertices.insert(vertices.end(), inner.begin(), inner.end());
      }
      vertices.push_back(ids[j]);
    }
    return vertices;
  }

  std::vector<int> edges_around(const SurfacePoint& p) const {
    std::vector<int> edges;
    if (p.kind == SurfacePoint::Kind::Edge) edges.push_back(p.id);
    if (p.kind == SurfacePoint::Kind::Vertex)
      for (int h : top_.outgoing(p.id)) {
        edges.push_back(top_.edge(h));
        edges.push_back(top_.edge(SurfaceTopology::prev(h)));
      }
    return edges;
  }

  std::vector<int> faces_around(const SurfacePoint& p) const {
    std::vector<int> faces;
    if (p.kind == SurfacePoint::Kind::Face) faces.push_back(p.id);
    if (p.kind == SurfacePoint::Kind::Vertex)
      for (int h : top_.outgoing(p.id)) faces.push_back(SurfaceTopology::face(h));
    if (p.kind == SurfacePoint::Kind::Edge) {
      const int h = top_.edge_half_edge(p.id);
      faces.push_back(SurfaceTopology::face(h));
      if (top_.opposite(h) >= 0) faces.push_back(SurfaceTopology::face(top_.opposite(h)));
    }
    return faces;
  }

  // The first element of `a` that `b` also holds, or −1: the edge both points of a segment lie
  // on (it runs along that edge), or else the face both lie in.
  static int first_common(const std::vector<int>& a, const std::vector<int>& b) {
    for (int x : a)
      if (std::find(b.begin(), b.end(), x) != b.end()) return x;
    return -1;
  }

  // Where vertex v (an end of edge e or a point on it) is along e, from 0 to 1.
  double edge_parameter(int e, int v) const {
    if (v >= mesh_.num_vertices()) return points_->origin(v).t;
    return v == top_.from(top_.edge_half_edge(e)) ? 0 : 1;
  }

  // The points on edge e strictly between a and b, in order from a.
  std::vector<int> between_on_edge(int e, int a, int b) const {
    const double ta = edge_parameter(e, a), tb = edge_parameter(e, b);
    std::vector<int> inner;
    for (const auto& [t, v] : points_->on_edge(e))
      if (v != a && v != b && t > std::min(ta, tb) && t < std::max(ta, tb)) inner.push_back(v);
    if (ta > tb) std::reverse(inner.begin(), inner.end());
    return inner;
  }

  // The points inside face f that lie on the open segment a–b, in order from a.
  std::vector<int> on_chord(int f, int a, int b) const {
    const FacePlane plane = face_plane(mesh_, f);
    const Point2 pa = xy(plane, f, a), pb = xy(plane, f, b);
    const double length = distance(pa, pb);
    std::vector<std::pair<double, int>> found;
    for (int v : points_->in_face(f)) {
      if (v == a || v == b) continue;
      const Point2 p = xy(plane, f, v);
      const double along =
          ((p[0] - pa[0]) * (pb[0] - pa[0]) + (p[1] - pa[1]) * (pb[1] - pa[1])) / (length * length);
      if (along > 0 && along < 1 &&
          std::fabs(orient(pa, pb, p)) <= kNearLine * plane.scale * length)
        found.push_back({along, v});
    }
    std::sort(found.begin(), found.end());
    std::vector<int> inner;
    for (const auto& [along, v] : found) inner.push_back(v);
    return inner;
  }

  // Vertex v's coordinates in face f's plane (v is a corner of f or a point on or in it).
  Point2 xy(const FacePlane& plane, int f, int v) const {
    const auto& corners = mesh_.faces[f];
    const SurfacePoint* p = v < mesh_.num_vertices() ? nullptr : &points_->origin(v);
    for (int i = 0; i < 3; ++i) {
      if (corners[i] == v) return plane.corner[i];
      if (p && p->kind == SurfacePoint::Kind::Edge && top_.edge(3 * f + i) == p->id) {
        const double t = 3 * f + i == top_.edge_half_edge(p->id) ? p->t : 1 - p->t;
        const Point2 &from = plane.corner[i], &to = plane.corner[(i + 1) % 3];
        return {from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])};
      }
    }
    if (p && p->kind == SurfacePoint::Kind::Face && p->id == f) {
      Point2 sum{0, 0};
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 2; ++c) sum[c] += p->bary[i] * plane.corner[i][c];
      return sum;
    }
    internal_error("vertex " + std::to_string(v) + " is not on face " + std::to_string(f));
  }

  // Replaces face f by its refinement, or keeps it if no point lies on or in it.
  void refine_face(int f) {
    std::vector<int> vertices(mesh_.faces[f].begin(), mesh_.faces[f].end());
    std::array<std::vector<int>, 3> side_points;
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i, e = top_.edge(h);
      for (const auto& [t, v] : points_->on_edge(e)) side_points[i].push_back(v);
      if (h != top_.edge_half_edge(e)) std::reverse(side_points[i].begin(), side_points[i].end());
      vertices.insert(vertices.end(), side_points[i].begin(), side_points[i].end());
    }
    const std::vector<int>& interior = points_->in_face(f);
    if (vertices.size() == 3 && interior.empty()) {
      out_.mesh.faces.push_back(mesh_.faces[f]);
      out_.parent_face.push_back(f);
      return;
    }
    vertices.insert(vertices.end(), interior.begin(), interior.end());
    std::map<int, int> local;
    std::vector<Point2> xys;
    const FacePlane plane = face_plane(mesh_, f);
    for (int v : vertices) {
      local.emplace(v, static_cast<int>(xys.size()));
      xys.push_back(xy(plane, f, v));
    }
    FaceTriangulation triangulation(f, std::move(xys), plane.scale);
    for (int i = 0; i < 3; ++i) {
      int previous = i;
      for (int v : side_points[i]) {
        triangulation.split_edge(previous, (i + 1) % 3, local.at(v));
        previous = local.at(v);
      }
    }
    for (int v : interior) triangulation.insert_interior_point(local.at(v));
    for (const std::vector<int>& chain : segments_[f])
      for (size_t k = 0; k + 1 < chain.size(); ++k)
        triangulation.insert_segment(local.at(chain[k]), local.at(chain[k + 1]));
    triangulation.flip_towards_delaunay();
    triangulation.check_orientation();
    for (const auto& t : triangulation.triangles()) {
      out_.mesh.faces.push_back({vertices[t[0]], vertices[t[1]], vertices[t[2]]});
      out_.parent_face.push_back(f);
    }
  }

  const SurfaceTopology& top_;
  const TriangleMesh& mesh_;
  CutMesh out_;
  const PointVertices* points_ = nullptr;
  std::vector<std::vector<std::vector<int>>> segments_;  // per face: its segments' vertex chains
};

}  // namespace

CutMesh cut_along_polylines(const SurfaceTopology& top,
                            const std::vector<std::vector<SurfacePoint>>& polylines) {
  return Cutter(top).run(polylines);
}

}  // namespace bimdf::layout
