#include "mesh/untangle.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "mesh/quad_quality.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::detail {
namespace {

// value(x, y) = c + gx·x + gy·y.
struct Linear {
  double c, gx, gy;
  double at(double x, double y) const { return c + gx * x + gy * y; }
};

}  // namespace

std::optional<std::array<Vec3, 2>> tangent_frame(const QuadMesh& mesh,
                                                 const std::vector<int>& quads) {
  Vec3 sum{0, 0, 0};
  for (int f : quads) {
    const Vec3 q = newell_normal(mesh, mesh.quads[f]);
    for (int d = 0; d < 3; ++d) sum[d] += q[d];
  }
  const Vec3 n = normalized(sum);
  if (norm(n) == 0) return std::nullopt;
  // t1: the axis least aligned with n, made orthogonal; t2 = n × t1.
  Vec3 t1{0, 0, 0};
  const int axis = std::abs(n[0]) < std::abs(n[1]) ? (std::abs(n[0]) < std::abs(n[2]) ? 0 : 2)
                                                   : (std::abs(n[1]) < std::abs(n[2]) ? 1 : 2);
  t1[axis] = 1;
  for (int d = 0; d < 3; ++d) t1[d] -= n[axis] * n[d];
  t1 = normalized(t1);
  return std::array<Vec3, 2>{t1, cross(n, t1)};
}

double mean_distance(const QuadMesh& mesh, const std::vector<int>& neighbours, const Vec3& at) {
  double length = 0;
  for (int w : neighbours) length += norm(sub(mesh.vertices[w], at)) / neighbours.size();
  return length;
}

std::optional<std::array<double, 3>> max_min_corner_position(
    const QuadMesh& mesh, int v, const std::vector<int>& quads,
    const std::vector<std::array<double, 3>>& normals, const std::array<double, 3>& t1,
    const std::array<double, 3>& t2, double radius) {
  const Vec3 at = mesh.vertices[v];
  // Objectives: the corners of the quads at v that touch v (the corner at v and its two
  // neighbours along the quad). The signed area cross(next − c, prev − c)·n is exactly linear
  // in v's position, so three evaluations give its coefficients.
  std::vector<Linear> area;
  for (int f : quads) {
    const std::array<int, 4>& q = mesh.quads[f];
    int k = 0;
    while (q[k] != v) ++k;
    for (int corner : {k, (k + 1) % 4, (k + 3) % 4}) {
      const auto value = [&](const Vec3& p) {
        const auto position = [&](int i) { return q[i] == v ? p : mesh.vertices[q[i]]; };
        const Vec3 c = position(corner);
        const Vec3 e1 = sub(position((corner + 1) % 4), c);
        const Vec3 e2 = sub(position((corner + 3) % 4), c);
        return dot(cross(e1, e2), normals[f]);
      };
      const Vec3 c = mesh.vertices[q[corner]];
      const double scale = norm(sub(mesh.vertices[q[(corner + 1) % 4]], c)) *
                           norm(sub(mesh.vertices[q[(corner + 3) % 4]], c));
      if (scale == 0) continue;
      const double v0 = value(at);
      area.push_back({v0 / scale, (value(along(at, 1, t1)) - v0) / scale,
                      (value(along(at, 1, t2)) - v0) / scale});
    }
  }
  if (area.empty()) return std::nullopt;
  // The disk as 16 half-planes gx·x + gy·y ≤ radius·cos(π/16) (hard constraints).
  constexpr int kSides = 16;
  std::vector<Linear> disk;
  for (int i = 0; i < kSides; ++i) {
    const double angle = 2 * std::numbers::pi * i / kSides;
    disk.push_back({radius * std::cos(std::numbers::pi / kSides), -std::cos(angle),
                    -std::sin(angle)});  // ≥ 0 inside
  }
  const auto objective = [&](double x, double y) {
    double worst = std::numeric_limits<double>::infinity();
    for (const Linear& a : area) worst = std::min(worst, a.at(x, y));
    return worst;
  };
  const auto inside = [&](double x, double y) {
    for (const Linear& d : disk)
      if (d.at(x, y) < -1e-9 * radius) return false;
    return true;
  };
  // The LP's optimum is a vertex of the arrangement: where three objectives are equal, two
  // are equal on a side of the disk, or one meets a corner of the disk. Enumerate them all
  // (a vertex has at most ~20 corners, so a few thousand small solves).
  double best_value = objective(0, 0), best_x = 0, best_y = 0;
  const auto consider = [&](double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y) || !inside(x, y)) return;
    const double value = objective(x, y);
    if (value > best_value) best_value = value, best_x = x, best_y = y;
  };
  const auto solve2 = [&](double a, double b, double c, double d, double e, double f) {
    // a·x + b·y = e, c·x + d·y = f.
    const double det = a * d - b * c;
    if (std::abs(det) < 1e-300) return;
    consider((e * d - b * f) / det, (a * f - e * c) / det);
  };
  const int n = static_cast<int>(area.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      // area_i = area_j, and area_j = area_k or a disk side active.
      const Linear& a = area[i];
      const Linear& b = area[j];
      for (int k = j + 1; k < n; ++k) {
        const Linear& c = area[k];
        solve2(a.gx - b.gx, a.gy - b.gy, b.gx - c.gx, b.gy - c.gy, b.c - a.c, c.c - b.c);
      }
      for (const Linear& d : disk) solve2(a.gx - b.gx, a.gy - b.gy, d.gx, d.gy, b.c - a.c, -d.c);
    }
  for (int s = 0; s < kSides; ++s) {
    const Linear& d = disk[s];
    const Linear& e = disk[(s + 1) % kSides];
    solve2(d.gx, d.gy, e.gx, e.gy, -d.c, -e.c);  // the 16-gon's corners
  }
  if (best_x == 0 && best_y == 0) return std::nullopt;
  return along(along(at, best_x, t1), best_y, t2);
}

std::array<double, 3> descend_in_tangent_plane(
    const std::function<double(const std::array<double, 3>&)>& energy,
    const std::array<double, 3>& at, const std::array<double, 3>& t1,
    const std::array<double, 3>& t2, double length, int iterations) {
  const auto point = [&](double x, double y) { return along(along(at, x, t1), y, t2); };
  const auto e = [&](double x, double y) { return energy(point(x, y)); };
  double x = 0, y = 0, value = e(0, 0);
  if (!std::isfinite(value)) return at;
  const double h = 1e-4 * length;
  for (int it = 0; it < iterations; ++it) {
    const double xp = e(x + h, y), xm = e(x - h, y), yp = e(x, y + h), ym = e(x, y - h);
    if (!std::isfinite(xp + xm + yp + ym)) break;
    const double gx = (xp - xm) / (2 * h), gy = (yp - ym) / (2 * h);
    const double hxx = (xp - 2 * value + xm) / (h * h), hyy = (yp - 2 * value + ym) / (h * h);
    const double hxy =
        (e(x + h, y + h) - e(x + h, y - h) - e(x - h, y + h) + e(x - h, y - h)) / (4 * h * h);
    const double det = hxx * hyy - hxy * hxy;
    double sx, sy;
    if (std::isfinite(det) && hxx > 0 && det > 0) {
      sx = -(hyy * gx - hxy * gy) / det, sy = -(hxx * gy - hxy * gx) / det;
    } else {
      const double g = std::hypot(gx, gy);
      if (!(g > 0)) break;
      sx = -gx / g * length / 2, sy = -gy / g * length / 2;
    }
    const double s = std::hypot(sx, sy);
    if (!(s > 0)) break;
    if (s > length / 2) sx *= length / 2 / s, sy *= length / 2 / s;
    bool moved = false;
    for (double t = 1; t > 1e-3; t /= 2) {
      const double trial = e(x + t * sx, y + t * sy);
      if (trial < value) {
        x += t * sx, y += t * sy, value = trial, moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return point(x, y);
}

double untangling_energy(const QuadMesh& mesh, const std::array<int, 4>& quad,
                         const std::array<double, 3>& normal, double delta) {
  double energy = 0;
  for (int a = 0; a < 4; ++a) {
    const Vec3& c = mesh.vertices[quad[a]];
    const Vec3 e1 = sub(mesh.vertices[quad[(a + 1) % 4]], c);
    const Vec3 e2 = sub(mesh.vertices[quad[(a + 3) % 4]], c);
    const double l1 = dot(e1, e1), l2 = dot(e2, e2);
    if (l1 == 0 || l2 == 0) return std::numeric_limits<double>::infinity();
    const double d = delta * std::sqrt(l1 * l2);
    const double det = dot(cross(e1, e2), normal);
    const double h2 = det + std::sqrt(det * det + 4 * d * d);  // 2·h(det)
    if (h2 <= 0) return std::numeric_limits<double>::infinity();
    energy += (l1 + l2) / h2;
  }
  return energy;
}

}  // namespace bimdf::detail
