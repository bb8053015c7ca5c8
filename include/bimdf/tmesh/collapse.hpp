// From a quantized quad T-mesh to a quad mesh (issue 21, paper §4.2): zero-length arcs and
// zero-width patches collapse, every other patch becomes a grid of its side lengths.
//
// Each arc of length x gets x − 1 interior points, each patch with side lengths X × Y > 0 an
// X × Y grid whose border points are its sides' arc points; a zero arc identifies its two
// ends, a patch of width 0 (or height 0) identifies its two long sides point by point (and all
// four sides when both are 0). The classes of identified points are the output vertices, the
// grids' quads the output faces. With opposite sides equal and every non-zero path non-zero
// the result is a conforming all-quad mesh; collapse checks it (every quad has four distinct
// corners, every edge at most two quads, every vertex one fan) and throws CollapseError
// naming the T-mesh patch or vertex otherwise. It also refuses points merging into an
// interior vertex of only two quads (they would fold onto each other; e.g. a cube whose
// vertical arcs are all 0 becomes a pillow: "T-mesh vertices 0 and 4 would become an
// interior vertex of only two quads") and a quantization that collapses every patch.
// Messages name points by the T-mesh vertices they hold ("T-mesh vertices 3 and 7"), else
// the arcs they lie on ("a point of arc 5") or their patch ("a point inside patch 2"), and
// quads by patch and grid cell ("patch 1: quad (0, 0) would have two corners at …").
//
// Geometry: with patch grids (a T-mesh from a quad mesh), an arc point at k/x of its arc sits
// at that fraction of the arc's mesh chain (counted in mesh edges, so that lengths equal to
// the chains' reproduce the input exactly), and a patch grid point at the transfinite
// (Coons) interpolation of its side points in the patch's grid coordinates, evaluated
// bilinearly on the mesh quad it falls in; without grids, the same in 3D over straight arcs.
// An output vertex made of several points sits at their mean. Output vertices are numbered
// in order of first use by the quads, which follow the patches and, within a patch, its grid
// row by row (j, then i): the same input always gives the same mesh.
//
// Irregular patches (a relaxed quantization, tmesh/quantize.hpp; only with allow_irregular):
// a patch whose opposite sides differ — every side ≥ 1, even perimeter — is tessellated with
// make_quad_pattern(X0, X1, X2, X3) (quant/pattern.hpp) instead of a grid. The pattern's
// boundary vertices are the patch's side points in walking order (both run counter-clockwise
// from corner 0), its interior vertices new points inside the patch (numbered like a grid's,
// so CollapsedVertex::patches names the patch), placed by Tutte's embedding with the boundary
// at the side points: in the patch grid's coordinates, then bilinearly on the input quad there,
// or in 3D without grids. Their quads follow the pattern's order; the checks above apply.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

class CollapseError : public std::runtime_error {
 public:
  explicit CollapseError(const std::string& what, std::vector<int> patches = {})
      : std::runtime_error(what), patches_(std::move(patches)) {}
  // The T-mesh patches the fault lies in (the quads' patches, the patches touching the
  // vertex): where a repair may act. Empty when the fault is everywhere.
  const std::vector<int>& patches() const { return patches_; }

 private:
  std::vector<int> patches_;
};

// Where an output vertex comes from, for smoothing: the T-mesh patches whose region it may
// move in, and whether it is pinned (a feature corner, border corner) or on a feature/border
// curve (the arcs it lies on).
struct CollapsedVertex {
  std::vector<int> patches;         // T-mesh patches touching any of its points
  std::vector<int> arcs;            // arcs it lies on (inside or at an end)
  std::vector<int> tmesh_vertices;  // T-mesh vertices merged into it
  // The points inside arcs merged into it: each one's arc and own position. The vertex sits at
  // the mean of all its points; smooth_requantized may start a vertex that must stay on a curve
  // arc at its point there instead.
  std::vector<std::pair<int, std::array<double, 3>>> arc_points;
};

struct CollapsedMesh {
  QuadMesh mesh;                        // quad_patch = the T-mesh patch each quad was made for
  std::vector<CollapsedVertex> origin;  // per output vertex
  int collapsed_patches = 0;            // patches with width or height 0
  int zero_arcs = 0;
  int irregular_patches = 0;  // patches tessellated by a pattern (allow_irregular only)
  // With patch grids (a T-mesh traced on `mesh`): per quad, its corners' coordinates (u, v) in
  // its patch's grid (PatchGrid: u along side 0, v along side 1, in input edges) as the
  // tessellation placed them, before any smoothing; (−1, −1) for an irregular patch's quads or
  // a patch without a grid. Empty without a mesh. What separatrix_deviation.hpp measures on.
  std::vector<std::array<std::array<double, 2>, 4>> quad_grid_uv;
};

// Zips (half-arc quantization, half_arc.hpp): pairs of chains of border half-arcs of equal
// length — the two sides of a two-gon, each walked with the two-gon on its left as patch sides
// are, so that they run opposite ways — whose points are identified position by position, the
// first chain's from its start with the second's from its end, as a patch of width 0
// identifies its long sides. A zipped point keeps the patches of both (CollapsedVertex).
using Zip = std::array<std::vector<int>, 2>;

// Collapses and tessellates. `mesh` is the quad mesh the T-mesh was traced on (nullptr when
// the T-mesh has no grids). Throws std::invalid_argument if `arc_length` has the wrong size, a
// negative entry, or opposite sides of a patch differ — unless allow_irregular, which then
// requires of such a patch every side ≥ 1 and an even perimeter — or a zip's chains are not
// chains of the T-mesh's half-arcs of equal length; CollapseError as above.
CollapsedMesh collapse_and_tessellate(const TMesh& tmesh, const TMeshIncidence& incidence,
                                      const std::vector<int64_t>& arc_length, const QuadMesh* mesh,
                                      bool allow_irregular = false,
                                      const std::vector<Zip>& zips = {});

// A conforming quad layout read off a quad mesh: its base complex (separatrices traced
// straight through regular vertices from every singular vertex, and the border, cut the
// faces into rectangles meeting corner to corner). Per patch: its four corner vertices (mesh
// vertex ids, counter-clockwise) and the integer lengths of its sides 0..3. Patches are
// numbered by their lowest quad id; corner 0 is the patch's corner with the lowest vertex id.
struct ConformingLayout {
  std::vector<std::array<int, 4>> patch_corners;
  std::vector<std::array<int64_t, 4>> patch_side_length;
  std::vector<std::array<std::vector<int>, 4>> patch_side_chain;  // mesh vertices per side
  std::vector<int> face_patch;                                    // per quad
};
// `feature_edges` (mesh vertex pairs) also cut, as separatrices do, and their corners (where
// a feature curve ends, branches, turns or meets the border) emit separatrices along every
// edge not cut yet, like singular vertices. Separatrices cross feature curves (a T-junction
// there would not be conforming). Throws std::invalid_argument for a feature edge that is not
// a mesh edge, and CollapseError when a patch is not a rectangle of the grid ("base complex
// patch 0 (with quad 0) has 0 corners, expected 4": e.g. a torus-like grid without any
// singularity or feature).
ConformingLayout conforming_layout(const QuadMesh& mesh,
                                   const std::vector<std::array<int, 2>>& feature_edges = {});

// Writes `layout` as OBJ: the mesh's vertices, then per patch a group `g patch_N`, a comment
// `# sides a b c d` with its side lengths, an `f` line of its four corners and one `l` polyline
// per side.
void write_layout_obj(std::ostream& out, const QuadMesh& mesh, const ConformingLayout& layout);

}  // namespace bimdf::tmesh
