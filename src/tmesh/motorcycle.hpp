// Feature curves, seeds and motorcycle graphs of an all-quad mesh (internal to src/tmesh; the
// rules are those of include/bimdf/tmesh/from_quad_mesh.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "tmesh/quad_mesh_topology.hpp"

namespace bimdf::tmesh::detail {

// One flag per mesh edge: 1 if the dihedral angle between its two quads' normals exceeds
// `sharp_angle_deg` (border edges never do; a quad with a zero normal makes no edge sharp), or
// if it is one of `given` (vertex pairs). Throws InputError naming `source` and the index in
// `given` of a pair that is not a mesh edge.
std::vector<uint8_t> detect_feature_edges(const QuadMesh& mesh, const QuadMeshTopology& topo,
                                          double sharp_angle_deg,
                                          const std::vector<std::array<int, 2>>& given,
                                          const std::string& source);

// Feature corners: vertices with feature edges, except where exactly two meet and continue
// each other straight on (QuadMeshTopology::straight_on). Ascending.
std::vector<int> feature_corners(const QuadMeshTopology& topo,
                                 const std::vector<uint8_t>& feature_edge);

// Seeds: used vertices that are irregular (interior valence ≠ 4, border valence ≠ 3, which
// includes the border corners) or feature corners. Ascending.
std::vector<int> seed_vertices(const QuadMeshTopology& topo,
                               const std::vector<uint8_t>& feature_edge);

// A trace: the mesh vertices it runs through, its seed first, and the edges between them
// (vertices.size() == edges.size() + 1). A trace blocked on its first edge has no edge.
struct Trace {
  int seed = -1;
  std::vector<int> vertices;
  std::vector<int> edges;
};

struct MotorcycleGraph {
  // In emission order: seeds ascending, and at each seed its edges counter-clockwise from the
  // start of its ring (QuadMeshTopology); one trace per edge that is not border or feature.
  std::vector<Trace> traces;
  std::vector<uint8_t> cut;     // per mesh edge: on a trace, the border or a feature curve
  std::vector<int> edge_trace;  // per mesh edge: the trace that cut it, or −1
};

// The motorcycle graph. All traces advance one edge per step, in emission order within a
// step. A trace first checks its next edge: if it is already cut (another trace came the other
// way along it), it stops without it. Otherwise it cuts the edge and moves to its far vertex;
// if that vertex is already on the graph (a seed, the border, a feature curve, or a trace
// that got there first — in this step or before), it stops there; else it marks the vertex
// and goes straight on. Unmarked vertices are regular and interior, so straight on is always
// defined, and every step cuts an edge or stops a trace, so this ends after at most
// (edges + traces) moves.
MotorcycleGraph trace_motorcycle_graph(const QuadMeshTopology& topo,
                                       const std::vector<uint8_t>& feature_edge,
                                       const std::vector<int>& seeds);

// The extended motorcycle graph (Lyon et al. 2021): the same traces, in the same order, each
// going straight on regardless of the others until it reaches the border, a feature curve or
// a seed, or until its next step would repeat a directed edge it has already taken (a grid
// line closing on itself). With `cross_features`, traces go straight across feature curves
// (a vertex on a curve that is not a seed is regular, and the curve passes through it
// straight on, so the trace's way on is the other edge off the curve) and stop only at the
// border and seeds. Each trace is at most 2·edges long.
std::vector<Trace> trace_extended_motorcycle_graph(const QuadMeshTopology& topo,
                                                   const std::vector<uint8_t>& feature_edge,
                                                   const std::vector<int>& seeds,
                                                   bool cross_features = false);

// Extra cuts that leave every region of the graph a rectangle whose grid vertices are
// distinct (from_quad_mesh.hpp, TracedTMesh::cylinder_cuts), added to `cut`:
//   * an annulus (a region between two closed border curves without corners: a tube between
//     feature loops, an open cylinder) is cut across along grid lines from two vertices of one
//     curve (the one of smallest id, and the one half-way round); when its two curves share
//     vertices (a torus cut by one loop), the closed grid line half-way across is cut first;
//   * a rectangle that meets itself (a ring crossed by a single trace: its grid holds a
//     vertex twice) is cut across between the two positions.
// Rounds repeat until nothing changes. Other regions are left for the caller's rectangle
// check (region_rectangle may throw here already, with the same message).
struct CompletionCuts {
  std::vector<std::vector<int>> traces;      // mesh vertices, from border to border
  std::vector<std::vector<int>> half_loops;  // per annulus: its curve from cut to cut
};
CompletionCuts complete_to_rectangles(const QuadMeshTopology& topo, std::vector<uint8_t>& cut,
                                      const std::string& source);

}  // namespace bimdf::tmesh::detail
