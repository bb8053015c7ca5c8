// quantize_tmesh (tmesh/quantize.hpp): Algorithm 2, the arc model, the exact solve, the check —
// twice for a coarse layout (the coarse objective picks the zero arcs, the deviation sets the
// others' lengths).
#include "bimdf/tmesh/quantize.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bimdf/solve.hpp"
#include "core/stopwatch.hpp"
#include "tmesh/quantize_stages.hpp"
#include "tmesh/strip_lengths.hpp"

namespace bimdf::tmesh {
namespace {

// Solves `model` exactly; fills status, objective, solution and lengths of `result`.
void solve_model(const ArcModel& model, const QuantizeOptions& options, TMeshQuantization& result,
                 bool drift_tie_break) {
  bimdf::detail::Stopwatch t;
  Solver solver(model.problem);
  solver.threads(options.threads);
  if (options.time_limit >= 0) solver.time_limit(options.time_limit);
  result.status = solver.run();
  result.time_solve_s += t.lap();
  result.solution = solver.solution();
  result.nodes = model.problem.num_nodes();
  result.edges = model.problem.num_edges();
  if (result.status != SolveStatus::Optimal && result.status != SolveStatus::Feasible) return;
  result.objective = result.solution.objective;
  // A drift cost that only breaks ties is no part of the objective (linear: slope × flow).
  if (drift_tie_break)
    for (int e : model.drift_edges)
      result.objective -=
          model.problem.cost[e].slope() * static_cast<double>(result.solution.flow[e]);
  result.arc_length = arc_lengths(model, result.solution.flow);
}

// Σ over patches of the product of the mean lengths of the two side pairs, `side(p, k)` being
// side k's length.
template <class SideLength>
double sum_of_patch_areas(const TMesh& tmesh, SideLength side) {
  double area = 0;
  for (int p = 0; p < tmesh.num_patches(); ++p)
    area += (side(p, 0) + side(p, 2)) / 2 * ((side(p, 1) + side(p, 3)) / 2);
  return area;
}

}  // namespace

double quantized_quads(const TMesh& tmesh, const std::vector<int64_t>& arc_length) {
  return sum_of_patch_areas(tmesh, [&](int p, int k) {
    return static_cast<double>(side_length(tmesh, p, k, arc_length));
  });
}

double target_quads(const TMesh& tmesh) {
  return sum_of_patch_areas(tmesh, [&](int p, int k) {
    double sum = 0;
    for (int h : tmesh.patch_sides[p][k]) sum += tmesh.arc_target[TMesh::arc_of(h)];
    return sum;
  });
}

namespace detail {

void run_quantization(const TMesh& tmesh, const TMeshIncidence& incidence,
                      const MinOneConstraints& constraints, ArcModelOptions model_options,
                      const QuantizeOptions& options, TMeshQuantization& result) {
  bimdf::detail::Stopwatch t;
  model_options.cost = options.cost;
  model_options.coarse = options.coarse;
  model_options.side_weight = options.side_weight;
  model_options.relaxed = options.relaxed;
  model_options.relaxed_weight = options.relaxed_weight;
  ArcModel model = build_arc_model(tmesh, incidence, constraints, model_options);
  result.time_model_s += t.lap();
  solve_model(model, options, result, model_options.two_gon_drift_tie_break);
  if (options.coarse && options.coarse_uniform && !result.arc_length.empty()) {
    // Every coarse length times one integer k: the layout's combinatorics, and so its base
    // complex, stay exactly those of the coarse stage; k brings the area (Σ width × height)
    // closest to the targets' area.
    result.coarse_objective = result.objective;
    if (options.coarse_strips) {
      double mean = 0;
      result.arc_length =
          strip_refined_lengths(tmesh, result.arc_length, model_options.two_gons, &mean);
      result.coarse_factor = std::max<int64_t>(1, std::llround(mean));
      result.strip_lengths = true;
      for (int64_t x : result.arc_length) result.zero_arcs += x == 0;
      return;
    }
    const double area = quantized_quads(tmesh, result.arc_length);
    const double target_area = target_quads(tmesh);
    const int64_t k =
        area > 0 ? std::max<int64_t>(1, std::llround(std::sqrt(target_area / area))) : 1;
    for (int64_t& x : result.arc_length) x *= k;
    result.coarse_factor = k;
  } else if (options.coarse && !result.arc_length.empty()) {
    result.coarse_objective = result.objective;
    t.lap();
    model_options.coarse = false;
    model_options.arc_pattern.resize(tmesh.num_arcs());
    for (int a = 0; a < tmesh.num_arcs(); ++a)
      model_options.arc_pattern[a] = result.arc_length[a] > 0 ? 1 : 0;
    model = build_arc_model(tmesh, incidence, constraints, model_options);
    result.time_model_s += t.lap();
    solve_model(model, options, result, model_options.two_gon_drift_tie_break);
    // The coarse solution itself satisfies the fixed pattern: this stage cannot be infeasible.
    if (result.arc_length.empty())
      throw std::logic_error("coarse quantization: the fixed zero pattern became infeasible");
  }
  if (result.arc_length.empty()) return;
  for (int64_t x : result.arc_length) result.zero_arcs += x == 0;
}

}  // namespace detail

TMeshQuantization quantize_tmesh(const TMesh& tmesh, const TMeshIncidence& incidence,
                                 const QuantizeOptions& options) {
  TMeshQuantization result;
  bimdf::detail::Stopwatch t;
  result.constraints = greedy_min_one_constraints(tmesh, incidence);
  add_constraints(result.constraints, options.extra_constraints);
  result.time_model_s = t.lap();
  detail::run_quantization(tmesh, incidence, result.constraints, {}, options, result);
  if (result.arc_length.empty()) return result;
  const std::string error = options.relaxed ? check_relaxed_quantization(tmesh, result.arc_length)
                                            : check_quantization(tmesh, result.arc_length);
  if (!error.empty()) throw std::logic_error("quantization failed its check: " + error);
  for (int p = 0; p < tmesh.num_patches(); ++p)
    result.irregular_patches += is_irregular_patch(tmesh, p, result.arc_length);
  return result;
}

void add_constraints(MinOneConstraints& to, const MinOneConstraints& extra) {
  to.arcs.insert(to.arcs.end(), extra.arcs.begin(), extra.arcs.end());
  to.sides.insert(to.sides.end(), extra.sides.begin(), extra.sides.end());
  to.arcs_two.insert(to.arcs_two.end(), extra.arcs_two.begin(), extra.arcs_two.end());
}

}  // namespace bimdf::tmesh
