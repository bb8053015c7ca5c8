// requantize (tmesh/requantize.hpp): the stages in order, each timed.
#include "bimdf/tmesh/requantize.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/stopwatch.hpp"
#include "tmesh/smooth_requantized.hpp"

namespace bimdf::tmesh {
namespace {

// Separation repair (requantize.hpp): for every output vertex that merged two seeds, a
// breadth-first search from one to the other over what merged points — zero arcs (joining
// their ends) and zero-width patches (joining every T-mesh vertex of their two long sides,
// through a node of their own) — and a min-one bound on the element of that path with the
// longest target, added to `bounds`. Returns whether any was added.
bool add_separation_bounds(const TMesh& tm, const std::vector<int64_t>& length,
                           const CollapsedMesh& collapsed, MinOneConstraints& bounds) {
  // Seeds: where non-zero paths start.
  std::vector<char> seed(tm.num_vertices(), 0);
  for (const auto& path : tm.nonzero_paths) seed[tm.half_arc_tail(path.front())] = 1;
  // Nodes: T-mesh vertices, then one per patch and side pair. Edges carry their element:
  // arc a ≥ 0, or −1 − (2·patch + pair).
  const int nv = tm.num_vertices();
  std::vector<std::vector<std::pair<int, int>>> adjacent(nv + 2 * tm.num_patches());
  for (int a = 0; a < tm.num_arcs(); ++a)
    if (length[a] == 0) {
      const auto [u, w] = tm.arc_ends[a];
      adjacent[u].push_back({w, a});
      adjacent[w].push_back({u, a});
    }
  for (int p = 0; p < tm.num_patches(); ++p)
    for (int pair = 0; pair < 2; ++pair) {
      if (side_length(tm, p, pair, length) != 0) continue;
      const int node = nv + 2 * p + pair;
      for (int k : {pair + 1, (pair + 3) % 4})
        for (int h : tm.patch_sides[p][k])
          for (int v : {tm.half_arc_tail(h), tm.half_arc_head(h)}) {
            adjacent[v].push_back({node, -1 - (2 * p + pair)});
            adjacent[node].push_back({v, -1 - (2 * p + pair)});
          }
    }
  const auto target = [&](int element) {
    if (element >= 0) return tm.arc_target[element];
    const int p = (-1 - element) / 2, pair = (-1 - element) % 2;
    double sum = 0;
    for (int k : {pair, pair + 2})
      for (int h : tm.patch_sides[p][k]) sum += tm.arc_target[TMesh::arc_of(h)];
    return sum / 2;
  };
  bool added = false;
  std::vector<std::pair<int, int>> came_from(adjacent.size());  // (node, element)
  for (const CollapsedVertex& o : collapsed.origin) {
    std::vector<int> merged;
    for (int v : o.tmesh_vertices)
      if (seed[v]) merged.push_back(v);
    if (merged.size() < 2) continue;
    std::fill(came_from.begin(), came_from.end(), std::pair<int, int>{-1, 0});
    std::vector<int> queue{merged[0]};
    came_from[merged[0]] = {merged[0], 0};
    for (size_t i = 0; i < queue.size() && came_from[merged[1]].first < 0; ++i)
      for (const auto& [w, element] : adjacent[queue[i]])
        if (came_from[w].first < 0) came_from[w] = {queue[i], element}, queue.push_back(w);
    if (came_from[merged[1]].first < 0) continue;  // merged some other way: not ours to fix
    int best = 0;
    double best_target = -1;
    for (int v = merged[1]; v != merged[0]; v = came_from[v].first)
      if (const int e = came_from[v].second; target(e) > best_target)
        best = e, best_target = target(e);
    if (best >= 0) {
      if (std::find(bounds.arcs.begin(), bounds.arcs.end(), best) != bounds.arcs.end()) continue;
      bounds.arcs.push_back(best);
    } else {
      const SideRef side{(-1 - best) / 2, (-1 - best) % 2};
      if (std::find(bounds.sides.begin(), bounds.sides.end(), side) != bounds.sides.end()) continue;
      bounds.sides.push_back(side);
    }
    added = true;
  }
  return added;
}

// Density calibration (requantize.hpp): quantizations of `tm` with every arc target scaled by
// one factor, until the quad count is within the tolerance of options.target_quads. Secant
// steps on log quads against log factor: quads grow about as the factor squared, less where
// separation holds short arcs at 1 — the measured slope says how much less. Leaves tm's targets
// scaled by the factor of the quantization returned (the closest one).
TMeshQuantization calibrate_density(TMesh& tm, const TMeshIncidence& incidence,
                                    const RequantizeOptions& options, RequantizeResult& r) {
  const std::vector<double> base = tm.arc_target;
  const double wanted = static_cast<double>(options.target_quads);
  const auto quantize_at = [&](double factor) {
    for (size_t a = 0; a < base.size(); ++a) tm.arc_target[a] = base[a] * factor;
    ++r.calibration_solves;
    return quantize_tmesh(tm, incidence, options.quantize);
  };
  double factor = 1;
  TMeshQuantization best = quantize_at(factor);
  if (best.arc_length.empty()) return best;
  double quads = quantized_quads(tm, best.arc_length), best_quads = quads, best_factor = factor;
  double last_factor = 0, last_quads = 0;
  const double limit = std::max(1.0, options.max_density_change);
  while (r.calibration_solves < options.calibration_solves && quads > 0 &&
         std::abs(quads / wanted - 1) > options.calibration_tolerance) {
    double slope = 2;
    if (last_factor > 0 && last_quads > 0 && last_quads != quads) {
      slope = std::log(quads / last_quads) / std::log(factor / last_factor);
      if (!(slope >= 0.5 && slope <= 4)) slope = 2;
    }
    const double next =
        std::clamp(factor * std::exp(std::log(wanted / quads) / slope), 1 / limit, limit);
    if (std::abs(next / factor - 1) < 1e-6) break;  // at a limit
    last_factor = factor, last_quads = quads, factor = next;
    TMeshQuantization q = quantize_at(factor);
    if (q.arc_length.empty()) break;
    quads = quantized_quads(tm, q.arc_length);
    if (std::abs(quads - wanted) < std::abs(best_quads - wanted))
      best = std::move(q), best_quads = quads, best_factor = factor;
  }
  for (size_t a = 0; a < base.size(); ++a) tm.arc_target[a] = base[a] * best_factor;
  r.density_factor = best_factor;
  return best;
}

}  // namespace

RequantizeResult requantize(const QuadMesh& mesh, const RequantizeOptions& options,
                            const std::string& source) {
  detail::Stopwatch t;
  TracedTMesh traced = trace_tmesh(mesh, options.trace, source);
  const double trace_s = t.lap();
  RequantizeResult r = requantize_tmesh(std::move(traced), &mesh, options, source);
  r.time_trace_s = trace_s;
  return r;
}

RequantizeResult requantize_tmesh(TracedTMesh traced, const QuadMesh* mesh,
                                  const RequantizeOptions& options, const std::string& source) {
  RequantizeResult r;
  r.traced = std::move(traced);
  TMesh& tm = r.traced.tmesh;
  detail::Stopwatch t;
  r.incidence = validate_tmesh(tm, source);
  const bool on_mesh = mesh && !tm.patch_grid.empty();
  QuantizeOptions quantize = options.quantize;
  const bool calibrate = options.target_quads > 0 && !quantize.coarse;
  for (bool first = true;; first = false) {
    r.quantization = first && calibrate ? calibrate_density(tm, r.incidence, options, r)
                                        : quantize_tmesh(tm, r.incidence, quantize);
    r.time_quantize_s += t.lap();
    if (r.quantization.arc_length.empty()) return r;
    r.collapsed = collapse_and_tessellate(tm, r.incidence, r.quantization.arc_length,
                                          on_mesh ? mesh : nullptr, options.quantize.relaxed);
    r.time_collapse_s += t.lap();
    if (!add_separation_bounds(tm, r.quantization.arc_length, r.collapsed,
                               quantize.extra_constraints))
      break;
    ++r.repair_rounds;
  }
  r.repair_constraints = quantize.extra_constraints;
  if (on_mesh)
    smooth_requantized(*mesh, tm, r.incidence, r.traced.feature_edges, r.traced.feature_corners,
                       r.collapsed, options.smoothing);
  r.time_smoothing_s = t.lap();
  return r;
}

}  // namespace bimdf::tmesh
