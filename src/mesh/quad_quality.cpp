#include "mesh/quad_quality.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/vec3.hpp"

namespace bimdf::detail {

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

bool degenerate(const QuadMesh& mesh, const std::array<int, 4>& q) {
  return corner_spread(mesh, q) < kDegenerateSpread || scaled_jacobian(mesh, q) == 0;
}

}  // namespace bimdf::detail
