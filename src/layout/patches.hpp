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
  std::vector<bool> not_disk;  // per patch: its problem is its topology (not a disk, pinched)
  // Patches whose sharp turns were fewer than 3 or more than 6, given their 3 (or 6) sharpest.
  int adjusted = 0;
};

// What decides corners, per vertex of the mesh being labelled.
struct CornerHints {
  // Quarter turns the cross field makes around the vertex: 4 − its quarter index inside the
  // mesh, 2 − it on the border (a straight border 2, a right-angled corner 1).
  std::vector<int> field_quarters;
  // The edge by which the one trace ending here arrives, where it ends on a line that goes on
  // (a T-junction: the two patches beside that edge have a corner here, the one across the
  // line has none, whatever the angles); −1 elsewhere.
  std::vector<int> ending_edge;
  // Per half-edge h (when not empty): the angle of h's face at h's origin in the parameter
  // plane the traces followed (seamless.hpp), in quarter turns. A sector's turn is then their
  // sum, which is exact where traces are iso-lines, instead of its share of the field's turns
  // (still used for a sector with a face folded or flat in the parameter plane, angle ≤ 0).
  std::vector<double> parameter_quarters;
  // Where > 0 (with parameter_quarters): an inner vertex's sector the map reads below 1.5
  // quarters, though its share of the field's turns is above this, is no corner — the map bends
  // there (near a cone, round a small hole), the surface does not. 0: the map decides.
  double flat_share = 0;
};

// Floods faces across every edge that is not a boundary (`boundary_edge` per edge of `top`:
// traces, feature curves; the mesh border bounds patches anyway). A patch has a corner at a
// boundary vertex where its sector there turns by at most one quarter of the field (the
// sector's share of the vertex's total angle, times the field's quarter turns around it,
// rounded), or beside a trace ending there (CornerHints). A patch with fewer than 3 or more
// than 6 corners gets its 3 (or 6) sharpest turns.
Patches label_patches(const SurfaceTopology& top, const std::vector<bool>& boundary_edge,
                      const CornerHints& hints);

// The last resort for patches that are not disks where seeding could not cut them
// (generate.cpp): in each, the shortest path of mesh edges through its inside from one of its
// boundary loops to another becomes a boundary (an annulus becomes a disk; a patch with more
// holes loses one per call). Its far end is marked as a trace ending there (`hints`). Returns
// how many paths were made; then label the patches again.
int cut_across_non_disks(const SurfaceTopology& top, const Patches& patches,
                         std::vector<bool>& boundary_edge, CornerHints& hints);

}  // namespace bimdf::layout
