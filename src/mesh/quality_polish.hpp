// The last phase of smoothing (SmoothingOptions::quality_rounds): per-vertex optimization of
// the corner angles of the quads at each vertex, for the figures quad meshes are compared by —
// the mean and 5th percentile of the per-quad scaled Jacobian (metrics.hpp). Relaxation
// towards the umbrella and parallelogram means evens out edge lengths but leaves corners skewed
// where charts are curved, stretched or irregular; the scaled Jacobian sees only angles.
//
// Each vertex moves, in its tangent plane (along its curve for vertices on feature or border
// curves), to a local minimum (Newton steps, untangle.hpp) of
//     E(v) = Σ over the corners c of the quads at v of (1 − sin θ_c)³,
// sin θ_c signed against the quad's own Newell normal (the scaled Jacobian's corner term), and
// is put back onto the surface (its chart or its feature/border curve, as smoothing projects).
// The cube weighs bad corners far more than good ones: it raised the 5th percentile more than
// the square did on the shared layouts, at the same mean (docs/benchmarks.md). A move is kept
// only if
//   1. E falls,
//   2. the vertex's worst quad gets no worse, both as smoothing rates it (against both
//      normals, slivers counted) and as metrics.hpp does (against its own normal), and no
//      quad at it is turned over — so the minimum scaled Jacobian never falls and nothing
//      gets inverted;
//   3. no sample of its quads (edge midpoints and centres, those of metrics.hpp's Hausdorff
//      distance) ends farther from the input surface than the farthest sample of all the
//      quads polishing may change was before it began — so the Hausdorff distance to the
//      input never grows. (A bound per vertex, its own quads' farthest, was measured too: it
//      blocks most moves on curved parts and left the mean below QuadWild's on 4 layouts.)
// Vertices that moved put themselves and their neighbours on the next round's list, so later
// rounds only revisit where something changed. After those rounds come as many again over the
// corners of the quads in the worst tenth (re-chosen each round), where the 5th percentile is
// decided and small moves still add up.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "bimdf/mesh.hpp"
#include "mesh/closest_point.hpp"
#include "mesh/mesh_on_surface.hpp"

namespace bimdf::detail {

struct PolishInput : MeshOnSurface {
  const TriangleTree& surface;        // the whole input surface (rule 3)
  std::function<bool(int)> movable;   // false: the vertex stays (corners, pins)
  std::function<bool(int)> on_curve;  // whether project() puts the vertex on a curve (1-D moves)
  // How the quads at a vertex rate at the current positions (rule 2).
  struct Rating {
    double quality;  // smoothing's rating of the worst quad (higher is better)
    double worst;    // the smallest scaled Jacobian against the quads' own normals
    int turned;      // how many are turned over
  };
  std::function<Rating(int)> rate;
};

struct PolishReport {
  int rounds = 0;      // rounds with at least one vertex to visit
  int64_t visits = 0;  // vertex visits
  int64_t moves = 0;   // moves kept
};

// Polishes the vertices `vertices` (others stay): at most `rounds` rounds over the vertices
// that moved, then `rounds` rounds over the corners of the worst tenth of their quads.
PolishReport polish_quality(const PolishInput& input, const std::vector<int>& vertices, int rounds);

// E(v) above for vertex v of `mesh` (0 when every corner of its quads is a right angle).
double corner_angle_energy(const QuadMesh& mesh, const std::vector<int>& quads_at_v);

}  // namespace bimdf::detail
