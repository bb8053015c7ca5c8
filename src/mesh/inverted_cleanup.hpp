// What tessellate does about quads still inverted after polishing (tessellate.hpp): collapse
// them (diagonal_collapse.hpp) and smooth the vertices around again. First every collapse that
// already improves the quads around before they move (collapse_inverted_quads), the two rings
// around each merged vertex then smoothed and polished; then, for each inverted quad left, each
// corner off the features and border is merged into its opposite on a copy, the two rings
// around smoothed (relaxation and untangling) and polished, and the first copy with fewer
// inverted quads and a better worst quad around is kept — most collapses pay only once the
// neighbours have moved (measured: cow 3 → 1 inverted, mannequin-devil 12 → 6). A quad no copy
// helped is not tried again. Last, where an inverted quad is left with corners on feature curves
// (tips where two curves meet at a few degrees, jagged feature loops narrower than a quad), those
// corners — then the feature-curve vertices of the quads around them — are let off their curve
// on a copy to move on their quads' charts, which is kept on the same terms: the quad mesh then
// leaves the curve at those few vertices instead of folding (measured: cow 1 → 0,
// mannequin-devil 6 → 1; Tessellation::released_from_curves). Feature corners and border
// vertices never move.
#pragma once

#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

// Returns how many quads were collapsed; `t` follows (origin, charts' quad counts). With
// smoothing.quality_rounds ≤ 0 only the first kind of collapse is made, and nothing is
// polished.
int remove_inverted_quads(const Layout& layout, const SmoothingOptions& smoothing, Tessellation& t);

}  // namespace bimdf::quant
