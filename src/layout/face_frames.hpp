// Per-face tangent frames of a triangle mesh, and angles of tangent vectors in them: the
// coordinates in which the cross field stores, compares and transports its crosses
// (cross_field.hpp) and in which tracing walks across faces.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "bimdf/mesh.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::layout {

struct FaceFrames {
  // Per face: e1 along its first edge, e2 = n × e1, unit normal n (counter-clockwise).
  std::vector<detail::Vec3> e1, e2, normal;
  std::vector<double> area;
  std::vector<detail::Vec3> centroid;

  explicit FaceFrames(const TriangleMesh& mesh);

  // The angle of tangent vector d in face f's frame.
  double angle(int f, const detail::Vec3& d) const {
    return std::atan2(detail::dot(d, e2[f]), detail::dot(d, e1[f]));
  }
  // The unit vector of angle a in face f's frame.
  detail::Vec3 direction(int f, double a) const {
    const double c = std::cos(a), s = std::sin(a);
    return {c * e1[f][0] + s * e2[f][0], c * e1[f][1] + s * e2[f][1], c * e1[f][2] + s * e2[f][2]};
  }
};

// x reduced modulo π/2 into [−π/4, π/4]: how far apart two crosses are.
inline double cross_difference(double x) { return x - (M_PI / 2) * std::round(x / (M_PI / 2)); }

}  // namespace bimdf::layout
