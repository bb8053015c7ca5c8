#include "surface_fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace bimdf::test {
namespace {

using P3 = std::array<double, 3>;

P3 unit(P3 p) {
  const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {p[0] / n, p[1] / n, p[2] / n};
}

// Quads of an (n+1)×(m+1) vertex grid, each cut into two triangles; `wrap_u`, `wrap_v` glue
// the grid's opposite sides. Vertex (i, j) is at id(i, j).
template <typename Id>
void grid_faces(TriangleMesh& mesh, int n, int m, Id id) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      mesh.faces.push_back({a, b, c});
      mesh.faces.push_back({a, c, d});
    }
}

}  // namespace

TriangleMesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : m.vertices) p = unit(p);
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const P3 &p = m.vertices[a], &q = m.vertices[b];
      m.vertices.push_back(unit({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
      return mid[key] = m.num_vertices() - 1;
    };
    std::vector<std::array<int, 3>> faces;
    for (const auto& f : m.faces) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      faces.push_back({f[0], a, c});
      faces.push_back({f[1], b, a});
      faces.push_back({f[2], c, b});
      faces.push_back({a, b, c});
    }
    m.faces = faces;
  }
  return m;
}

TriangleMesh torus(double R, double r, int n, int m) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      mesh.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                               (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  grid_faces(mesh, n, m, [&](int i, int j) { return (i % n) * m + (j % m); });
  return mesh;
}

TriangleMesh cube(int n) {
  TriangleMesh mesh;
  std::map<std::array<long, 3>, int> ids;  // vertices shared by faces, by position × n
  const auto vertex = [&](P3 p) {
    const std::array<long, 3> key = {std::lround(p[0] * n), std::lround(p[1] * n),
                                     std::lround(p[2] * n)};
    const auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    mesh.vertices.push_back(p);
    return ids[key] = mesh.num_vertices() - 1;
  };
  // Each face: a corner and two edge directions whose cross product points outwards.
  const P3 corner[6] = {{1, -1, -1},  {-1, -1, -1}, {-1, 1, -1},
                        {-1, -1, -1}, {-1, -1, 1},  {-1, -1, -1}};
  const P3 du[6] = {{0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const P3 dv[6] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  for (int s = 0; s < 6; ++s)
    grid_faces(mesh, n, n, [&](int i, int j) {
      P3 p;
      for (int k = 0; k < 3; ++k) p[k] = corner[s][k] + 2.0 * (du[s][k] * i + dv[s][k] * j) / n;
      return vertex(p);
    });
  return mesh;
}

TriangleMesh cylinder(double h, int n, int m) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= m; ++j) {
      const double u = 2 * M_PI * i / n;
      mesh.vertices.push_back({std::cos(u), std::sin(u), h * j / m});
    }
  grid_faces(mesh, n, m, [&](int i, int j) { return (i % n) * (m + 1) + j; });
  return mesh;
}

TriangleMesh square(double w, int n) {
  TriangleMesh mesh;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) mesh.vertices.push_back({w * i / n, w * j / n, 0});
  grid_faces(mesh, n, n, [&](int i, int j) { return i * (n + 1) + j; });
  return mesh;
}

TriangleMesh combine(const TriangleMesh& a, const TriangleMesh& b, double offset) {
  TriangleMesh m = a;
  for (auto p : b.vertices) m.vertices.push_back({p[0] + offset, p[1], p[2]});
  for (auto f : b.faces)
    m.faces.push_back({f[0] + a.num_vertices(), f[1] + a.num_vertices(), f[2] + a.num_vertices()});
  return m;
}

}  // namespace bimdf::test
