// Chart flattening (src/mesh/chart_parametrization.hpp): with either weighting, every chart of
// the bundled layout maps one-to-one onto its pattern polygon — the boundary on the polygon,
// every triangle turned the same way, and the triangles' areas adding up to the polygon's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bimdf/quant/pattern.hpp"
#include "bimdf/quant/quantize.hpp"
#include "mesh/chart_parametrization.hpp"

namespace bimdf::quant {
namespace {

double signed_area(const std::array<double, 2>& a, const std::array<double, 2>& b,
                   const std::array<double, 2>& c) {
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

TEST(Flattening, EveryChartMapsOneToOneOntoItsPolygonWithBothWeightings) {
  const Layout layout =
      read_quadwild_layout(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj");
  const std::vector<int64_t> lengths = quantize(layout, {}).lengths();
  for (const auto weights :
       {detail::FlatteningWeights::MeanValue, detail::FlatteningWeights::Uniform}) {
    for (int c = 0; c < static_cast<int>(layout.charts.size()); ++c) {
      if (layout.charts[c].empty()) continue;
      const std::vector<int64_t> sides = side_lengths(layout, c, lengths);
      const std::vector<std::array<double, 2>> polygon =
          pattern_polygon(std::vector<int>(sides.begin(), sides.end()));
      const detail::ChartParametrization p =
          detail::parametrize_chart(layout, c, lengths, polygon, weights);
      double polygon_area = 0;
      for (size_t j = 0; j < polygon.size(); ++j)
        polygon_area += signed_area({0, 0}, polygon[j], polygon[(j + 1) % polygon.size()]);
      // A point on a side of the polygon (pinned boundary vertices are).
      const auto on_boundary = [&](const std::array<double, 2>& x) {
        for (size_t j = 0; j < polygon.size(); ++j) {
          const auto& a = polygon[j];
          const auto& b = polygon[(j + 1) % polygon.size()];
          if (std::abs(signed_area(a, b, x)) < 1e-12 &&
              (x[0] - a[0]) * (x[0] - b[0]) + (x[1] - a[1]) * (x[1] - b[1]) <= 1e-12)
            return true;
        }
        return false;
      };
      double total = 0, smallest = INFINITY;
      int flat_ears = 0;
      for (const auto& t : p.triangles) {
        const double a = signed_area(p.uv[t[0]], p.uv[t[1]], p.uv[t[2]]);
        total += a;
        // A triangle with all three corners on one side of the polygon is flat in any
        // flattening that pins the boundary; every other triangle must keep its orientation.
        if (on_boundary(p.uv[t[0]]) && on_boundary(p.uv[t[1]]) && on_boundary(p.uv[t[2]]) &&
            std::abs(a) < 1e-12) {
          ++flat_ears;
          continue;
        }
        smallest = std::min(smallest, a * (polygon_area > 0 ? 1 : -1));
      }
      EXPECT_LT(flat_ears, static_cast<int>(p.triangles.size())) << "chart " << c;
      EXPECT_GT(smallest, 0) << "chart " << c
                             << (weights == detail::FlatteningWeights::Uniform ? " (uniform)"
                                                                               : " (mean value)");
      EXPECT_NEAR(total, polygon_area, 1e-9 * std::abs(polygon_area)) << "chart " << c;
    }
  }
}

}  // namespace
}  // namespace bimdf::quant
