// Smoothing a part of a tessellation (smooth_on_surface in quant/tessellate.hpp smooths all).
#pragma once

#include <vector>

#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

// smooth_on_surface restricted to the quad mesh vertices `vertices` (those that may move at
// all): the others stay where they are. Used to give one tangled chart a second start.
void smooth_vertices(const Layout& layout, Tessellation& tessellation,
                     const SmoothingOptions& options, const std::vector<int>& vertices);

}  // namespace bimdf::quant
