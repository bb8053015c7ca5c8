// quantize_half_arcs and half_arc_bounds (tmesh/half_arc.hpp): the bounds the half-arc model
// keeps, the arc model of the inflated T-mesh with its two-gons, and both checks.
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "bimdf/tmesh/half_arc.hpp"
#include "core/stopwatch.hpp"
#include "tmesh/quantize_stages.hpp"

namespace bimdf::tmesh {
namespace {

// "" when every two-gon's sides have equal lengths under `arc_length` (of T').
std::string check_two_gons(const InflatedTMesh& inflated, const std::vector<int64_t>& arc_length) {
  for (const TwoGon& g : inflated.two_gons) {
    int64_t left = 0, right = 0;
    for (int h : g.left) left += arc_length[TMesh::arc_of(h)];
    for (int h : g.right) right += arc_length[TMesh::arc_of(h)];
    if (left != right)
      return "the two-gon of path " + std::to_string(g.paths[0]) + " has sides " +
             std::to_string(left) + " and " + std::to_string(right);
  }
  return "";
}

}  // namespace

MinOneConstraints half_arc_bounds(const TMesh& tmesh, const TMeshIncidence& incidence,
                                  const InflatedTMesh& inflated, const std::vector<char>& bounded) {
  if (!bounded.empty() && bounded.size() != inflated.two_gons.size())
    throw std::invalid_argument("half_arc_bounds: one bounded flag per two-gon");
  std::vector<int> cover;
  const MinOneConstraints greedy = greedy_min_one_constraints(tmesh, incidence, &cover);
  // Per set of arcs of a relaxed path: whether it keeps Algorithm 2's bounds, and on which side
  // of its line it is measured (0 left, 1 right).
  std::map<std::vector<int>, std::pair<bool, int>> relaxed;
  std::vector<char> cut(tmesh.num_arcs(), 0);
  for (size_t k = 0; k < inflated.two_gons.size(); ++k) {
    const TwoGon& g = inflated.two_gons[k];
    for (size_t j = 0; j < g.paths.size(); ++j)
      relaxed[arcs_along(tmesh.nonzero_paths[g.paths[j]])] = {!bounded.empty() && bounded[k],
                                                              static_cast<int>(j)};
    for (int h : g.left) cut[TMesh::arc_of(h)] = 1;
  }
  MinOneConstraints out;
  // Per bound of Algorithm 2: 1 if it covers a path kept by bounds, 2 / 4 if a relaxed one
  // measured on the left / right of its line.
  std::vector<int> keep(greedy.sides.size() + greedy.arcs.size(), 0);
  for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m) {
    const std::vector<int> arcs = arcs_along(tmesh.nonzero_paths[m]);
    if (arcs.size() == 1)
      out.arcs.push_back(arcs.front());  // exact: the path is its arc
    else if (const auto it = relaxed.find(arcs); it == relaxed.end())
      keep[cover[m]] |= 1;
    else if (it->second.first)
      keep[cover[m]] |= it->second.second == 0 ? 2 : 4;
  }
  for (size_t i = 0; i < greedy.sides.size(); ++i)
    if (keep[i]) out.sides.push_back(greedy.sides[i]);
  for (size_t j = 0; j < greedy.arcs.size(); ++j) {
    const int why = keep[greedy.sides.size() + j], a = greedy.arcs[j];
    if (why && !cut[a]) out.arcs.push_back(a);
    if (!cut[a]) continue;
    if (why & 1)
      for (int h : {2 * a, 2 * a + 1})
        out.sides.push_back({incidence.half_arc_patch[h], incidence.half_arc_side[h]});
    if (why & 2) out.arcs.push_back(a);
    if (why & 4) out.arcs.push_back(inflated.twin[a]);
  }
  detail::sort_unique(out.arcs);
  detail::sort_unique(out.sides);
  return out;
}

std::vector<char> drift_pins(const TwoGon& two_gon, bool keep_crossings) {
  std::vector<char> pinned = two_gon.path_crossing;
  if (keep_crossings)
    for (size_t i = 0; i < pinned.size(); ++i) pinned[i] |= two_gon.crossing[i];
  if (two_gon.paths.size() == 2) pinned[two_gon.left_end] = pinned[two_gon.right_start] = 1;
  return pinned;
}

HalfArcSetup prepare_half_arcs(const TMesh& tmesh, const TMeshIncidence& incidence,
                               double reorder_weight, bool keep_crossings) {
  HalfArcSetup setup;
  setup.relaxed = relaxable_paths(tmesh, incidence, reorder_weight >= 0);
  setup.inflated = inflate_two_gons(tmesh, incidence, setup.relaxed);
  setup.incidence = validate_tmesh(setup.inflated.tmesh, "<inflated t-mesh>");
  const size_t n = setup.inflated.two_gons.size();
  setup.greedy_bounds = half_arc_bounds(tmesh, incidence, setup.inflated, std::vector<char>(n, 1));
  setup.reorder_weight = reorder_weight;
  setup.keep_crossings = keep_crossings;
  set_aligned(setup, tmesh, incidence, std::vector<char>(n, 0));
  return setup;
}

void set_aligned(HalfArcSetup& setup, const TMesh& tmesh, const TMeshIncidence& incidence,
                 std::vector<char> aligned) {
  if (aligned.size() != setup.inflated.two_gons.size())
    throw std::invalid_argument("set_aligned: one flag per two-gon");
  setup.aligned = std::move(aligned);
  setup.bounds = setup.reorder_weight >= 0
                     ? setup.greedy_bounds
                     : half_arc_bounds(tmesh, incidence, setup.inflated, setup.aligned);
}

int align_two_gons(HalfArcSetup& setup, const TMesh& tmesh, const TMeshIncidence& incidence,
                   const std::vector<int>& two_gons) {
  std::vector<char> aligned = setup.aligned;
  aligned.resize(setup.inflated.two_gons.size(), 0);
  int added = 0;
  for (int g : two_gons) {
    if (g < 0 || g >= static_cast<int>(aligned.size()))
      throw std::invalid_argument("align_two_gons: no two-gon " + std::to_string(g));
    added += !aligned[g];
    aligned[g] = 1;
  }
  set_aligned(setup, tmesh, incidence, std::move(aligned));
  return added;
}

TMeshIncidence glued_incidence(const HalfArcSetup& setup) {
  TMeshIncidence glued = setup.incidence;
  for (const TwoGon& g : setup.inflated.two_gons)
    for (size_t i = 0; i < g.left.size(); ++i) {
      const int left_border = TMesh::opposite(g.left[i]),
                right_patched = TMesh::opposite(g.right[i]);
      for (auto [border, across] :
           {std::pair{left_border, right_patched}, std::pair{g.right[i], g.left[i]}}) {
        glued.half_arc_patch[border] = setup.incidence.half_arc_patch[across];
        glued.half_arc_side[border] = setup.incidence.half_arc_side[across];
      }
    }
  return glued;
}

namespace {

// One solve of T''s arc model with `bounds` (and options.extra_constraints), two-gons exact
// (reorder_weight < 0) or bounded at that weight.
TMeshQuantization solve_inflated(const HalfArcSetup& setup, const MinOneConstraints& bounds,
                                 double reorder_weight, bool drift_tie_break,
                                 const QuantizeOptions& options) {
  TMeshQuantization q;
  bimdf::detail::Stopwatch t;
  const TMesh& cut = setup.inflated.tmesh;
  q.constraints = bounds;
  add_constraints(q.constraints, options.extra_constraints);
  ArcModelOptions model;
  model.arc_weight.assign(cut.num_arcs(), 1.0);
  for (int a = 0; a < cut.num_arcs(); ++a)
    if (setup.inflated.twin[a] >= 0) model.arc_weight[a] = 0.5;
  for (const TwoGon& g : setup.inflated.two_gons) model.two_gons.push_back(two_gon_zip(g));
  model.two_gon_reorder_weight = reorder_weight;
  model.two_gon_drift_tie_break = drift_tie_break;
  model.two_gon_aligned = setup.aligned;
  for (const TwoGon& g : setup.inflated.two_gons)
    model.two_gon_split.push_back({g.left_end, g.right_start});
  for (const TwoGon& g : setup.inflated.two_gons)
    model.two_gon_pinned.push_back(drift_pins(g, setup.keep_crossings));
  q.time_model_s = t.lap();
  detail::run_quantization(cut, setup.incidence, q.constraints, model, options, q);
  return q;
}

bool no_worse(double x, double than) { return x <= than + 1e-9 * std::max(1.0, std::fabs(than)); }

}  // namespace

TMeshQuantization quantize_inflated(const HalfArcSetup& setup, const QuantizeOptions& options) {
  if (options.relaxed)
    throw std::invalid_argument("half-arc quantization does not combine with relaxed patches");
  TMeshQuantization q = solve_inflated(setup, setup.bounds, setup.reorder_weight, false, options);
  const bool any_free = std::count(setup.aligned.begin(), setup.aligned.end(), 0) > 0;
  if (setup.reorder_weight < 0 && any_free && !q.arc_length.empty()) {
    TMeshQuantization tie =
        solve_inflated(setup, setup.greedy_bounds, kDriftTieBreak, true, options);
    tie.time_model_s += q.time_model_s;
    tie.time_solve_s += q.time_solve_s;
    if (tie.arc_length.empty() || !no_worse(tie.coarse_objective, q.coarse_objective) ||
        !no_worse(tie.objective, q.objective)) {
      q.time_model_s = tie.time_model_s;
      q.time_solve_s = tie.time_solve_s;
    } else {
      tie.constraints = std::move(q.constraints);  // the exact model's
      q = std::move(tie);
    }
  }
  if (q.arc_length.empty()) return q;
  const TMesh& cut = setup.inflated.tmesh;
  std::string error = check_quantization(cut, q.arc_length);
  if (error.empty()) error = check_two_gons(setup.inflated, q.arc_length);
  if (!error.empty()) throw std::logic_error("half-arc quantization failed its check: " + error);
  return q;
}

HalfArcQuantization quantize_half_arcs(const TMesh& tmesh, const TMeshIncidence& incidence,
                                       const QuantizeOptions& options, double reorder_weight,
                                       bool keep_crossings) {
  HalfArcQuantization r;
  static_cast<HalfArcSetup&>(r) =
      prepare_half_arcs(tmesh, incidence, reorder_weight, keep_crossings);
  r.quantization = quantize_inflated(r, options);
  if (r.quantization.arc_length.empty()) return r;
  r.half_arc_length = half_arc_lengths(tmesh, r.inflated, r.quantization.arc_length);
  const std::string error =
      check_half_arc_quantization(tmesh, r.inflated.two_gons, r.half_arc_length);
  if (!error.empty()) throw std::logic_error("half-arc quantization failed its check: " + error);
  return r;
}

}  // namespace bimdf::tmesh
