// Placing a chart's pattern on the surface, and second chances for charts that smoothing
// leaves tangled (../shared/reference/quadwild_modeling.md §4.1 steps 4–5). Used by
// tessellate.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/quant/tessellate.hpp"
#include "mesh/chart_parametrization.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::quant {

// Places the interior vertices of chart c's pattern (pattern vertex v → quad mesh vertex
// global[v]) at the surface points the chart's flattening with `weights` maps them to.
void place_interior(const Layout& layout, int c, const std::vector<int64_t>& lengths,
                    const QuadPattern& pattern, const std::vector<int>& global,
                    detail::FlatteningWeights weights,
                    std::vector<std::array<double, 3>>& positions);

// Charts whose quads are still inverted or degenerate after smoothing get more starts, each
// kept only if it leaves the quads touching the moved vertices less tangled (fewer inverted or
// degenerate quads, then a larger smallest scaled Jacobian):
//  1. the interior vertices re-placed through the uniform (Tutte) flattening and smoothed with
//     everything else fixed;
//  2. three times the smoothing rounds with the neighbouring charts' vertices free too;
//  3. both together;
//  4. up to 8 randomly shaken starts (a generator seeded by the chart id: reproducible).
// The retries stop once they have relaxed as many vertices (summed over their rounds) as one
// smoothing of the whole mesh: enough for every layout QuadWild made, and a bound on the time
// where a layout leaves many charts tangled.
// `patterns[c]` and `globals[c]` (pattern vertex → quad mesh vertex) as tessellate built them;
// `smoother` is set up on `tessellation`.
void retry_tangled_charts(const Layout& layout, const std::vector<int64_t>& lengths,
                          const std::vector<QuadPattern>& patterns,
                          const std::vector<std::vector<int>>& globals,
                          const SmoothingOptions& smoothing, SurfaceSmoother& smoother,
                          Tessellation& tessellation);

}  // namespace bimdf::quant
