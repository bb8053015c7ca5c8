// What tessellate does about quads still inverted after polishing (tessellate.hpp): collapse
// them (diagonal_collapse.hpp) and smooth the vertices around again. First every collapse that
// already improves the quads around before they move (collapse_inverted_quads), the two rings
// around each merged vertex then smoothed and polished; then, for each inverted quad left, each
// corner off the features and border is merged into its opposite on a copy, the two rings
// around smoothed (relaxation and untangling) and polished, and the first copy with fewer
// inverted quads and a better worst quad around is kept — most collapses pay only once the
// neighbours have moved (measured: cow 3 → 1 inverted, mannequin-devil 12 → 6). A quad no copy
// helped is not tried again. Where an inverted quad is left with corners on feature curves
// (tips where two curves meet at a few degrees, jagged feature loops narrower than a quad), those
// corners are let off their curve on a copy, to move on their quads' charts — then the curve
// vertices of the quads around them, then, last resort, those quads' feature corners — and the
// copy is kept on the same terms: the quad mesh leaves the feature at those few vertices instead
// of folding across it. This is tried after each refused collapse (near it) and once more at the
// end (measured: cow 1 → 0, camel 1 → 0, mannequin-devil 6 → 0; bull's QuadWild layout 1 → 0;
// Tessellation::released_from_features). Border vertices never move, and no trial may add a
// flat quad.
#pragma once

#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

// Returns how many quads were collapsed; `t` follows (origin, charts' quad counts). With
// smoothing.quality_rounds ≤ 0 only the first kind of collapse is made, and nothing is
// polished.
int remove_inverted_quads(const Layout& layout, const SmoothingOptions& smoothing, Tessellation& t);

}  // namespace bimdf::quant
