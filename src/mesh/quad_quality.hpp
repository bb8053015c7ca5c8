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

// The same, signed by a given unit `normal` (e.g. the surface's) instead of the quad's own:
// negative also when the whole quad faces the other way.
double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& quad,
                       const std::array<double, 3>& normal);

}  // namespace bimdf::detail
