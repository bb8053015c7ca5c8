// Flattening one chart of a layout onto its pattern polygon, and finding points in the result
// (../shared/reference/quadwild_modeling.md §4.1 step 4).
//
// The chart's boundary is pinned to the polygon of its pattern (quant/pattern.hpp): each
// subside covers its quantized share of its side, its mesh vertices placed by arc length, so
// that subside endpoints land exactly on the pattern's boundary vertices. Interior vertices get
// mean-value coordinates (Floater 2003), or uniform ones (Tutte's barycentric embedding): both
// positive weights, so the map of a chart onto a convex polygon is one-to-one and every pattern
// vertex falls in exactly one triangle. Mean-value coordinates follow the surface's shape;
// uniform ones spread the vertices by the mesh's connectivity, which gives a different start
// where a chart's shape makes the first fail (tessellate.cpp retries tangled charts with it).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bimdf/quant/layout.hpp"

namespace bimdf::quant::detail {

struct ChartParametrization {
  std::vector<int> mesh_vertex;               // local vertex → mesh vertex id
  std::vector<std::array<double, 2>> uv;      // local vertex → position in the k-gon
  std::vector<std::array<int, 3>> triangles;  // local vertex ids
};

enum class FlatteningWeights { MeanValue, Uniform };

// Flattens chart `c` given every subside's quantized length onto `polygon`, the chart's
// pattern polygon (QuadPattern::polygon: corner j, side j of the chart's side lengths).
ChartParametrization parametrize_chart(const Layout& layout, int c,
                                       const std::vector<int64_t>& lengths,
                                       const std::vector<std::array<double, 2>>& polygon,
                                       FlatteningWeights weights = FlatteningWeights::MeanValue);

// A point of the chart, as a mesh triangle and barycentric coordinates.
struct SurfacePoint {
  int triangle = -1;  // index into ChartParametrization::triangles
  std::array<double, 3> barycentric{};
};

// Point location in a parametrization (a uniform grid of triangle bounding boxes). Points that
// fall outside every triangle by rounding get the nearest triangle with clamped coordinates.
class UvLocator {
 public:
  explicit UvLocator(const ChartParametrization& param);
  SurfacePoint locate(const std::array<double, 2>& p) const;

 private:
  const ChartParametrization& param_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

}  // namespace bimdf::quant::detail
