// The angle-bounded extended motorcycle graph and its non-zero paths (internal to src/tmesh):
// the T-mesh of `bimdf requantize --coarse [--max-angle DEG]`, after Lyon, Campen and Kobbelt
// 2021, "Quad Layouts via Constrained T-Mesh Quantization" (ATQ).
//
// Source note: ATQ's own text was not available to us. The rules below follow a second-hand
// description of a reimplementation, completed where it was silent (marked "ours"); the
// construction may differ from the paper's in details. What it must guarantee, it does by
// construction: the cut cuts the mesh into rectangles (up to the annuli and self-meeting rings
// that complete_to_rectangles handles), the result does not depend on the order of the seeds,
// and every non-zero chain is a straight chain of cut edges from a seed.
//
// Traces. From every seed along every edge that is neither border nor feature (the traces of
// trace_extended_motorcycle_graph, in the same emission order), each going straight on through
// collisions and — with `cross_features` (ours) — across feature curves, until it reaches the
// border or a seed, or would repeat a directed edge — or until the angle rule stops it. Without
// `cross_features` a trace also ends where it reaches a feature curve (Lyon et al.'s rule, as
// far as we know it: features are arcs that traces end on). Crossing keeps a separatrix in the
// T-mesh on both sides, so a coarsening cannot bend it onto another singularity there (which
// grew a cylinder-like part's base complex from 6 to 10, dragknob); ending leaves the far side
// free, which on organic models with feature lines gives far coarser layouts (measured in
// docs/benchmarks.md, "Coarse layouts"). The angle rule:
//   * A crossing of traces t_i (from seed i) and t_j (seed j, j ≠ i as traces) is a regular
//     interior vertex n that both traces have reached, arriving along perpendicular edges. With
//     l_ij the edges along t_i from i to n and l_ji along t_j, the right triangle (i, n, j)
//     has tan|α_ij| = l_ji / l_ij at i; α_ij > 0 when t_j arrives from t_i's left (from the
//     counter-clockwise neighbour of t_i's forward edge in n's ring), < 0 from its right.
//   * With α = max_angle_deg < 90, t_i becomes *done* once it has crossed a trace with
//     α_ij ∈ (0, α] and one with α_ij ∈ [−α, 0) (the same trace may be both, meeting t_i twice
//     around a loop: two copies of one seed). Ratios within 1e-12 of tan α count as equal.
//   * Lockstep (ours, for order independence): all traces advance one edge per step along
//     their lines (those of trace_extended_motorcycle_graph), so a trace's position is the
//     step number. A step first moves every trace, then records the crossings that now exist
//     (a trace that stopped keeps what it traced and is crossed only there), then decides: a
//     done trace stops at its current vertex if a trace line crosses it there straight
//     through and perpendicular to it — a trace that arrived along a perpendicular edge and
//     has moved on (itself, around a loop, included), or one standing there that is not done
//     (it will move on) — or if it is on a feature curve (which it would cross). Otherwise it
//     runs on until it is at such a vertex (or at the border, a seed or the end of its
//     line). So no trace ends inside a region, two done
//     traces never end on each other in an L, and every trace ends at a T-mesh vertex (not on
//     a line along its own, where its non-zero path would end inside an arc). Every decision
//     of a step depends only on the state after all of its moves, never on the traces' order.
//   * Monotone in α (ours): one lockstep run is not — a smaller α keeps some trace running,
//     its new crossings can let another trace stop sooner, and the graph can lose edges. So
//     each trace's length is its longest over the runs at every angle from α up to (not
//     including) 90°: the union of their graphs, which is again valid (every trace end stays
//     on a line through it, as lines only grow) and is exactly lockstep(α) whenever that is
//     already the largest. A run changes only at thresholds where some trace would be done
//     at a step where it was not (the larger of its two smallest side ratios l_ji / l_ij so
//     far); the runs go from tan α to the smallest such threshold, and so on until there is
//     none (lockstep_runs counts them). Thus a smaller α never gives a trace fewer edges.
//   * max_angle_deg ≥ 90 disables the angle rule: the traces are those of
//     trace_extended_motorcycle_graph.
//
// Non-zero paths (mesh-vertex chains, each a prefix of a trace or a curve path):
//   (1) per trace t_i, from i to the first crossing n_ij with l_ji < l_ij (seed j inside t_i's
//       90° sector), or the whole trace if there is none;
//   (2) when max_angle_deg < 90, for every crossing with l_ji > tan α · l_ij: t_j from j to
//       n_ij (else seed j could slide onto t_i's line, turning it by more than α);
//   (2 on curves, ours) (2) with a border or feature curve from seed i in place of t_i: where
//     t_j reaches the curve path (3) from i, q edges from i, after p edges: with p > tan α · q,
//     t_j from j to the curve; with q > tan α · p, the curve path from i to that vertex (no
//     trace runs along a curve, so (2) alone let seeds on curves meet at more than α: elk at
//     20° had two joined at 26.6°, measured by tmesh/separatrix_deviation.hpp);
//   (3, ours) from every seed along every border or feature edge, straight on along that curve
//     to the next seed (without it a mesh whose curves leave no trace could collapse whole);
//   (4, ours) every piece of a trace from one curve it reaches (border or feature) to the
//     next, so that a coarsening cannot fold two sharp curves, or a curve and the border,
//     into one where a trace runs between them.
//   Two paths with the same edge set are one (the one whose vertex sequence is smaller is
//   kept), and a path whose edges include all of another path's is dropped (it is implied).
//   Since (1) and (2) are nested prefixes of one trace, each trace keeps at most one path.
//
// Cost: the lines take at most 2·edges moves in all (a directed edge is on one line at most),
// and so does each run; runs are as many as the thresholds at which the outcome changes (a few
// hundred on 20k–40k-quad meshes at 10°–45°, about 0.1–1.5 s in all); paths add
// O(crossings + edges).
#pragma once

#include <cstdint>
#include <vector>

#include "tmesh/motorcycle.hpp"
#include "tmesh/quad_mesh_topology.hpp"

namespace bimdf::tmesh::detail {

struct AngleBoundedGraph {
  // In emission order (seeds as given, at each seed its ring order), as
  // trace_extended_motorcycle_graph; every trace has at least one edge.
  std::vector<Trace> traces;
  std::vector<uint8_t> cut;  // per mesh edge: on a trace, the border or a feature curve
  // Non-zero paths as mesh-vertex chains, each from a seed along cut edges straight on;
  // sorted lexicographically.
  std::vector<std::vector<int>> nonzero_chains;
  // Per chain: the trace it is a prefix of, −1 for a curve path (3), or −2 − t for a piece of
  // trace t between two curves (4).
  std::vector<int> nonzero_trace;
  int crossings = 0;      // crossings of two traces (an unordered pair at one vertex)
  int lockstep_runs = 0;  // thresholds tried (see above; 0 without the angle rule)
};

// Throws std::invalid_argument when feature_edge is not one flag per edge, a seed is not a
// vertex, or max_angle_deg is negative or NaN.
AngleBoundedGraph trace_angle_bounded(const QuadMeshTopology& topo,
                                      const std::vector<uint8_t>& feature_edge,
                                      const std::vector<int>& seeds, double max_angle_deg,
                                      bool cross_features = true);

}  // namespace bimdf::tmesh::detail
