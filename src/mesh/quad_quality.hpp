// Shape of one quad in space (metrics.hpp states the conventions).
#pragma once

#include <array>

#include "bimdf/mesh.hpp"

namespace bimdf::detail {

// Newell's normal of the quad (not normalized): robust for non-planar quads.
std::array<double, 3> newell_normal(const QuadMesh& mesh, const std::array<int, 4>& quad);

// The minimum over the corners of sin(corner angle), signed by the Newell normal: 1 for a
// rectangle, ≤ 0 for a degenerate, concave or folded corner.
double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& quad);

}  // namespace bimdf::detail
