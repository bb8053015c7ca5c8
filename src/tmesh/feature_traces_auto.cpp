// FeatureTraces::Auto (requantize.hpp): the second run, with traces ending at feature curves,
// and the rule that keeps one of the two — the coarser layout when its quads and the angle
// bound hold (docs/coarse_layouts.md, "Traces that end at feature curves").
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "core/stopwatch.hpp"

namespace bimdf::tmesh {
namespace {

// "0.949": a scaled Jacobian in a report.
std::string three_decimals(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", x);
  return text;
}

// Adds `other`'s stage times to `kept`'s: a result of two runs reports the work of both.
void add_times(RequantizeResult& kept, const RequantizeResult& other) {
  kept.time_trace_s += other.time_trace_s;
  kept.time_quantize_s += other.time_quantize_s;
  kept.time_collapse_s += other.time_collapse_s;
  kept.time_smoothing_s += other.time_smoothing_s;
}

}  // namespace

bool prefer_coarser_layout(const QuadMeshMetrics& coarser, const QuadMeshMetrics& other,
                           double slack) {
  return coarser.base_complex_faces < other.base_complex_faces &&
         coarser.inverted + coarser.degenerate <= other.inverted + other.degenerate &&
         coarser.scaled_jacobian_mean >= other.scaled_jacobian_mean - slack;
}

// The angle bound is the user's: a coarser layout that breaks it on more separatrices does not
// win (traces ending at feature curves leave the seeds beyond a curve free to slide).
bool stop_wins(const RequantizeResult& cross, const QuadMeshMetrics& cross_metrics,
               const RequantizeResult& stop, const QuadMeshMetrics& stop_metrics, double slack) {
  return prefer_coarser_layout(stop_metrics, cross_metrics, slack) &&
         stop.deviation.over_bound <= cross.deviation.over_bound;
}

bool stop_wins_but_for_bad_quads(const RequantizeResult& cross,
                                 const QuadMeshMetrics& cross_metrics, const RequantizeResult& stop,
                                 const QuadMeshMetrics& stop_metrics, double slack) {
  if (stop_metrics.inverted + stop_metrics.degenerate <=
      cross_metrics.inverted + cross_metrics.degenerate)
    return false;
  QuadMeshMetrics righted = stop_metrics;
  righted.inverted = cross_metrics.inverted;
  righted.degenerate = cross_metrics.degenerate;
  return stop_wins(cross, cross_metrics, stop, righted, slack);
}

RequantizeResult keep_coarser_run(RequantizeResult cross, RequantizeResult stop, double slack) {
  if (stop.given_up_at_base_complex > 0) {
    cross.other_base_complex = stop.given_up_at_base_complex;
    cross.other_failure =
        "given up before smoothing: base complex " + std::to_string(stop.given_up_at_base_complex);
    add_times(cross, stop);
    return cross;
  }
  if (stop.collapsed.mesh.quads.empty()) return cross;
  const QuadMeshMetrics a = measure_quad_mesh(cross.collapsed.mesh);
  const QuadMeshMetrics b = measure_quad_mesh(stop.collapsed.mesh);
  const bool keep_stop = cross.collapsed.mesh.quads.empty() || stop_wins(cross, a, stop, b, slack);
  RequantizeResult& kept = keep_stop ? stop : cross;
  const RequantizeResult& other = keep_stop ? cross : stop;
  const QuadMeshMetrics& other_metrics = keep_stop ? a : b;
  kept.other_base_complex = other_metrics.base_complex_faces;
  kept.other_scaled_jacobian_mean = other_metrics.scaled_jacobian_mean;
  kept.other_over_bound = other.deviation.over_bound;
  add_times(kept, other);
  return std::move(kept);
}

RequantizeResult compare_feature_stops(RequantizeResult cross, const QuadMesh& mesh,
                                       RequantizeOptions options, const std::string& source) {
  if (cross.traced.feature_edges.empty()) return cross;  // nothing to stop at
  const auto start = std::chrono::steady_clock::now();
  const auto report = [&](const char* stage, const std::string& detail) {
    if (options.progress) options.progress({bimdf::detail::seconds_since(start), stage, detail});
  };
  options.trace.cross_features = false;
  // Only a coarser layout can win: give up before smoothing (the costly part, and where
  // couplingdown's traces ending at curves spend minutes in repairs) when it is not.
  const QuadMeshMetrics cross_metrics = measure_quad_mesh(cross.collapsed.mesh);
  options.give_up_at_base_complex = cross_metrics.base_complex_faces;
  const RequantizeOptions with_repairs = options;
  // One smoothing, no repairs after it, at first: a run that leaves quads inverted loses to one
  // that does not anyway, and its repairs (each a smoothing again) took couplingdown at 10° from
  // 2 s to over 3 minutes.
  options.max_split_repairs = 0;
  options.refit_uniform = false;
  const auto run_stop = [&](const RequantizeOptions& o) {
    bimdf::detail::Stopwatch t;
    TracedTMesh traced = trace_tmesh(mesh, o.trace, source);
    const double trace_s = t.lap();
    report("traced", progress_summary(traced.tmesh));
    RequantizeResult r = requantize_tmesh(std::move(traced), &mesh, o, source);
    r.time_trace_s = trace_s;
    return r;
  };
  RequantizeResult stop;
  try {
    stop = run_stop(options);
    // Coarser and as good but for a few bad quads (mech-holes-shark at 45°: one inverted quad,
    // 860 patches against 994): the repairs after smoothing may right them, so the run is made
    // again with them — only here, where it would win, since they cost a smoothing each.
    if (stop.given_up_at_base_complex <= 0 && !stop.collapsed.mesh.quads.empty() &&
        !cross.collapsed.mesh.quads.empty() &&
        (with_repairs.max_split_repairs > 0 || with_repairs.refit_uniform) &&
        stop_wins_but_for_bad_quads(cross, cross_metrics, stop,
                                    measure_quad_mesh(stop.collapsed.mesh),
                                    options.coarser_quality_slack)) {
      report("repair",
             "ending at feature curves left quads inverted or degenerate: run again "
             "with repairs after smoothing");
      RequantizeResult repaired = run_stop(with_repairs);
      add_times(repaired, stop);
      stop = std::move(repaired);
    }
  } catch (const CollapseError& e) {
    cross.other_failure = e.what();
    report("compared", feature_traces_summary(cross));
    return cross;
  }
  RequantizeResult kept =
      keep_coarser_run(std::move(cross), std::move(stop), options.coarser_quality_slack);
  report("compared", feature_traces_summary(kept));
  return kept;
}

OtherRunSummary other_run_summary(const RequantizeResult& r) {
  OtherRunSummary s;
  s.failure = r.other_failure;
  if (r.other_base_complex < 0) return s;
  s.base_complex = r.other_base_complex;
  if (!r.other_failure.empty()) return s;
  s.scaled_jacobian_mean = r.other_scaled_jacobian_mean;
  if (r.deviation.bound_deg >= 0) s.over_bound = r.other_over_bound;
  return s;
}

std::string feature_traces_summary(const RequantizeResult& r) {
  if (r.traced.feature_traces.empty()) return "";
  const bool crossing = r.traced.feature_traces == "cross";
  std::string s = crossing ? "traces cross feature curves" : "traces end at feature curves";
  if (!r.other_failure.empty()) return s + " (ending there: " + r.other_failure + ")";
  if (r.other_base_complex >= 0)
    s += "; kept against " + std::string(crossing ? "ending there" : "crossing them") +
         " (base complex " + std::to_string(r.other_base_complex) + ", mean scaled Jacobian " +
         three_decimals(r.other_scaled_jacobian_mean) + ")";
  return s;
}

}  // namespace bimdf::tmesh
