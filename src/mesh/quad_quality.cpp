#include "mesh/quad_quality.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/vec3.hpp"

namespace bimdf::detail {

Vec3 quad_centre(const QuadMesh& mesh, const std::array<int, 4>& q) {
  Vec3 centre{0, 0, 0};
  for (int v : q)
    for (int d = 0; d < 3; ++d) centre[d] += mesh.vertices[v][d] / 4;
  return centre;
}

Vec3 newell_normal(const QuadMesh& mesh, const std::array<int, 4>& q) {
  Vec3 n{0, 0, 0};
  for (int a = 0; a < 4; ++a) {
    const Vec3& u = mesh.vertices[q[a]];
    const Vec3& v = mesh.vertices[q[(a + 1) % 4]];
    n[0] += (u[1] - v[1]) * (u[2] + v[2]);
    n[1] += (u[2] - v[2]) * (u[0] + v[0]);
    n[2] += (u[0] - v[0]) * (u[1] + v[1]);
  }
  return n;
}

double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& q) {
  const Vec3 n = newell_normal(mesh, q);
  const double nn = std::sqrt(dot(n, n));
  if (nn == 0) return 0;
  return scaled_jacobian(mesh, q, {n[0] / nn, n[1] / nn, n[2] / nn});
}

double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& q, const Vec3& n) {
  double worst = 1;
  for (int a = 0; a < 4; ++a) {
    const Vec3& c = mesh.vertices[q[a]];
    const Vec3 e1 = sub(mesh.vertices[q[(a + 1) % 4]], c);
    const Vec3 e2 = sub(mesh.vertices[q[(a + 3) % 4]], c);
    const Vec3 x = cross(e1, e2);
    const double l = std::sqrt(dot(e1, e1) * dot(e2, e2));
    worst = std::min(worst, l > 0 ? dot(x, n) / l : 0.0);
  }
  return worst;
}

double corner_spread(const QuadMesh& mesh, const std::array<int, 4>& q) {
  double shortest = INFINITY, longest = 0;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) {
      const double d = norm(sub(mesh.vertices[q[a]], mesh.vertices[q[b]]));
      shortest = std::min(shortest, d);
      if (b == a + 1 || (a == 0 && b == 3)) longest = std::max(longest, d);
    }
  }
  return longest > 0 ? shortest / longest : 0;
}

QuadShape quad_shape(const QuadMesh& mesh, const std::array<int, 4>& q, const Vec3& normal) {
  const Vec3* p[4] = {&mesh.vertices[q[0]], &mesh.vertices[q[1]], &mesh.vertices[q[2]],
                      &mesh.vertices[q[3]]};
  const Vec3 newell = newell_normal(mesh, q);
  const double nn = std::sqrt(dot(newell, newell));
  const Vec3 n = nn > 0 ? Vec3{newell[0] / nn, newell[1] / nn, newell[2] / nn} : Vec3{0, 0, 0};
  Vec3 edge[4];  // edge[a] = p[a + 1] − p[a]
  double length2[4];
  for (int a = 0; a < 4; ++a) {
    edge[a] = sub(*p[(a + 1) % 4], *p[a]);
    length2[a] = dot(edge[a], edge[a]);
  }
  QuadShape shape{1, 1, 0};
  for (int a = 0; a < 4; ++a) {
    const int previous = (a + 3) % 4;
    // Corner a: e1 = edge[a], e2 = −edge[previous].
    const Vec3 e2 = {-edge[previous][0], -edge[previous][1], -edge[previous][2]};
    const Vec3 x = cross(edge[a], e2);
    const double l = std::sqrt(length2[a] * length2[previous]);
    shape.own = std::min(shape.own, nn > 0 && l > 0 ? dot(x, n) / l : 0.0);
    shape.under = std::min(shape.under, l > 0 ? dot(x, normal) / l : 0.0);
  }
  const double diagonal2 = std::min(dot(sub(*p[2], *p[0]), sub(*p[2], *p[0])),
                                    dot(sub(*p[3], *p[1]), sub(*p[3], *p[1])));
  const double shortest2 = std::min({length2[0], length2[1], length2[2], length2[3], diagonal2});
  const double longest2 = std::max({length2[0], length2[1], length2[2], length2[3]});
  shape.spread = longest2 > 0 ? std::sqrt(shortest2 / longest2) : 0;
  return shape;
}

bool degenerate(const QuadMesh& mesh, const std::array<int, 4>& q) {
  double squared_edges = 0;
  for (int a = 0; a < 4; ++a) {
    const Vec3 e = sub(mesh.vertices[q[(a + 1) % 4]], mesh.vertices[q[a]]);
    squared_edges += dot(e, e);
  }
  return corner_spread(mesh, q) < kDegenerateSpread || scaled_jacobian(mesh, q) == 0 ||
         norm(newell_normal(mesh, q)) < kDegenerateArea * squared_edges;
}

}  // namespace bimdf::detail
