// Patches of a cut mesh (issue 51, item 4): the regions its traces and feature curves leave,
// and each patch's corners — what QuadWild's `.patch` and `.corners` files hold.
#pragma once

#include <string>
#include <vector>

#include "layout/surface_topology.hpp"

namespace bimdf::layout {

struct Patches {
  std::vector<int> face_patch;            // per face
  std::vector<std::vector<int>> corners;  // per patch, its corner vertices (any order)
  // Per patch: why it cannot be a chart of the layout ("" if it can): not a disk.
  std::vector<std::string> problem;
  // Patches whose sharp turns were fewer than 3 or more than 6, given their 3 (or 6) sharpest.
  int adjusted = 0;
};

// Floods faces across every edge that is not a boundary (`boundary_edge` per edge of `top`:
// traces, feature curves; the mesh border bounds patches anyway). A boundary vertex is a corner
// of a patch where the patch's angle there (inside the mesh scaled to a flat vertex's 2π) is
// below 135°: a right angle or a singularity's sector, not a straight side. A patch
// with fewer than 3 or more than 6 such turns gets its 3 (or 6) sharpest.
Patches label_patches(const SurfaceTopology& top, const std::vector<bool>& boundary_edge);

}  // namespace bimdf::layout
