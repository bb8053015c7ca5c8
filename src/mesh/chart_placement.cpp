#include "mesh/chart_placement.hpp"

#include <algorithm>
#include <functional>
#include <random>
#include <utility>

#include "mesh/quad_adjacency.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::quant {
namespace {

using Vec3 = std::array<double, 3>;

constexpr int kShakenStarts = 8;

// The retries may relax at most this many times as many vertices, summed over their rounds, as
// one smoothing of the whole mesh does. A retry relaxes tangled vertices, each of which tries
// dozens of positions, so without a bound a layout with many tangled charts spent minutes here
// (a bare mesh's layout: 165 s against 6 s for the first smoothing). On QuadWild's 23 layouts
// the retries use at most 0.11 of it, so the bound changes none of their results.
constexpr int64_t kRetryWork = 1;

// The number of inverted or degenerate quads among `quads` and their smallest scaled
// Jacobian, by which a tangled chart's alternatives are compared.
std::pair<int, double> tangle(const QuadMesh& mesh, const std::vector<int>& quads) {
  int inverted = 0;
  double worst = 1;
  for (int f : quads) {
    const double sj = bimdf::detail::scaled_jacobian(mesh, mesh.quads[f]);
    inverted += sj < 0 || bimdf::detail::degenerate(mesh, mesh.quads[f]);
    worst = std::min(worst, sj);
  }
  return {inverted, worst};
}

}  // namespace

void place_interior(const Layout& layout, int c, const std::vector<int64_t>& lengths,
                    const QuadPattern& pattern, const std::vector<int>& global,
                    detail::FlatteningWeights weights, std::vector<Vec3>& positions) {
  if (pattern.perimeter() == pattern.num_vertices()) return;
  const detail::ChartParametrization param =
      detail::parametrize_chart(layout, c, lengths, pattern.polygon, weights);
  const detail::UvLocator locator(param);
  for (int v = pattern.perimeter(); v < pattern.num_vertices(); ++v) {
    const detail::SurfacePoint p = locator.locate(pattern.positions[v]);
    Vec3 x{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
      const Vec3& corner = layout.mesh.vertices[param.mesh_vertex[param.triangles[p.triangle][a]]];
      for (int d = 0; d < 3; ++d) x[d] += p.barycentric[a] * corner[d];
    }
    positions[global[v]] = x;
  }
}

void retry_tangled_charts(const Layout& layout, const std::vector<int64_t>& lengths,
                          const std::vector<QuadPattern>& patterns,
                          const std::vector<std::vector<int>>& globals,
                          const SmoothingOptions& smoothing, SurfaceSmoother& smoother,
                          Tessellation& t) {
  QuadMesh& mesh = t.mesh;
  // Deterministic (counted, not timed), so that a run repeats exactly.
  int64_t budget = kRetryWork * mesh.num_vertices() * smoothing.iterations;
  std::vector<std::vector<int>> chart_quads(layout.charts.size());
  for (int f = 0; f < mesh.num_quads(); ++f) chart_quads[mesh.quad_patch[f]].push_back(f);
  const std::vector<std::vector<int>> vertex_quads = bimdf::detail::quads_at_vertices(mesh);
  // Runs `start` and then smoothing over `vertices`; undoes both unless the quads touching
  // `vertices` end up less tangled.
  const auto attempt = [&](std::vector<int> vertices, const std::function<void()>& start,
                           const SmoothingOptions& options) {
    const int64_t work = static_cast<int64_t>(vertices.size()) * options.iterations;
    if (work > budget) {
      budget = 0;
      return;
    }
    budget -= work;
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::vector<int> touching;
    for (int v : vertices)
      touching.insert(touching.end(), vertex_quads[v].begin(), vertex_quads[v].end());
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    const std::pair<int, double> before = tangle(mesh, touching);
    std::vector<Vec3> kept;
    for (int v : vertices) kept.push_back(mesh.vertices[v]);
    start();
    smoother.run(options, vertices);
    const std::pair<int, double> after = tangle(mesh, touching);
    if (after.first > before.first ||
        (after.first == before.first && after.second <= before.second))
      for (size_t i = 0; i < vertices.size(); ++i) mesh.vertices[vertices[i]] = kept[i];
  };
  std::vector<std::vector<int>> neighbour_charts(layout.charts.size());
  for (const Subside& s : layout.subsides)
    if (s.charts[0] >= 0 && s.charts[1] >= 0 && s.charts[0] != s.charts[1]) {
      neighbour_charts[s.charts[0]].push_back(s.charts[1]);
      neighbour_charts[s.charts[1]].push_back(s.charts[0]);
    }
  SmoothingOptions longer = smoothing;
  longer.iterations *= 3;
  for (int c = 0; c < static_cast<int>(layout.charts.size()) && budget > 0; ++c) {
    if (tangle(mesh, chart_quads[c]).first == 0) continue;
    attempt(
        globals[c],
        [&] {
          place_interior(layout, c, lengths, patterns[c], globals[c],
                         detail::FlatteningWeights::Uniform, mesh.vertices);
        },
        smoothing);
    if (tangle(mesh, chart_quads[c]).first == 0) continue;
    std::vector<int> around = globals[c];
    for (int n : neighbour_charts[c])
      around.insert(around.end(), globals[n].begin(), globals[n].end());
    attempt(
        around, [] {}, longer);
    if (tangle(mesh, chart_quads[c]).first == 0) continue;
    attempt(
        around,
        [&] {
          place_interior(layout, c, lengths, patterns[c], globals[c],
                         detail::FlatteningWeights::Uniform, mesh.vertices);
        },
        longer);
    // (4) Shaken starts: each interior vertex pulled a random part (< 1/2) of the way to a
    // random vertex of the chart, to leave the local optimum the others ended in.
    std::mt19937_64 random(static_cast<uint64_t>(c));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int shake = 0; shake < kShakenStarts && tangle(mesh, chart_quads[c]).first > 0; ++shake)
      attempt(
          around,
          [&] {
            const std::vector<int>& chart_vertices = globals[c];
            for (int v : chart_vertices) {
              if (t.origin[v].chart != c) continue;
              const Vec3 to = mesh.vertices[chart_vertices[random() % chart_vertices.size()]];
              const double f = 0.5 * unit(random);
              for (int d = 0; d < 3; ++d) mesh.vertices[v][d] += f * (to[d] - mesh.vertices[v][d]);
            }
          },
          longer);
  }
}

}  // namespace bimdf::quant
