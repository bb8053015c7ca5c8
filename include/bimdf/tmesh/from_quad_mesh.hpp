// A quadrangular T-mesh from an all-quad mesh (issue 21, paper §4.1): its motorcycle graph.
//
// Seeds are the mesh's *special* vertices: irregular vertices (interior valence ≠ 4, border
// valence ≠ 3), border corners, and feature corners (ends of feature curves, and vertices where
// a curve turns or where more than two curve edges meet). Feature curves are the mesh edges
// whose dihedral angle exceeds `sharp_angle_deg`, plus those given (a QuadWild-style
// `.feature` file). From every seed, a trace leaves along every mesh edge that is not on the
// border or a feature curve and goes straight on (the opposite edge at a regular vertex). All
// traces advance one edge per step together; a trace stops at the first vertex that is already
// on a trace, the border or a feature curve (motorcycle graph). The traced edges, the border
// and the feature curves cut the faces into rectangles of the grid — the T-mesh's patches — and
// their chains between T-mesh vertices are its arcs.
//
// Regions that are not rectangles of the grid with distinct vertices (annuli, rings crossed by
// one trace) are cut across (TracedTMesh::cylinder_cuts); a closed component without seeds,
// border or feature is refused.
//
// The *extended* motorcycle graph (Lyon et al. 2021) lets traces continue through collisions
// until they reach the border, a feature curve or a seed (or repeat an edge); it is where the
// non-zero paths come from (see trace_tmesh).
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

struct TraceOptions {
  // Edges whose dihedral angle (between the two quads' normals) exceeds this many degrees are
  // feature edges; ≥ 180 turns detection off.
  double sharp_angle_deg = 35;
  // Feature edges given by the user (mesh vertex pairs), in addition to the sharp ones.
  std::vector<std::array<int, 2>> feature_edges;
  // Each arc's target length: its number of mesh edges times this.
  double density = 1;
  // < 0: the plain motorcycle graph, with one non-zero path per trace (to where it stopped)
  // and per border or feature curve piece. ≥ 0: Lyon et al.'s angle-bounded extended graph
  // instead (src/tmesh/angle_bounded.hpp): traces run through collisions and across feature
  // curves until they have crossed, on each side, a trace whose seed lies within this angle
  // (≥ 90: until the border or a seed), and the non-zero paths keep every seed from sliding
  // onto another's separatrix at a deviation above the angle, and feature curves apart where
  // a trace crosses between them — the T-mesh of `requantize --coarse`.
  double max_angle_deg = -1;
  // With max_angle_deg ≥ 0: whether the traces go on across feature curves (true) or end where
  // they reach one (src/tmesh/angle_bounded.hpp; requantize's FeatureTraces chooses).
  bool cross_features = true;
};

struct TracedTMesh {
  TMesh tmesh;  // with vertex_mesh_vertex, arc_chain, arc_feature, patch_grid and nonzero_paths
  std::vector<std::array<int, 2>> feature_edges;  // every feature edge (sharp and given)
  std::vector<int> feature_corners;               // mesh vertices
  std::vector<int> seeds;                         // mesh vertices that emitted traces
  int traces = 0;                                 // traces started
  int crossings = 0;                              // trace crossings (angle-bounded graph only)
  // Angle-bounded graph only: "cross" when traces went on across feature curves, "stop" when
  // they ended there (TraceOptions::cross_features); "" for the plain motorcycle graph.
  std::string feature_traces;
  int extended_trace_edges = 0;                   // mesh edges on extended traces (diagnostics)

  // Trace i, as the mesh vertices it runs through (its seed first), in the motorcycle graph
  // and in the extended one; both in emission order (seeds ascending, then each seed's edges
  // counter-clockwise), so trace i is the same trace in both.
  std::vector<std::vector<int>> trace_vertices;
  std::vector<std::vector<int>> extended_trace_vertices;
  // Per entry of tmesh.nonzero_paths: the trace it was made from, −1 for a cylinder half-loop,
  // −2 for a border or feature curve piece between two seeds, −3 for a piece of a trace
  // between two curves it reaches (angle-bounded graph only).
  std::vector<int> nonzero_path_trace;

  // Completion cuts. Two kinds of region of the motorcycle graph are not rectangles with
  // distinct vertices: an annulus between two closed border curves without corners (a tube
  // between two feature loops, an open cylinder) and a ring crossed by a single trace (a
  // rectangle glued to itself). Extra traces along grid lines cut them: an annulus across
  // from two vertices of one of its curves (the one of smallest id and the one half-way round;
  // if both curves share vertices, as on a torus cut by one loop, the closed grid line
  // half-way across is cut first), a ring across between the two places where it meets
  // itself. They are the last `cylinder_cuts` entries of trace_vertices (and, unchanged, of
  // extended_trace_vertices), counted in `traces`; their starts are not in `seeds`. Per
  // annulus, `cylinder_half_loops` holds the mesh vertices along the cut curve from the first
  // cut to the second, a non-zero path (so that the curve cannot collapse to a point).
  int cylinder_cuts = 0;
  std::vector<std::vector<int>> cylinder_half_loops;
};

// Builds the T-mesh of `mesh` (all quads, manifold, consistently oriented). T-mesh vertices
// are the seeds and the mesh vertices where the cut edges (traces, border, features) do not
// just pass straight on, in mesh vertex order; arcs are the chains of cut edges between them;
// patches are the regions in order of their smallest quad, corner 0 at their corner of
// smallest mesh vertex id. Non-zero paths (M1): one per trace, along the half-arcs it ran on
// from its seed to where it stopped (an arc it only partly ran on counts whole), plus the
// cylinder half-loops. The result passes validate_tmesh. Throws InputError
// naming `source` and the face, edge or vertex for a non-manifold or inconsistently oriented
// mesh, an empty mesh, a degenerate quad (repeated vertex), a feature edge that is not a mesh
// edge, and a closed mesh without seeds ("has no irregular vertex, border or feature: its grid
// lines close on themselves, so there is no layout to quantize").
TracedTMesh trace_tmesh(const QuadMesh& mesh, const TraceOptions& options,
                        const std::string& source);

// The half-arcs a chain of mesh vertices runs along, for each chain: every arc it touches,
// once and in order, as the half-arc in the chain's direction (an arc the chain only partly
// covers counts whole). `tmesh` must have arc chains (made by trace_tmesh); consecutive chain
// vertices must be the ends of an edge on an arc, else std::invalid_argument. This is how the
// non-zero paths are made from the traces.
std::vector<std::vector<int>> half_arcs_along(const TMesh& tmesh,
                                              const std::vector<std::vector<int>>& chains);

// Reads a QuadWild-style feature file for a quad mesh: a count N, then N lines `face,edge`
// (0-based quad id, edge 0..3 = from corner e to corner e+1). Returns mesh vertex pairs. Throws
// InputError naming the file and line.
std::vector<std::array<int, 2>> read_quad_feature_file(const std::string& path,
                                                       const QuadMesh& mesh);

// Writes `edges` (mesh vertex pairs) in the format read_quad_feature_file reads: the count, then
// per edge `face,edge` of the lowest quad that has it. Throws std::invalid_argument naming the
// first pair that is no edge of `mesh`.
void write_quad_feature_file(std::ostream& out, const QuadMesh& mesh,
                             const std::vector<std::array<int, 2>>& edges);

}  // namespace bimdf::tmesh
