// Refining a triangle mesh so that given polylines on its surface (traced separatrices) run
// along its edges: the step between tracing and patches (issue 51, item 4). QuadWild's tracer
// does the same before it labels patches: a layout's patch borders must be mesh edges.
//
// Each polyline is a sequence of SurfacePoints in which every two consecutive points lie in one
// common face of the input mesh (the segment between them is a straight chord of that face, or
// runs along one of its edges). Polylines do not cross one another; they may share points
// (their ends, e.g. a singular vertex where several start) and a polyline may end on another
// one's segment — a T-junction — at a point that is not one of the other's points (it is then
// inserted into the other's segment as well).
//
// The refinement inserts a vertex at every distinct polyline point that is not a mesh vertex
// (points with equal kind and id and with t or barycentric coordinates equal within 1e-9 are
// one point), then re-triangulates every face that a segment crosses or touches, so that every
// segment becomes a chain of mesh edges (a segment through another polyline's point is split
// there). Faces no segment enters are kept as they are.
#pragma once

#include <vector>

#include "bimdf/mesh.hpp"
#include "layout/surface_point.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

struct CutMesh {
  // The refined mesh: the input's vertices first, in their order and unchanged, then the
  // inserted ones; faces oriented as the faces they came from. No face has zero area.
  TriangleMesh mesh;
  std::vector<int> parent_face;  // per face of `mesh`: the input face it lies in
  // Per polyline: the vertex ids of `mesh` it now runs through, in order, including every
  // point where another polyline ends on it (so consecutive ids are joined by a mesh edge).
  std::vector<std::vector<int>> polyline_vertices;
};

// Throws std::logic_error (an internal error: the tracer broke its promises) if two
// consecutive points of a polyline share no face, or if segments cross.
CutMesh cut_along_polylines(const SurfaceTopology& top,
                            const std::vector<std::vector<SurfacePoint>>& polylines);

}  // namespace bimdf::layout
