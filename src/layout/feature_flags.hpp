// Feature curves as per-edge flags of a SurfaceTopology: what the cross field and the tracing
// test edge by edge.
#pragma once

#include <vector>

#include "bimdf/layout/features.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

// Per undirected edge of `top`: whether it lies on a feature curve (a sharp edge or the
// border). Sharp edges that are not edges of the mesh are ignored (features_from_edges has
// checked them).
std::vector<bool> feature_edge_flags(const SurfaceTopology& top, const Features& features);

}  // namespace bimdf::layout
