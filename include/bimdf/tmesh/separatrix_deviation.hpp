// How far a requantized mesh's separatrices turn away from the input's grid lines (issue 52,
// point 4): measured on the mesh, not assumed from the angle bound it was traced with.
//
// A coarse layout moves singularities relative to each other: where a zero arc or a collapsed
// patch joins a singularity to a line of the layout, that separatrix no longer follows the
// input's grid. Lyon et al. 2021 (ATQ) bound the turn by the angle rule of the traces
// (TraceOptions::max_angle_deg, angle_bounded.hpp); this measures it. A separatrix is traced on
// the output mesh as its base complex is (metrics.hpp): from a singular vertex (inside with
// valence ≠ 4, on the border ≠ 3) along each of its edges into the mesh, straight on through
// regular interior vertices, up to the next singular or border vertex. Its *deviation* is the angle
// between the output's line (one axis of the quads it starts along) and the displacement, in the
// input's grid, from where it starts to where it ends: atan(|across| / along) in degrees, 90 or
// more when it ends behind its start.
//
// The displacement is integrated on the input quad mesh, whose quads are unit squares: each
// output vertex on the way sits at its tessellation place (CollapsedMesh::quad_grid_uv, before
// smoothing) in the input quad of its patch's grid there; consecutive places — along an output
// edge, or the points a collapse merged into one output vertex — are joined through the input
// quads of the T-mesh patches between them (those of the output vertex, CollapsedVertex::
// patches), carrying the quads' frames across their shared edges. A singular end is measured at
// the singular input vertex the collapse put there (the T-mesh vertex, not the mean of its
// class), so the slide of a singularity along a zero arc counts in full. Inside a region free
// of singular vertices this displacement depends only on the ends, not on the way taken.
//
// Cost: linear in the separatrices' length, with a small search per step.
#pragma once

#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

// The angle bound concerns separatrices between singular vertices: the rule keeps a
// singularity from sliding onto another's line. One that ends at the border ends where the
// quantization put that border point, which no rule of the traces holds (reported apart).
struct SeparatrixDeviation {
  int measured = 0;    // separatrices measured
  int unmeasured = 0;  // not: a line that closes on itself (no end), a quad without grid
                       // coordinates, no way found between places, or frames that disagree on
                       // the line's direction (none expected)
  double max_deg = 0;  // the largest deviation of one between singular vertices
  double max_to_border_deg = 0;        // the largest of one ending at the border
  int worst_from = -1, worst_to = -1;  // output vertices of a separatrix with max_deg
  double bound_deg = -1;  // the bound measured against (< 0: none, and over_bound is 0)
  int over_bound = 0;     // between singular vertices and above the bound (1e-9 slack)
  // Every measured separatrix: its output vertices (start, end), whether it ends at the border
  // (at a vertex that is not singular), its deviation, and the T-mesh patches it runs through
  // (those of its quads and of its vertices' classes, CollapsedVertex::patches; sorted); in
  // order of the start vertex.
  struct Measured {
    int from = -1, to = -1;
    bool to_border = false;
    double deg = 0;
    std::vector<int> patches;
  };
  std::vector<Measured> separatrices;
};

// Measures `collapsed` (collapse_and_tessellate of `tmesh`, traced on `input`; for half-arc
// quantization the cut T-mesh, HalfArcSetup::inflated.tmesh). `bound_deg` < 0: none. Without
// grid coordinates (a T-mesh without patch grids) every separatrix is unmeasured. Throws
// std::invalid_argument when `collapsed` does not belong to `tmesh` and `input` (sizes).
SeparatrixDeviation measure_separatrix_deviation(const QuadMesh& input, const TMesh& tmesh,
                                                 const CollapsedMesh& collapsed,
                                                 double bound_deg = -1);

// The same for requantize's result on `input` (the T-mesh it collapsed: the cut one with
// half-arc quantization).
struct RequantizeResult;
SeparatrixDeviation measure_separatrix_deviation(const QuadMesh& input, const RequantizeResult& r,
                                                 double bound_deg = -1);

}  // namespace bimdf::tmesh
