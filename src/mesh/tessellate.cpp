#include "bimdf/quant/tessellate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "bimdf/quant/quantize.hpp"
#include "core/stopwatch.hpp"
#include "mesh/chart_parametrization.hpp"
#include "mesh/chart_placement.hpp"
#include "mesh/doublets.hpp"
#include "mesh/inverted_cleanup.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::quant {
namespace {

using bimdf::detail::seconds_since;

using Vec3 = std::array<double, 3>;

void check_lengths(const Layout& layout, const std::vector<int64_t>& lengths) {
  if (lengths.size() != layout.subsides.size())
    throw std::invalid_argument(std::to_string(lengths.size()) + " subside lengths for " +
                                std::to_string(layout.subsides.size()) + " subsides");
  for (size_t s = 0; s < lengths.size(); ++s)
    if (lengths[s] < 1 || lengths[s] > (int64_t{1} << 24))
      throw std::invalid_argument("subside " + std::to_string(s) + ": length " +
                                  std::to_string(lengths[s]) + ", expected 1 to 2^24");
  for (size_t c = 0; c < layout.charts.size(); ++c) {
    if (layout.charts[c].empty()) continue;
    int64_t perimeter = 0;
    for (int s : layout.charts[c].subsides) perimeter += lengths[s];
    if (perimeter % 2 != 0 || perimeter < 4)
      throw std::invalid_argument("chart " + std::to_string(c) + ": perimeter " +
                                  std::to_string(perimeter) +
                                  ", expected an even number of at least 4");
  }
}

// Quad vertices along every subside, shared by the charts on both sides: index i of subside
// s is at arc-length fraction i / x_s along its chain; the ends are its end mesh vertices.
std::vector<std::vector<int>> subside_vertices(const Layout& layout,
                                               const std::vector<int64_t>& lengths,
                                               std::vector<Vec3>& positions,
                                               std::vector<VertexOrigin>& origin) {
  std::unordered_map<int, int> end_vertex;
  const auto vertex_at_mesh_vertex = [&](int v) {
    auto [it, inserted] = end_vertex.emplace(v, static_cast<int>(positions.size()));
    if (inserted) {
      positions.push_back(layout.mesh.vertices[v]);
      origin.push_back({v, -1, -1});
    }
    return it->second;
  };
  std::vector<std::vector<int>> out(layout.subsides.size());
  for (size_t s = 0; s < layout.subsides.size(); ++s) {
    const std::vector<int>& chain = layout.subsides[s].vertices;
    const int64_t x = lengths[s];
    std::vector<double> arc(chain.size(), 0);
    for (size_t m = 1; m < chain.size(); ++m) {
      const Vec3& a = layout.mesh.vertices[chain[m - 1]];
      const Vec3& b = layout.mesh.vertices[chain[m]];
      arc[m] = arc[m - 1] + std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    }
    out[s].push_back(vertex_at_mesh_vertex(chain.front()));
    size_t m = 0;
    for (int64_t i = 1; i < x; ++i) {
      const double target = arc.back() * double(i) / double(x);
      while (m + 2 < chain.size() && arc[m + 1] < target) ++m;
      const double span = arc[m + 1] - arc[m];
      const double t = span > 0 ? std::clamp((target - arc[m]) / span, 0.0, 1.0) : 0.0;
      const Vec3& a = layout.mesh.vertices[chain[m]];
      const Vec3& b = layout.mesh.vertices[chain[m + 1]];
      out[s].push_back(static_cast<int>(positions.size()));
      origin.push_back({-1, static_cast<int>(s), -1});
      positions.push_back(
          {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
    }
    out[s].push_back(vertex_at_mesh_vertex(chain.back()));
  }
  return out;
}

}  // namespace

Tessellation tessellate(const Layout& layout, const std::vector<int64_t>& lengths,
                        const SmoothingOptions& smoothing) {
  check_lengths(layout, lengths);
  Tessellation result;
  QuadMesh& mesh = result.mesh;
  auto start = std::chrono::steady_clock::now();
  const std::vector<std::vector<int>> on_subside =
      subside_vertices(layout, lengths, mesh.vertices, result.origin);
  result.time_mapping_s += seconds_since(start);
  result.charts.resize(layout.charts.size());
  std::vector<QuadPattern> patterns(layout.charts.size());
  std::vector<std::vector<int>> globals(layout.charts.size());  // pattern → quad mesh vertex
  for (int c = 0; c < static_cast<int>(layout.charts.size()); ++c) {
    const Chart& chart = layout.charts[c];
    if (chart.empty()) continue;
    const int k = chart.valence();
    start = std::chrono::steady_clock::now();
    const std::vector<int64_t> sides = side_lengths(layout, c, lengths);
    QuadPattern pattern = make_quad_pattern(std::vector<int>(sides.begin(), sides.end()));
    result.time_patterns_s += seconds_since(start);

    start = std::chrono::steady_clock::now();
    // Pattern vertex → quad mesh vertex: the boundary from the subsides, in walking order.
    std::vector<int> global(pattern.num_vertices(), -1);
    int position = 0;
    for (int j = 0; j < k; ++j) {
      const Side& side = chart.sides[j];
      for (size_t i = 0; i < side.subsides.size(); ++i) {
        const std::vector<int>& along = on_subside[side.subsides[i]];
        const int x = static_cast<int>(along.size()) - 1;
        for (int t = 0; t < x; ++t) global[position++] = along[side.reversed[i] ? x - t : t];
      }
    }
    for (int v = pattern.perimeter(); v < pattern.num_vertices(); ++v) {
      global[v] = mesh.num_vertices();
      mesh.vertices.push_back({0, 0, 0});
      result.origin.push_back({-1, -1, c});
    }
    place_interior(layout, c, lengths, pattern, global, detail::FlatteningWeights::MeanValue,
                   mesh.vertices);
    std::vector<int> valence(pattern.num_vertices(), 0);
    for (const auto& q : pattern.quads) {
      mesh.quads.push_back({global[q[0]], global[q[1]], global[q[2]], global[q[3]]});
      mesh.quad_patch.push_back(c);
      for (int v : q) ++valence[v];  // quads around v = its valence inside the disk
    }
    ChartTiling& tiling = result.charts[c];
    tiling.kind = pattern.kind;
    tiling.cuts = pattern.cuts;
    tiling.quads = static_cast<int>(pattern.quads.size());
    for (int v = pattern.perimeter(); v < pattern.num_vertices(); ++v)
      tiling.singularities += valence[v] != 4;
    result.time_mapping_s += seconds_since(start);
    patterns[c] = std::move(pattern);
    globals[c] = std::move(global);
  }
  start = std::chrono::steady_clock::now();
  if (smoothing.iterations > 0 || smoothing.quality_rounds > 0) {
    SurfaceSmoother smoother(layout, result);
    smoother.run(smoothing);
    if (smoothing.iterations > 0)
      retry_tangled_charts(layout, lengths, patterns, globals, smoothing, smoother, result);
    result.time_smoothing_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    smoother.polish(smoothing);
    result.time_polish_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    result.collapsed_inverted = remove_inverted_quads(layout, smoothing, result);
    result.removed_doublets = bimdf::detail::remove_doublets(layout, result);
    result.time_smoothing_s += seconds_since(start);
  }
  return result;
}

}  // namespace bimdf::quant
