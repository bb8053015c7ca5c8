// The conformity check of collapse_and_tessellate (internal to src/tmesh, used by
// collapse.cpp; tmesh/collapse.hpp describes the rules and messages). Zero arcs and
// zero-width patches identify points, and an identification can break the mesh even when the
// quantization is valid; so before returning it, collapse checks the finished mesh: every
// quad has four distinct corners, every edge at most two quads walking it in opposite
// directions, every vertex one fan of quads, and no merged point becomes an interior vertex of
// only two quads (they would fold onto each other). It throws CollapseError naming the patch,
// grid cell or vertex instead of returning a non-conforming mesh.
#pragma once

#include <array>
#include <vector>

#include "bimdf/tmesh/collapse.hpp"

namespace bimdf::tmesh::detail {

// Checks result.mesh, naming its vertices by result.origin. `quad_cell` is per quad its grid
// cell (i, j), or (f, -1) for pattern quad f of an irregular patch; `class_size` per output
// vertex the number of points merged into it.
void check_result(const CollapsedMesh& result, const std::vector<std::array<int, 2>>& quad_cell,
                  const std::vector<int>& class_size);

}  // namespace bimdf::tmesh::detail
