// Tessellating an irregular patch of a relaxed quantization (internal to src/tmesh, used by
// collapse.cpp; tmesh/collapse.hpp describes the result).
//
// A patch whose opposite sides differ gets make_quad_pattern(X0, X1, X2, X3) (quant/
// pattern.hpp). The pattern's boundary is counter-clockwise from its corner 0 and its side j
// runs from corner j to corner j+1 — exactly how a T-mesh patch's sides are walked (patch on
// the left, side k from corner k to corner k+1) — so boundary vertex X0 + … + X(k−1) + s is
// the point at position s of side k, and the pattern's quads, counter-clockwise like its
// boundary, come out oriented like the patch's grid quads.
//
// The pattern's interior vertices are placed by Tutte's embedding (each at the mean of its
// neighbours) with the boundary fixed where the patch's side points are: in the patch grid's
// (u, v) coordinates when the T-mesh has grids — the patch is a rectangle there, a convex
// domain, so the embedding has no fold-overs for a 3-connected pattern — and then evaluated
// bilinearly on the input quad that (u, v) falls in, like a regular patch's grid points;
// without grids, in 3D. The pattern's own positions are not used: its polygon is a cyclic
// polygon with evenly spaced boundary vertices, while the side points are spaced along the
// arcs' chains, and a map between the two would not keep the boundary where it is.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/quant/pattern.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh::detail {

// "" when a patch with these side lengths can be tessellated (every side ≥ 1, even
// perimeter), else why not ("sides 3, 1, 2, 1: the perimeter 7 is odd").
std::string irregular_sides_issue(const std::array<int64_t, 4>& sides);

// The pattern of such a patch (sides must pass irregular_sides_issue).
quant::QuadPattern irregular_pattern(const std::array<int64_t, 4>& sides);

// Per pattern vertex, its point: boundary vertices from `side_points` (side k's points by
// position 0…X_k, as collapse numbers them), interior vertices first_interior, first_interior
// + 1, … in pattern order.
std::vector<int> pattern_points(const quant::QuadPattern& pattern,
                                const std::array<std::vector<int>, 4>& side_points,
                                int first_interior);

// Tutte's embedding of the pattern's interior vertices, given every boundary vertex's position
// (P = perimeter entries): one position per interior vertex, in pattern order.
std::vector<std::array<double, 3>> tutte_interior(
    const quant::QuadPattern& pattern, const std::vector<std::array<double, 3>>& boundary);

// The pattern's interior vertices placed as the header explains, in pattern order: Tutte's
// embedding with boundary vertex b at boundary[b] — a 3D position, or, given `mesh` and
// `grid`, a grid coordinate (u, v, 0) whose embedding is then evaluated by point_on_grid.
std::vector<std::array<double, 3>> place_pattern_interior(
    const quant::QuadPattern& pattern, const std::vector<std::array<double, 3>>& boundary,
    const QuadMesh* mesh, const PatchGrid* grid);

// The point of the input mesh at grid coordinate (u, v) of a patch grid (clamped to it):
// bilinear on the grid cell it falls in.
std::array<double, 3> point_on_grid(const QuadMesh& mesh, const PatchGrid& grid,
                                    std::array<double, 2> uv);

}  // namespace bimdf::tmesh::detail
