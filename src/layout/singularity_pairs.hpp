// Close pairs of opposite field singularities, cancelled in the parametrization (issue 51).
//
// A cross field's singularities come in whatever number its smoothness energy and constraints
// leave; near jagged feature curves and fine surface noise it leaves ± pairs (a valence-3 and
// a valence-5 vertex) closer together than one quad. Every one of them becomes a singular
// vertex of the quad mesh, with the separatrices, T-junctions and slivers it brings, although
// a regular grid, slightly distorted over the pair's few triangles, fits the surface as well at
// that scale. The pair cannot be removed from the field without changing it elsewhere, but it
// can from the parametrization: the map's cones come from the matchings, the quarter turns
// relating neighbouring faces' crosses, and adding ∓1 quarter to the matching of every edge
// on a path from one singularity to the other moves one quarter of index along the path —
// both ends get index 0, the vertices in between keep theirs (each path edge takes a quarter
// from one end and gives it to the other). The map then follows the field everywhere but on
// the path's few faces. (Bommes et al. 2009 place singularities by the same means, with the
// matchings as integer unknowns; here only the pairs below the quad size are touched.)
#pragma once

#include <array>
#include <vector>

#include "bimdf/layout/cross_field.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

struct CancelledPairs {
  // Per edge of the surface: quarter turns to add to the field's matching across it (0 on
  // most), in the orientation of the edge's first half-edge (SurfaceTopology::edge_half_edge):
  // what field_indices and SeamlessOptions::matching_offset take.
  std::vector<int> matching_offset;
  std::vector<std::array<int, 2>> pairs;  // the cancelled pairs' vertices (index +1, index −1)
};

// Cancels pairs of interior singularities of quarter index +1 and −1 (`indices`, from
// field_indices) that lie within `radius` of each other (Euclidean, in the mesh's units), the
// closest pairs first, each vertex in one pair at most. A pair is cancelled along the shortest
// path of interior mesh edges between them whose vertices all lie inside the mesh (not on its
// border) and within 2 × `radius` of the first; vertices where `keep` is true (e.g. on feature
// curves, where the curve's own turning puts the singularity) are left alone. radius ≤ 0:
// nothing is cancelled.
CancelledPairs cancel_close_pairs(const SurfaceTopology& top, const FieldIndices& indices,
                                  const std::vector<bool>& keep, double radius);

}  // namespace bimdf::layout
