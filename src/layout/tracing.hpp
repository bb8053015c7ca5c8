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
// Tracing on per-face constant ways (FaceWays): inside a face a trace is a straight segment
// along one of the face's four ways; crossing an edge it takes the next face's way closest to
// its own transported across the edge. With a parametrization's ways that is its iso-line,
// exactly. Crossings within `snap` of a mesh vertex go through the vertex; at a vertex the trace
// continues along the way closest to straight on (half the vertex's total angle from where it
// came), into a face or along an edge.
//
// Pairing: separatrices that run into another singularity head on are traced once, from one
// to the other; if that trace stops before it gets there, the other singularity's separatrix
// it stood for is traced after all (no singularity loses a separatrix). Seeds pair the same
// way, but not with a seed beside them (passed more to the side than ahead).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "bimdf/layout/cross_field.hpp"
#include "layout/face_frames.hpp"
#include "layout/surface_point.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

// Per face, the angles (in the face's frame, FaceFrames::angle) of the four ways a trace may go
// in it: way k + 2 is opposite way k, way 1 about a quarter turn counter-clockwise from way 0.
// A cross field's ways are one angle plus k quarter turns; a parametrization's are its
// iso-lines' directions ±∂x/∂u, ±∂x/∂v, which need not be orthogonal.
using FaceWays = std::vector<std::array<double, 4>>;

// The ways of per-face direction pairs (way 0, way 1), e.g. (d, n × d) for a cross field's
// direction d, or SeamlessMap::iso_direction.
FaceWays face_ways(const FaceFrames& frames,
                   const std::vector<std::array<detail::Vec3, 2>>& directions);

struct TraceOptions {
  // Edge crossings closer than this fraction of the edge's length to an end go through that
  // vertex instead. In [0, 0.5).
  double snap = 1e-4;
  // A trace longer than this many bounding-box diagonals stops unfinished (a streamline that
  // winds around a handle without meeting anything).
  double max_length = 4;
  // Pair separatrices that run into another singularity head on (tracing.cpp,
  // pair_separatrices): within this many average edge lengths of it, and against one of its
  // own separatrices by less than ~30°.
  bool pair_singularities = true;
  double approach_radius = 1;
  // Within this many approach radii of its target a paired trace steers onto the target's
  // separatrix, aiming `steer_lead` × (distance left) ahead of the target along it; 0: it
  // steps straight onto the target from the first face next to it.
  double steer_radius = 3;
  double steer_lead = 0.3;
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
  int start_ways = 0;  // how many ways its start vertex has (consecutive ways: ±1 modulo this)
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
                                       const FaceWays& ways, const std::vector<int>& quarter_index,
                                       const std::vector<bool>& curve_edge,
                                       const TraceOptions& options);

}  // namespace bimdf::layout
