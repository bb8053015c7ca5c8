// Smoothing a collapsed, re-tessellated T-mesh (tmesh/collapse.hpp) on the quad mesh it was
// traced on, with the same smoother as `remesh` (mesh/smoothing.hpp): the input quads, split
// into triangles, are the surface; every T-mesh patch is a chart; every arc a subside.
#pragma once

#include <array>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

// The layout smoothing projects onto: `input`'s quads as two triangles each (quad f gives
// triangles 2f = (q0, q1, q2) and 2f + 1 = (q0, q2, q3), orientation kept), face_chart = the
// T-mesh patch whose grid covers the quad (−1 if none), one chart per patch (its faces,
// corners and sides; sides list arcs as subsides), one subside per arc (its chain; charts =
// the patches of its half-arcs, −1 for a border half-arc), and the feature edges and corners
// (arcs flagged arc_feature add their chains' edges). Needs patch grids and arc chains;
// throws std::invalid_argument naming the patch if a grid cell is not a quad of `input`.
quant::Layout requantization_layout(const QuadMesh& input, const TMesh& tmesh,
                                    const TMeshIncidence& incidence,
                                    const std::vector<std::array<int, 2>>& feature_edges,
                                    const std::vector<int>& feature_corners);

// What smoothing left: quads inverted and degenerate (as metrics.hpp counts them), and the
// inverted ones that another quantization may right (`to_split`): all but those repeating, at
// the same corners, a quad that is inverted in the input. Smoothing stops where every move of
// one vertex turns some quad over; a quad with pinned corners (T-mesh vertices that stay at
// their input vertices) cannot move at all. Splitting such a quad (add_quad_split_bounds,
// separation_repair.hpp) puts a vertex between its corners that smoothing can move.
struct SmoothedQuads {
  std::vector<int> to_split;
  std::vector<int> degenerate_quads;
  int inverted = 0;
  int degenerate = 0;
};

// Smooths `result.mesh` in place on `input` (quant::SmoothingOptions: iterations, damping).
// Each output vertex moves on the charts of every T-mesh patch it touches
// (CollapsedVertex::patches), so a vertex merged across a collapsed strip can settle anywhere
// over it. Vertices on border or feature arcs slide along them; T-mesh vertices that are
// feature corners or where border/feature curves turn stay at their mesh vertex. Both are
// first put back where they belong (a merged vertex starts at the mean of its points; when
// it holds such a T-mesh vertex it goes there, else onto its curve) — unchecked, so a
// quantization that merges two pinned vertices can leave an inverted quad. After that no
// move inverts a quad or makes the worst quad at a vertex worse (see SmoothingOptions);
// the vertices of a quad alone at a straight border corner (~180°, forced by the input) stay.
// Does nothing with 0 iterations or without patch grids, arc chains and mesh vertices.
//
// Returns what smoothing left (SmoothedQuads).
//
// `more_charts` (optional, per patch): patches whose charts the vertices of that patch may move
// on too — for half-arc quantization, every patch along a two-gon, since a T-junction moved
// along the path takes its patches' quads over the input region of their neighbours.
SmoothedQuads smooth_requantized(const QuadMesh& input, const TMesh& tmesh,
                                 const TMeshIncidence& incidence,
                                 const std::vector<std::array<int, 2>>& feature_edges,
                                 const std::vector<int>& feature_corners, CollapsedMesh& result,
                                 const quant::SmoothingOptions& options,
                                 const std::vector<std::vector<int>>& more_charts = {});

}  // namespace bimdf::tmesh
