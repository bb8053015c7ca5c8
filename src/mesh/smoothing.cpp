// smooth_on_surface (quant/tessellate.hpp): damped umbrella smoothing with projection onto the
// input surface. Each free vertex is projected onto the triangles of the chart(s) it belongs
// to rather than onto the whole surface, so that on thin parts it cannot jump to the far side.
#include "mesh/smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "bimdf/quant/tessellate.hpp"
#include "mesh/closest_point.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/quality_polish.hpp"
#include "mesh/smoothing_setup.hpp"
#include "mesh/tangled_regions.hpp"
#include "mesh/untangle.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::quant {
namespace {

// Quads at least this good (scaled Jacobian) may get worse while smoothing, down to this.
constexpr double kGoodEnough = 0.5;
// Vertices whose worst quad is worse than this get the local search.
constexpr double kBad = 0.2;
// Corners closer than this, relative to the quad's longest edge, make a quad bad.
constexpr double kShortEdge = 0.01;
// The untangling phase: at most this many rounds over the vertices near inverted quads, with
// this regularization (untangle.hpp).
constexpr int kUntangleRounds = 50;
constexpr double kUntangleDelta = 0.05;
constexpr int kNewtonSteps = 5;

// Points around `at` in the tangent plane `frame`: 8 directions, 4 distances relative to
// `length`.
std::vector<bimdf::detail::Vec3> tangent_probes(const std::array<bimdf::detail::Vec3, 2>& frame,
                                                const bimdf::detail::Vec3& at, double length) {
  const auto& [t1, t2] = frame;
  std::vector<bimdf::detail::Vec3> probes;
  for (double step : {0.6, 0.3, 0.1, 0.03})
    for (int k = 0; k < 8; ++k) {
      const double c = std::cos(k * std::numbers::pi / 4), s = std::sin(k * std::numbers::pi / 4);
      bimdf::detail::Vec3 p;
      for (int d = 0; d < 3; ++d) p[d] = at[d] + step * length * (c * t1[d] + s * t2[d]);
      probes.push_back(p);
    }
  return probes;
}

// The point of a mesh polyline closest to p (face −1) and its distance (−1: no segment).
bimdf::detail::TriangleTree::Hit closest_on_polyline(const Layout& layout,
                                                     const std::vector<int>& chain,
                                                     const std::array<double, 3>& p) {
  bimdf::detail::TriangleTree::Hit best;
  best.distance = -1;
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    const bimdf::detail::Vec3 q = bimdf::detail::closest_point_on_segment(
        p, layout.mesh.vertices[chain[i]], layout.mesh.vertices[chain[i + 1]]);
    const bimdf::detail::Vec3 pq = bimdf::detail::sub(q, p);
    const double d2 = bimdf::detail::dot(pq, pq);
    if (best.distance < 0 || d2 < best.distance) best = {-1, q, d2};
  }
  // A distance, as TriangleTree::closest gives, so that project() compares like with like.
  if (best.distance > 0) best.distance = std::sqrt(best.distance);
  return best;
}

}  // namespace

SurfaceSmoother::SurfaceSmoother(const Layout& layout, Tessellation& t,
                                 const std::vector<std::vector<int>>* vertex_charts)
    : setup_(std::make_unique<Setup>(layout, t, vertex_charts)) {}

SurfaceSmoother::~SurfaceSmoother() = default;

void SurfaceSmoother::run(const SmoothingOptions& options) {
  run(options, nullptr, Phase::kRelaxAndUntangle);
}

void SurfaceSmoother::run(const SmoothingOptions& options, const std::vector<int>& vertices) {
  run(options, &vertices, Phase::kRelaxAndUntangle);
}

void SurfaceSmoother::reembed_tangled(const SmoothingOptions& options,
                                      const std::vector<int>& vertices,
                                      const std::vector<std::array<double, 3>>* placed) {
  run(options, &vertices, Phase::kTangledRegions, placed);
}

void SurfaceSmoother::polish(const SmoothingOptions& options) {
  run(options, nullptr, Phase::kPolish);
}

void SurfaceSmoother::polish(const SmoothingOptions& options, const std::vector<int>& vertices) {
  run(options, &vertices, Phase::kPolish);
}

bool SurfaceSmoother::can_move(int v) const {
  const Setup& s = *setup_;
  return (!s.charts[v].empty() || s.curve[v] >= 0) && !s.neighbours[v].empty();
}

void SurfaceSmoother::run(const SmoothingOptions& options, const std::vector<int>* only,
                          Phase phase, const std::vector<std::array<double, 3>>* placed) {
  if ((phase == Phase::kPolish ? options.quality_rounds : options.iterations) <= 0) return;
  Setup& s = *setup_;
  const Layout& layout = s.layout;
  QuadMesh& mesh = s.t.mesh;
  const int nv = mesh.num_vertices();
  const std::vector<std::vector<int>>& curve_polylines = s.curve_polylines;
  const std::vector<std::vector<int>>& charts = s.charts;
  const std::vector<int>& curve = s.curve;
  const std::vector<std::vector<std::array<int, 3>>>& corners = s.corners;
  const std::vector<std::vector<int>>& neighbours = s.neighbours;
  const std::vector<std::vector<int>>& vertex_quads = s.vertex_quads;
  // Each chart's triangles for closest points, built on first use and kept for later runs.
  const auto tree = [&](int c) -> const bimdf::detail::TriangleTree* {
    if (c < 0 || layout.charts[c].empty()) return nullptr;
    if (!s.trees[c])
      s.trees[c] =
          std::make_unique<bimdf::detail::TriangleTree>(layout.mesh, layout.charts[c].faces);
    return s.trees[c].get();
  };
  std::vector<int> active;
  if (only) {
    active = *only;
  } else {
    active.resize(nv);
    for (int v = 0; v < nv; ++v) active[v] = v;
  }
  std::vector<char> is_active(nv, 0);
  for (int v : active) is_active[v] = 1;
  // The surface's normal under each quad (at its centre's closest point on its chart): the
  // quality below measures quads against it, so that turning a quad over never looks good.
  // Only the quads at active vertices are ever measured.
  std::vector<int> active_quads;
  for (int f = 0; f < mesh.num_quads(); ++f)
    for (int v : mesh.quads[f])
      if (is_active[v]) {
        active_quads.push_back(f);
        break;
      }
  // The surface's normal at a point: interpolated from its triangle's corner normals (within
  // its chart), not the triangle's own. Where the surface is a quad mesh (requantize), a
  // triangle is half a possibly non-planar quad, and its normal can tilt so far from the
  // surface's that a fine quad measures as turned over against it.
  if (s.corner_normals.empty())
    s.corner_normals = chart_corner_normals(layout.mesh, layout.face_chart);
  const auto surface_normal = [&](const bimdf::detail::TriangleTree::Hit& hit) {
    const auto& tri = layout.mesh.faces[hit.face];
    const bimdf::detail::Vec3 w = bimdf::detail::barycentric_coordinates(
        hit.point, layout.mesh.vertices[tri[0]], layout.mesh.vertices[tri[1]],
        layout.mesh.vertices[tri[2]]);
    bimdf::detail::Vec3 n{0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d)
        n[d] += w[k] * bimdf::detail::normalized(s.corner_normals[hit.face][k])[d];
    return bimdf::detail::norm(n) > 0 ? n : bimdf::detail::triangle_normal(layout.mesh, hit.face);
  };
  std::vector<std::array<double, 3>> up(mesh.num_quads());
  for (int f : active_quads) {
    const std::array<double, 3> centre = bimdf::detail::quad_centre(mesh, mesh.quads[f]);
    const int c = f < static_cast<int>(mesh.quad_patch.size()) ? mesh.quad_patch[f] : -1;
    const bimdf::detail::TriangleTree* under = tree(c);
    up[f] = bimdf::detail::normalized(under ? surface_normal(under->closest(centre))
                                            : bimdf::detail::newell_normal(mesh, mesh.quads[f]));
  }
  // How the quads at v rate, in one pass over them (every candidate position is rated):
  //  * quality: the worst scaled Jacobian among them, against the surface's normal and against
  //    the quad's own (what metrics.hpp reports), where corners closer than kShortEdge of the
  //    longest edge count as bad as an inverted quad, down to −1 when they coincide —
  //    otherwise a vertex could escape an inverted quad by collapsing onto its neighbour
  //    (projection onto a chart clamps to its corner), which the scaled Jacobian does not see;
  //  * turned, worst: how many are turned over (against either normal), and the worst scaled
  //    Jacobian without that penalty. A move may not turn more quads over — the quality alone
  //    does not ensure that when a quad at v already rates below an inverted one: a sliver
  //    would let a move turn a good neighbour over to widen it — unless quads at v are turned
  //    already and the move raises that worst scaled Jacobian while lowering the total by
  //    which they are turned (trading one badly turned quad for two slightly turned ones can
  //    be the way out; the sliver penalty must not count there; but raising the worst by
  //    0.001 must not buy turning a good neighbour over, which untangling then cannot undo).
  struct Rating {
    double quality = 1;
    int turned = 0;
    double worst = 1;
    double turned_amount = 0;  // Σ over turned quads of −(their worse scaled Jacobian)
    double own_worst = 1;      // the worst scaled Jacobian against the quads' own normals
  };
  const auto rate = [&](int v) {
    Rating r;
    for (int f : vertex_quads[v]) {
      const std::array<int, 4>& q = mesh.quads[f];
      const auto [own, under, spread] = bimdf::detail::quad_shape(mesh, q, up[f]);
      if (spread < kShortEdge) r.quality = std::min(r.quality, spread / kShortEdge - 1);
      r.turned += own < 0 || under < 0;
      r.turned_amount += std::max(0.0, -std::min(own, under));
      r.worst = std::min({r.worst, own, under});
      r.own_worst = std::min(r.own_worst, own);
    }
    r.quality = std::min(r.quality, r.worst);
    return r;
  };
  const auto may_turn = [&](const Rating& before, const Rating& after) {
    return after.turned <= before.turned || (before.turned > 0 && after.worst > before.worst &&
                                             after.turned_amount < before.turned_amount);
  };
  // p back on the surface: on v's curve, or on its charts' triangles.
  const auto project = [&](int v, const std::array<double, 3>& p) {
    bimdf::detail::TriangleTree::Hit best;
    best.distance = -1;
    if (curve[v] >= 0) best = closest_on_polyline(layout, curve_polylines[curve[v]], p);
    for (int c : charts[v]) {
      const bimdf::detail::TriangleTree* on = tree(c);
      if (!on) continue;
      const bimdf::detail::TriangleTree::Hit hit = on->closest(p);
      if (best.distance < 0 || hit.distance < best.distance) best = hit;
    }
    return best.distance >= 0 ? best.point : p;
  };
  const auto movable = [&](int v) { return can_move(v); };
  // Positions around v worth trying where its quads are bad (before projection): samples of
  // its tangent plane, and the exact best position for its quads' corner areas and half-way
  // there.
  const auto search_positions = [&](int v) {
    std::vector<bimdf::detail::Vec3> positions;
    const auto frame = bimdf::detail::tangent_frame(mesh, vertex_quads[v]);
    const bimdf::detail::Vec3 at = mesh.vertices[v];
    const double length = bimdf::detail::mean_distance(mesh, neighbours[v], at);
    if (!frame || length == 0) return positions;
    positions = tangent_probes(*frame, at, length);
    if (const auto p = bimdf::detail::max_min_corner_position(mesh, v, vertex_quads[v], up,
                                                              (*frame)[0], (*frame)[1], length)) {
      positions.push_back(*p);
      positions.push_back({(p->at(0) + at[0]) / 2, (p->at(1) + at[1]) / 2, (p->at(2) + at[2]) / 2});
    }
    return positions;
  };
  // One relaxation step of vertex v.
  const auto relax = [&](int v) {
    if (!movable(v)) return;
    // Half the umbrella mean, half the mean of where each quad at v would put v if it were
    // a parallelogram (the corner opposite v mirrored through the other two).
    std::array<double, 3> mean{0, 0, 0};
    for (int w : neighbours[v])
      for (int d = 0; d < 3; ++d) mean[d] += 0.5 * mesh.vertices[w][d] / neighbours[v].size();
    for (const auto& [a, b, c] : corners[v])
      for (int d = 0; d < 3; ++d)
        mean[d] += 0.5 * (mesh.vertices[a][d] + mesh.vertices[c][d] - mesh.vertices[b][d]) /
                   corners[v].size();
    const std::array<double, 3> old = mesh.vertices[v];
    // Where v would go with a step of `damping` towards the mean.
    const auto candidate = [&](double damping) {
      std::array<double, 3> p;
      for (int d = 0; d < 3; ++d) p[d] = (1 - damping) * old[d] + damping * mean[d];
      return project(v, p);
    };
    // Moves in place, and only if the quads at v stay as good as they were or good enough:
    // smoothing never creates an inverted quad and never worsens the worst one. Where the
    // quads at v are bad, longer and shorter steps are tried too, and then a local search
    // in the tangent plane for the position that makes the worst quad best.
    const Rating start = rate(v);
    const double before = start.quality;
    std::array<double, 3> chosen = old;
    double chosen_quality = -2;
    const auto consider = [&](const std::array<double, 3>& p) {
      mesh.vertices[v] = p;
      const Rating r = rate(v);
      if (r.quality > chosen_quality && may_turn(start, r)) chosen_quality = r.quality, chosen = p;
    };
    if (before < kBad)
      for (const bimdf::detail::Vec3& p : search_positions(v)) consider(project(v, p));
    for (double damping : {options.damping, 1.0, 0.25}) {
      consider(candidate(damping));
      if (before >= kGoodEnough) break;
    }
    mesh.vertices[v] = chosen_quality >= std::min(before, kGoodEnough) ? chosen : old;
  };
  if (phase == Phase::kTangledRegions) {
    using Freedom = bimdf::detail::TangledRegionInput::Freedom;
    const auto freedom = [&](int v) {
      if (!movable(v)) return Freedom::kPinned;
      if (curve[v] >= 0) return Freedom::kOnCurve;
      return charts[v].empty() ? Freedom::kPinned : Freedom::kFree;
    };
    const auto smooth = [&](const std::vector<int>& vertices) {
      run(options, &vertices, Phase::kRelaxAndUntangle);
    };
    const auto quality = [&](int f) {
      const auto [own, under, spread] = bimdf::detail::quad_shape(mesh, mesh.quads[f], up[f]);
      return std::array<double, 2>{own, under};
    };
    const auto normal_under = [&](int f) { return up[f]; };
    const bimdf::detail::TangledRegionInput input{
        {mesh, vertex_quads, neighbours, project}, freedom, quality, normal_under, smooth, placed};
    bimdf::detail::reembed_tangled_regions(input, active);
    return;
  }
  if (phase == Phase::kPolish) {
    if (!s.surface) s.surface = std::make_unique<bimdf::detail::TriangleTree>(layout.mesh);
    const auto rating = [&](int v) {
      const Rating r = rate(v);
      return bimdf::detail::PolishInput::Rating{r.quality, r.own_worst, r.turned};
    };
    const auto on_curve = [&](int v) { return curve[v] >= 0; };
    const bimdf::detail::PolishInput polish{
        {mesh, vertex_quads, neighbours, project}, *s.surface, movable, on_curve, rating};
    bimdf::detail::polish_quality(polish, active, options.quality_rounds);
    return;
  }

  for (int iteration = 0; iteration < options.iterations; ++iteration)
    for (int v : active) relax(v);

  // Untangling where quads are still inverted: the vertices near them descend the sum of
  // their quads' untangling energies (untangle.hpp) against both normals. Unlike the
  // max-min quality above, the sum lets a vertex give up some quality of one quad to make
  // room for a neighbour, which frees clusters of vertices that block each other.
  const auto inverted = [&](int f) {
    const auto [own, under, spread] = bimdf::detail::quad_shape(mesh, mesh.quads[f], up[f]);
    return spread < kShortEdge || own < 0 || under < 0;
  };
  const auto inverted_at = [&](int v) {
    int count = 0;
    for (int f : vertex_quads[v]) count += inverted(f);
    return count;
  };
  const auto energy = [&](int v) {
    double sum = 0;
    for (int f : vertex_quads[v]) {
      const std::array<int, 4>& q = mesh.quads[f];
      const bimdf::detail::Vec3 own =
          bimdf::detail::normalized(bimdf::detail::newell_normal(mesh, q));
      sum += bimdf::detail::untangling_energy(mesh, q, up[f], kUntangleDelta) +
             bimdf::detail::untangling_energy(mesh, q, own, kUntangleDelta);
    }
    return sum;
  };
  for (int round = 0; round < kUntangleRounds; ++round) {
    std::set<int> region;
    for (int f : active_quads)
      if (inverted(f))
        for (int v : mesh.quads[f])
          for (int w : neighbours[v]) {
            region.insert(w);
            region.insert(neighbours[w].begin(), neighbours[w].end());
          }
    if (region.empty()) break;
    for (int v : region) {
      if (!is_active[v] || !movable(v)) continue;
      const bimdf::detail::Vec3 old = mesh.vertices[v];
      bimdf::detail::Vec3 chosen = old;
      double lowest = energy(v);
      const int tangled = inverted_at(v);
      const Rating start = rate(v);
      // The energy at p, +∞ where v would tangle more quads, make corners coincide or turn
      // more quads over than may_turn allows (trading a sliver for a turned quad keeps the
      // count of tangled ones).
      const auto allowed_energy = [&](const bimdf::detail::Vec3& p) {
        mesh.vertices[v] = project(v, p);
        return inverted_at(v) <= tangled && may_turn(start, rate(v))
                   ? energy(v)
                   : std::numeric_limits<double>::infinity();
      };
      for (const bimdf::detail::Vec3& p : search_positions(v)) {
        const double e = allowed_energy(p);
        if (e < lowest) lowest = e, chosen = mesh.vertices[v];
      }
      // From the best sample, Newton steps on the energy.
      mesh.vertices[v] = chosen;
      if (const auto frame = bimdf::detail::tangent_frame(mesh, vertex_quads[v])) {
        const bimdf::detail::Vec3 p = bimdf::detail::descend_in_tangent_plane(
            allowed_energy, chosen, (*frame)[0], (*frame)[1],
            bimdf::detail::mean_distance(mesh, neighbours[v], chosen), kNewtonSteps);
        const double e = allowed_energy(p);
        if (e < lowest) lowest = e, chosen = mesh.vertices[v];
      }
      mesh.vertices[v] = chosen;
    }
  }
}

void smooth_on_surface(const Layout& layout, Tessellation& t, const SmoothingOptions& options) {
  if (options.iterations <= 0 && options.quality_rounds <= 0) return;
  SurfaceSmoother smoother(layout, t);
  smoother.run(options);
  smoother.polish(options);
}

}  // namespace bimdf::quant
