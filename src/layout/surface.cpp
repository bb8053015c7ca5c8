// Preparing a user's polygon mesh for the layout stages, and describing it (surface.hpp).
#include "bimdf/layout/surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bimdf/error.hpp"
#include "layout/surface_topology.hpp"
#include "mesh/vec3.hpp"
#include "quant/triangle_connectivity.hpp"

namespace bimdf::layout {
namespace {

using P3 = detail::Vec3;
using detail::cross;
using detail::dot;
using detail::norm;
using detail::sub;

std::string face_name(const PolygonMesh& in, int f) {
  std::string s = "face " + std::to_string(f);
  if (f < static_cast<int>(in.face_line.size()) && in.face_line[f] > 0)
    s += " (line " + std::to_string(in.face_line[f]) + ")";
  return s;
}

// Why a triangle is unusable, or "" if it is fine: a zero edge or (numerically) zero area. The
// area test is relative to the longest edge, so it does not depend on the model's scale.
std::string degeneracy(const P3& a, const P3& b, const P3& c) {
  const double l = std::max({norm(sub(b, a)), norm(sub(c, b)), norm(sub(a, c))});
  if (std::min({norm(sub(b, a)), norm(sub(c, b)), norm(sub(a, c))}) == 0)
    return "two of its vertices are at the same position";
  if (norm(cross(sub(b, a), sub(c, a))) <= 1e-12 * l * l) return "its vertices are collinear";
  return "";
}

// Ear clipping in the plane of the polygon's Newell normal: of the ears (convex corners with
// no other corner inside their triangle) the one with the largest smallest angle is cut first,
// which keeps slivers out where the polygon allows. Returns false if no ear is left (a
// self-overlapping or degenerate polygon).
bool triangulate_polygon(const std::vector<P3>& p, std::vector<std::array<int, 3>>& out) {
  const int n = static_cast<int>(p.size());
  P3 normal{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const P3 &a = p[i], &b = p[(i + 1) % n];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  std::vector<int> left(n);
  for (int i = 0; i < n; ++i) left[i] = i;
  const auto turn = [&](int a, int b, int c) {
    return dot(cross(sub(p[b], p[a]), sub(p[c], p[b])), normal);
  };
  const auto inside = [&](int x, int a, int b, int c) {
    return turn(a, b, x) >= 0 && turn(b, c, x) >= 0 && turn(c, a, x) >= 0;
  };
  const auto min_angle = [&](int a, int b, int c) {
    const int v[3] = {a, b, c};
    double m = M_PI;
    for (int k = 0; k < 3; ++k) {
      const P3 u = sub(p[v[(k + 1) % 3]], p[v[k]]), w = sub(p[v[(k + 2) % 3]], p[v[k]]);
      m = std::min(m, std::atan2(norm(cross(u, w)), dot(u, w)));
    }
    return m;
  };
  while (left.size() > 3) {
    const int m = static_cast<int>(left.size());
    int best = -1;
    double best_angle = -1;
    for (int i = 0; i < m; ++i) {
      const int a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
      if (turn(a, b, c) <= 0) continue;
      bool ear = true;
      for (int x : left)
        if (x != a && x != b && x != c && inside(x, a, b, c)) {
          ear = false;
          break;
        }
      if (ear && min_angle(a, b, c) > best_angle) best = i, best_angle = min_angle(a, b, c);
    }
    if (best < 0) return false;
    out.push_back({left[(best + m - 1) % m], left[best], left[(best + 1) % m]});
    left.erase(left.begin() + best);
  }
  out.push_back({left[0], left[1], left[2]});
  return true;
}

// Gives every fan of faces around a vertex after the first its own copy of the vertex, so that
// each vertex has one fan (a disk or half-disk). Returns the number of copies made;
// `copy_of` receives each new vertex's original.
int split_nonmanifold_vertices(TriangleMesh& m, std::vector<int>& copy_of) {
  const quant::Connectivity c = quant::connect(m, "", nullptr);
  const int H = 3 * m.num_faces();
  std::vector<std::vector<int>> out(m.num_vertices());
  for (int h = 0; h < H; ++h) out[quant::from_vertex(m, h)].push_back(h);
  const auto prev = [](int h) { return h - h % 3 + (h % 3 + 2) % 3; };
  const auto next = [](int h) { return h - h % 3 + (h % 3 + 1) % 3; };
  std::vector<int> fan_of(H, -1);
  int copies = 0;
  for (int v = 0; v < static_cast<int>(out.size()); ++v) {
    int fans = 0;
    for (int h0 : out[v]) {
      if (fan_of[h0] >= 0) continue;
      std::vector<int> fan;
      // Counter-clockwise from h0, then clockwise from it, until the border or back at h0.
      for (int h = h0; h >= 0 && fan_of[h] < 0; h = c.opposite[prev(h)])
        fan_of[h] = fans, fan.push_back(h);
      for (int g = c.opposite[h0]; g >= 0;) {
        const int h = next(g);
        if (fan_of[h] >= 0) break;
        fan_of[h] = fans;
        fan.push_back(h);
        g = c.opposite[h];
      }
      if (fans > 0) {
        const int copy = m.num_vertices();
        m.vertices.push_back(m.vertices[v]);
        copy_of.push_back(v);
        for (int h : fan) m.faces[h / 3][h % 3] = copy;
        ++copies;
      }
      ++fans;
    }
  }
  return copies;
}

}  // namespace

Surface prepare_surface(const PolygonMesh& in, const std::string& source) {
  if (in.faces.empty())
    throw InputError(source, "", "the mesh has no faces, expected a triangle or polygon mesh");
  Surface s;
  TriangleMesh& m = s.mesh;
  m.vertices = in.vertices;
  for (int f = 0; f < in.num_faces(); ++f) {
    const std::vector<int>& face = in.faces[f];
    std::vector<std::array<int, 3>> triangles;
    if (face.size() == 3) {
      triangles.push_back({face[0], face[1], face[2]});
    } else {
      std::vector<P3> corners;
      for (int v : face) corners.push_back(in.vertices[v]);
      std::vector<std::array<int, 3>> local;
      if (!triangulate_polygon(corners, local))
        throw InputError(source, "",
                         face_name(in, f) + " (" + std::to_string(face.size()) +
                             " vertices) cannot be cut into triangles: it overlaps itself or "
                             "its corners are collinear");
      for (const auto& t : local) triangles.push_back({face[t[0]], face[t[1]], face[t[2]]});
      ++s.repairs.triangulated_polygons;
    }
    for (const auto& t : triangles) {
      const std::string why = degeneracy(in.vertices[t[0]], in.vertices[t[1]], in.vertices[t[2]]);
      if (!why.empty())
        throw InputError(source, "",
                         face_name(in, f) + " has zero area (" + why +
                             "), expected a proper triangle: remove or merge it first");
      m.faces.push_back(t);
      s.input_face.push_back(f);
    }
  }

  // Edges with three or more faces and non-orientable pieces are named in the input's vertex
  // and face numbering (triangles keep the input's vertex ids up to here).
  {
    std::vector<std::pair<int, int>> conflicts;
    const quant::Connectivity c = quant::connect(m, source, &conflicts);
    if (!conflicts.empty()) {
      try {
        s.repairs.flipped_faces = quant::orient_coherently(m, c, source);
      } catch (const InputError&) {
        throw InputError(source, "",
                         "the mesh is not orientable (around " + face_name(in, s.input_face[0]) +
                             "'s piece, faces cannot agree on a side), expected an orientable "
                             "surface");
      }
    }
  }

  s.input_vertex.resize(m.num_vertices());
  for (int v = 0; v < m.num_vertices(); ++v) s.input_vertex[v] = v;
  s.repairs.split_vertices = split_nonmanifold_vertices(m, s.input_vertex);

  // Drop vertices no face uses, keeping the others' order.
  std::vector<int> new_id(m.num_vertices(), -1);
  for (const auto& t : m.faces)
    for (int v : t) new_id[v] = 0;
  int kept = 0;
  for (int v = 0; v < m.num_vertices(); ++v)
    if (new_id[v] == 0) {
      new_id[v] = kept;
      m.vertices[kept] = m.vertices[v];
      s.input_vertex[kept] = s.input_vertex[v];
      ++kept;
    }
  // Copies made by the split count as used vertices, not as dropped ones.
  s.repairs.unreferenced_vertices = m.num_vertices() - kept;
  m.vertices.resize(kept);
  s.input_vertex.resize(kept);
  for (auto& t : m.faces)
    for (int& v : t) v = new_id[v];
  return s;
}

Surface read_surface(const std::string& path) {
  return prepare_surface(read_polygon_mesh(path), path);
}

SurfaceInfo describe_surface(const TriangleMesh& mesh) {
  const SurfaceTopology top(mesh);
  SurfaceInfo info;
  info.vertices = mesh.num_vertices();
  info.faces = mesh.num_faces();
  info.edges = top.num_edges();
  info.components = top.num_components();
  info.border_loops = static_cast<int>(top.border_loops().size());
  info.euler_characteristic = info.vertices - info.edges + info.faces;
  const int C = info.components;
  std::vector<int> euler(C, 0);
  info.component_border_loops.assign(C, 0);
  std::vector<int> vertex_component(mesh.num_vertices(), -1);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int c = top.face_component()[f];
    euler[c] += 1;
    for (int v : mesh.faces[f]) vertex_component[v] = c;
  }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (vertex_component[v] >= 0) euler[vertex_component[v]] += 1;
  for (int e = 0; e < top.num_edges(); ++e)
    euler[top.face_component()[top.edge_half_edge(e) / 3]] -= 1;
  for (const auto& loop : top.border_loops())
    ++info.component_border_loops[top.face_component()[loop[0] / 3]];
  for (int c = 0; c < C; ++c)
    info.component_genus.push_back((2 - euler[c] - info.component_border_loops[c]) / 2);
  info.average_edge_length = top.mean_edge_length();
  P3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const P3& p : mesh.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  info.bounding_box_diagonal = mesh.vertices.empty() ? 0 : norm(sub(hi, lo));
  for (int f = 0; f < mesh.num_faces(); ++f)
    info.area += 0.5 * norm(detail::triangle_normal(mesh, f));
  return info;
}

}  // namespace bimdf::layout
