// From a quantized layout to a quad mesh (../shared/reference/quadwild_modeling.md §4.1): each
// chart gets the quad pattern of its side lengths (pattern.hpp), mapped onto the surface through
// a flattening of the chart's triangles onto the pattern's polygon, and the charts are stitched
// along their subsides.
//
// Conformity by construction: a subside of length x gets x − 1 quad vertices at equal arc-length
// steps along its polyline, and both charts beside it use those same vertices; subside
// endpoints (corners, T-junctions) are the layout's own mesh vertices. Interior pattern
// vertices are placed at the surface point the flattening maps to them, so the result lies on
// the input surface; smoothing (SmoothingOptions) then evens out the quads, staying on it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/pattern.hpp"

namespace bimdf::quant {

struct ChartTiling {
  PatternKind kind = PatternKind::Regular;
  int cuts = 0;
  int quads = 0;
  int singularities = 0;  // interior pattern vertices of valence ≠ 4
};

// Where a quad mesh vertex comes from: exactly one of the three is ≥ 0.
struct VertexOrigin {
  int mesh_vertex = -1;  // a subside endpoint: this layout mesh vertex (corner or T-junction)
  int subside = -1;      // a point inside this subside
  int chart = -1;        // a pattern vertex inside this chart
};

struct Tessellation {
  QuadMesh mesh;                     // quad_patch = chart id
  std::vector<VertexOrigin> origin;  // per quad mesh vertex
  std::vector<ChartTiling> charts;   // by chart id; empty charts get 0 quads
  double time_patterns_s = 0;        // building the patterns
  double time_mapping_s = 0;         // flattening charts and placing vertices
  double time_smoothing_s = 0;       // relaxation, untangling, tangled retries, cleanups
  double time_polish_s = 0;          // quality polishing (SmoothingOptions::quality_rounds)
  // Interior vertices of valence 2 removed after polishing, their two quads merged into one
  // (src/mesh/doublets.hpp); then the charts' quad counts no longer add up to the patterns'.
  int removed_doublets = 0;
  // Inverted quads left after polishing that were removed by merging two opposite corners
  // (src/mesh/inverted_cleanup.hpp, diagonal_collapse.hpp); the vertices within two rings of
  // each merged one were smoothed and polished again.
  int collapsed_inverted = 0;
  // Vertices of feature curves (feature corners last; never border vertices) that were let
  // off their curve, to move on the charts of their quads, because that turned an inverted
  // quad at them right side up (src/mesh/inverted_cleanup.hpp): there the quad mesh leaves
  // the feature. Their origin still names the curve or corner.
  int released_from_features = 0;
  // The farthest any of them ended from the layout's feature edges, in average layout edge
  // lengths (0 when none was let go).
  double released_max_offset = 0;
};

// Smoothing after stitching (note §4.2): `iterations` rounds in which every free vertex moves
// `damping` of the way to the mean of its neighbours and is projected back onto the closest
// point of the input surface among the triangles of its chart(s). Vertices on subsides along
// the mesh border or along feature edges (NAME.feature) slide along them; so do the subsides'
// ends where exactly two such subsides continue each other (turning by less than 30°). Other
// ends and feature corners (NAME.c_feature) stay: feature curves and corners keep their
// place. A move is kept only if it does not make the vertex's worst quad (scaled Jacobian)
// worse than min(its worst before, 0.5), and never if it makes two corners of a quad
// coincide; vertices with a quad below 0.2 also try sampled positions in their tangent plane
// and the position that maximizes their smallest corner area (untangle.hpp). 0 iterations:
// no smoothing.
//
// Then `quality_rounds` rounds of quality polishing (src/mesh/quality_polish.hpp): each vertex
// moves to where the corners of its quads are closest to right angles, never lowering its
// worst quad, turning a quad over or moving the mesh farther from the input surface; then as
// many rounds again over the corners of the worst tenth of the quads. It raises the mean and
// 5th-percentile scaled Jacobian; 0: none. Last, where smoothing or polishing ran, each
// interior vertex of valence 2 off the features (a "doublet", two quads with a corner of about
// 180° each) is removed and its two quads merged into one, where that raises the worse of them.
// Before that, quads still inverted are collapsed or have their feature vertices let off the
// features (src/mesh/inverted_cleanup.hpp): the one place where the mesh may leave a feature.
struct SmoothingOptions {
  int iterations = 30;
  double damping = 0.5;
  int quality_rounds = 30;
};

// Tessellates `layout` with subside lengths `lengths` (one per subside, as quantize returns).
// Throws std::invalid_argument naming the subside or chart if a length is < 1, the count is
// wrong, or a chart's perimeter is odd or < 4.
Tessellation tessellate(const Layout& layout, const std::vector<int64_t>& lengths,
                        const SmoothingOptions& smoothing = {});

// The edges of `t.mesh` that run along the layout's feature curves (NAME.feature), as sorted
// vertex pairs (lower id first): both ends lie on one feature subside — points inside it, or
// the layout vertices it ends at. Border subsides are not features (the border is the border).
// Vertices let off a feature (Tessellation::released_from_features) still count as on it. What
// `bimdf remesh --feature-out` writes, so that `bimdf requantize --feature` keeps the curves the
// layout had instead of guessing them from dihedral angles.
std::vector<std::array<int, 2>> feature_edges_of(const Layout& layout, const Tessellation& t);

// The smoothing step alone, on a tessellation of `layout` (called by tessellate).
void smooth_on_surface(const Layout& layout, Tessellation& tessellation,
                       const SmoothingOptions& options);

}  // namespace bimdf::quant
