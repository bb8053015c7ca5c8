// Shape of one quad in space (metrics.hpp states the conventions).
#pragma once

#include <array>

#include "bimdf/mesh.hpp"

namespace bimdf::detail {

// The mean of the quad's four corners.
std::array<double, 3> quad_centre(const QuadMesh& mesh, const std::array<int, 4>& quad);

// Newell's normal of the quad (not normalized): robust for non-planar quads.
std::array<double, 3> newell_normal(const QuadMesh& mesh, const std::array<int, 4>& quad);

// The minimum over the corners of sin(corner angle), signed by the Newell normal: 1 for a
// rectangle, ≤ 0 for a degenerate, concave or folded corner.
double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& quad);

// The same, signed by a given unit `normal` (e.g. the surface's) instead of the quad's own:
// negative also when the whole quad faces the other way.
double scaled_jacobian(const QuadMesh& mesh, const std::array<int, 4>& quad,
                       const std::array<double, 3>& normal);

// The shortest distance between two of the quad's corners (its edges and diagonals) over its
// longest edge: 1 for a square's edges… 0 when two corners coincide. The scaled Jacobian only
// sees angles, which stay finite (and meaningless) as an edge shrinks to nothing.
double corner_spread(const QuadMesh& mesh, const std::array<int, 4>& quad);

// The three measures above at once, for smoothing, which rates every candidate position by
// them: own = scaled_jacobian(mesh, quad), under = scaled_jacobian(mesh, quad, normal),
// spread = corner_spread(mesh, quad). One pass shares the edge vectors and cross products.
struct QuadShape {
  double own, under, spread;
};
QuadShape quad_shape(const QuadMesh& mesh, const std::array<int, 4>& quad,
                     const std::array<double, 3>& normal);

// Degenerate (metrics.hpp): a scaled Jacobian of exactly 0, or two corners closer than
// kDegenerateSpread of the longest edge, or a Newell normal shorter than kDegenerateArea times
// the sum of the squared edges (a square: 1/2) — all four corners on one line, as a quad
// squeezed along a feature curve (eight's remesh had one, its edges 2·10⁻⁵–2·10⁻⁴ long on one
// line, that passed as a scaled Jacobian of ±10⁻¹⁵). There the corner angles are rounding
// noise.
constexpr double kDegenerateSpread = 1e-6;
constexpr double kDegenerateArea = 1e-9;
bool degenerate(const QuadMesh& mesh, const std::array<int, 4>& quad);

}  // namespace bimdf::detail
