// Separatrices of a cross field traced as a motorcycle graph on a triangle mesh (issue 51,
// item 4): from every singularity and every concave or dangling feature corner, along the
// field, each trace stopping where it meets a feature curve, the border, a singularity or a
// trace already drawn. Every region the traces and curves leave is then (ideally) a disk with
// four corners: a quad patch of a T-mesh, its T-junctions where traces end on others.
//
// Why a motorcycle graph: it needs no choice among candidate paths (QuadWild's selection),
// every trace ends by construction, and the patches are quads, so the layout's only
// singularities are the field's; our quantizer then chooses the lengths. The graph is traced in
// lockstep — always advancing the shortest trace — so that which of two traces stops at the
// other does not depend on the order they were started in.
//
// Tracing on a per-face constant field: inside a face a trace is a straight segment along one
// of the face's four directions; crossing an edge it takes the next face's direction closest to
// its own transported across the edge. Crossings within `snap` of a mesh vertex go through the
// vertex (no slivers for the cut); at a vertex the trace continues along the field direction
// closest to straight on (half the vertex's total angle from where it came), into a face or
// along an edge.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "bimdf/layout/cross_field.hpp"
#include "layout/face_frames.hpp"
#include "layout/surface_point.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

struct TraceOptions {
  // Edge crossings closer than this fraction of the edge's length to an end go through that
  // vertex instead. In [0, 0.5).
  double snap = 0.1;
  // A trace longer than this many bounding-box diagonals stops unfinished (a streamline that
  // winds around a handle without meeting anything).
  double max_length = 4;
  // Pair separatrices that run into another singularity head on (tracing.cpp,
  // pair_separatrices): within this many average edge lengths of it, and against one of its
  // own separatrices by less than ~30°.
  bool pair_singularities = true;
  double approach_radius = 1;
  // Regular interior vertices to trace all four directions from, as if they were singular:
  // what cuts a patch that the separatrices left as an annulus or worse (generate.cpp).
  std::vector<int> seeds;
  // Separatrices not to trace: (start vertex, way), as Trace::start_vertex, start_way number
  // them (the numbering depends only on the mesh, the field and the seeds).
  std::vector<std::array<int, 2>> banned;
};

struct Trace {
  enum class End { Curve, Trace, Singularity, Unfinished };
  std::vector<SurfacePoint> points;  // from its start vertex to its end
  int start_vertex = -1;
  int start_way = -1;  // which of its start vertex's ways (TraceOptions::banned numbering)
  End end = End::Unfinished;
  // End::Trace, End::Curve: the angle between its last piece and the line it stopped at (0 to
  // π/2). Near 0 it ran into a line of its own family: the two are one line of the layout, and
  // the wedge between them would be a patch with a cusp.
  double end_angle = M_PI / 2;
  int end_trace = -1;  // End::Trace: the trace it stopped at (itself for a loop)
  double length = 0;
};

struct MotorcycleGraph {
  std::vector<Trace> traces;
  int starts = 0;  // vertices traces started from
};

// Where separatrices start, from the field's indices and the curve edges (features and border,
// per edge of `top`); the traces' ends. `quarter_index` per vertex (field_indices).
MotorcycleGraph trace_motorcycle_graph(const SurfaceTopology& top, const FaceFrames& frames,
                                       const CrossField& field,
                                       const std::vector<int>& quarter_index,
                                       const std::vector<bool>& curve_edge,
                                       const TraceOptions& options);

}  // namespace bimdf::layout
