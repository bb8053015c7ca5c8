// Coarse lengths refined strip by strip (issue 52, point 3; internal to src/tmesh): the lengths
// of a coarse quantization (quantize.hpp, `coarse`) multiplied not by one integer for the whole
// mesh but by one per strip of the coarse tessellation, each chosen for the input's size there.
//
// Every unit of a coarse arc length is an edge of the coarse tessellation, and each such edge
// crosses one strip (a chord of quads running from side to opposite side through the patches):
// in a patch, unit s of side k and unit L − 1 − s of side k + 2 are crossed by the same strip
// (the same edge, in a patch that collapses to width 0), and so are unit s of a zip's first
// chain and unit L − 1 − s of its second. Giving every unit of a strip the same length s ≥ 1
// keeps opposite sides equal, every zero arc 0 and every other arc ≥ 1 — the collapse, and so
// the base complex, is the coarse layout's exactly, as with one factor — while a strip through
// wide parts of the input gets more quads than one through narrow parts. A strip's s is the
// mean, over its units, of the arc's target per coarse unit (arc_target / coarse length),
// rounded, at least 1.
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh::detail {

// `coarse`: one length ≥ 0 per arc with opposite sides equal (and the zips' chains equal);
// returns the refined lengths. `factor_mean` (optional) receives the mean strip factor.
std::vector<int64_t> strip_refined_lengths(const TMesh& tmesh, const std::vector<int64_t>& coarse,
                                           const std::vector<Zip>& zips,
                                           double* factor_mean = nullptr);

}  // namespace bimdf::tmesh::detail
