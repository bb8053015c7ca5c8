// Which subsides of a QuadWild layout run along its feature curves (internal to src/mesh).
#pragma once

#include <vector>

#include "bimdf/quant/layout.hpp"

namespace bimdf::quant {

// Per subside: 1 when every layout mesh edge along it is a feature edge (NAME.feature). Border
// subsides are 0: the border is a curve of its own. Smoothing slides the points of these
// subsides along their curve; feature_edges_of reports the quad edges along them.
std::vector<char> feature_subsides(const Layout& layout);

}  // namespace bimdf::quant
