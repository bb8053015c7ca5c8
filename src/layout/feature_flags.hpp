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

// Per vertex of `top`: whether it is an end of a flagged edge (`edge_flag` per undirected edge).
std::vector<bool> vertices_of_edges(const SurfaceTopology& top, const std::vector<bool>& edge_flag);

// Sharp edges (per undirected edge of `top`) cleaned of noise as FeatureOptions::erode_dilate
// says, with `steps` erosions: spiky triangles' edges dropped, dangling ends eroded and the
// remaining curves grown back from their eroded ends, small sets away from the border dropped,
// the flatter side of each small lens dropped.
// `steps` ≤ 0 returns `sharp` as it is.
std::vector<bool> clean_sharp_edges(const SurfaceTopology& top, std::vector<bool> sharp, int steps);

}  // namespace bimdf::layout
