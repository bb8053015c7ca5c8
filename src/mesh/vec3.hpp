// Small 3-vector arithmetic on std::array<double, 3>, shared by the geometry code (mesh.hpp
// stores positions in that type).
#pragma once

#include <array>
#include <cmath>

#include "bimdf/mesh.hpp"

namespace bimdf::detail {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
// a + t·d.
inline Vec3 along(const Vec3& a, double t, const Vec3& d) {
  return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
// a / |a|, or zero for the zero vector.
inline Vec3 normalized(const Vec3& a) {
  const double n = norm(a);
  return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 0};
}

// An orthonormal frame (t1, t2) of the plane with unit normal n, oriented so that t1 × t2 = n:
// counter-clockwise about n reads counter-clockwise in (t1, t2) coordinates. t1 is n × x̂, or
// n × ŷ where n is close to x̂.
inline std::array<Vec3, 2> plane_frame(const Vec3& n) {
  const Vec3 axis = std::fabs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 t1 = normalized(cross(n, axis));
  return {t1, cross(n, t1)};
}

// The (not normalized) normal of triangle f, counter-clockwise.
inline Vec3 triangle_normal(const TriangleMesh& mesh, int f) {
  const auto& t = mesh.faces[f];
  return cross(sub(mesh.vertices[t[1]], mesh.vertices[t[0]]),
               sub(mesh.vertices[t[2]], mesh.vertices[t[0]]));
}

}  // namespace bimdf::detail
