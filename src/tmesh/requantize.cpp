// requantize (tmesh/requantize.hpp): the stages in order, each timed.
#include "bimdf/tmesh/requantize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "bimdf/error.hpp"
#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/separatrix_deviation.hpp"
#include "core/stopwatch.hpp"
#include "tmesh/density_search.hpp"
#include "tmesh/separation_repair.hpp"
#include "tmesh/smooth_requantized.hpp"

namespace bimdf::tmesh {
namespace {

// Density calibration (requantize.hpp): quantizations of `tm` with every arc target scaled by
// one factor (`base`: the targets as given), searched by search_density_factor_within_reach from
// r.density_factor (the previous round's, after a repair added bounds). Leaves tm's targets
// scaled by the factor of the quantization returned (the closest one).
TMeshQuantization calibrate_density(TMesh& tm, const std::vector<double>& base,
                                    const std::function<TMeshQuantization()>& quantize,
                                    const RequantizeOptions& options, RequantizeResult& r) {
  const double wanted = static_cast<double>(options.target_quads);
  // Every quantization the search runs, kept until it has chosen one (a few, each O(arcs)).
  std::vector<std::pair<double, TMeshQuantization>> runs;
  const detail::DensitySearch found = detail::search_density_factor_within_reach(
      wanted, r.density_factor, options.calibration_tolerance, options.calibration_solves,
      std::max(1.0, options.max_density_change), options.max_density_reach, [&](double factor) {
        for (size_t a = 0; a < base.size(); ++a) tm.arc_target[a] = base[a] * factor;
        runs.emplace_back(factor, quantize());
        const TMeshQuantization& q = runs.back().second;
        return q.arc_length.empty() ? -1.0 : quantized_quads(tm, q.arc_length);
      });
  r.calibration_solves += found.solves;
  r.calibration_floor = found.floor_quads;
  // The first run when it failed (its status is reported), else the one chosen.
  size_t chosen = 0;
  if (found.quads >= 0)
    while (chosen + 1 < runs.size() && runs[chosen].first != found.factor) ++chosen;
  const double best_factor = runs[chosen].first;
  TMeshQuantization best = std::move(runs[chosen].second);
  for (size_t a = 0; a < base.size(); ++a) tm.arc_target[a] = base[a] * best_factor;
  if (found.quads >= 0) r.density_factor = best_factor;
  return best;
}

// A figure for a progress report: six significant digits.
std::string figure(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// "1 quad", "3 quads": a count for a progress report (`plural`: the noun + "s" if empty).
std::string counted(size_t n, const std::string& noun, const std::string& plural = "") {
  return std::to_string(n) + " " + (n == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

}  // namespace

std::string progress_summary(const TMesh& tmesh) {
  return counted(tmesh.num_patches(), "patch", "patches") + ", " +
         counted(tmesh.num_arcs(), "arc") + ", " +
         counted(tmesh.nonzero_paths.size(), "non-zero path");
}

std::string set_half_arc_mode(RequantizeOptions& options, const std::string& mode,
                              double reorder_weight) {
  if (mode != "auto" && mode != "exact" && mode != "bounded" && mode != "off")
    throw std::invalid_argument("the half-arc mode must be auto, exact, bounded or off, not '" +
                                mode + "'");
  const std::string used = mode != "auto"                                         ? mode
                           : options.quantize.coarse && !options.quantize.relaxed ? "bounded"
                                                                                  : "off";
  options.half_arc = used != "off";
  options.reorder_weight = used == "bounded" ? reorder_weight : -1;
  return used;
}

double mean_edge_length(const QuadMesh& mesh) {
  double sum = 0;
  for (const auto& q : mesh.quads)
    for (int a = 0; a < 4; ++a) {
      const auto& p = mesh.vertices[q[a]];
      const auto& r = mesh.vertices[q[(a + 1) % 4]];
      sum += std::sqrt((p[0] - r[0]) * (p[0] - r[0]) + (p[1] - r[1]) * (p[1] - r[1]) +
                       (p[2] - r[2]) * (p[2] - r[2]));
    }
  return mesh.quads.empty() ? 0 : sum / (4.0 * mesh.quads.size());
}

double requested_density(const QuadMesh& mesh, double scale, double edge_length,
                         int64_t target_faces, const std::string& source) {
  if (mesh.quads.empty()) throw std::invalid_argument("the quad mesh has no quads");
  if (target_faces > 0) return std::sqrt(static_cast<double>(target_faces) / mesh.num_quads());
  if (edge_length > 0) {
    const double mean = mean_edge_length(mesh);
    if (!(mean > 0)) throw InputError(source, "", kCoincidentVertices);
    return mean / edge_length;
  }
  if (!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("the scale must be a positive number");
  return 1 / scale;
}

RequantizeResult requantize(const QuadMesh& mesh, const RequantizeOptions& options,
                            const std::string& source) {
  const bool bounded = options.trace.max_angle_deg >= 0;
  if (bounded && options.feature_traces == FeatureTraces::Auto) {
    const auto start = std::chrono::steady_clock::now();
    RequantizeOptions one = options;
    one.feature_traces = FeatureTraces::Cross;
    RequantizeResult cross = requantize(mesh, one, source);
    const double offset = bimdf::detail::seconds_since(start);
    if (options.progress)
      one.progress = [&](RequantizeProgress p) {  // elapsed since this call, as promised
        p.elapsed_s += offset;
        options.progress(p);
      };
    return compare_feature_stops(std::move(cross), mesh, one, source);
  }
  bimdf::detail::Stopwatch t;
  TraceOptions trace = options.trace;
  if (options.feature_traces != FeatureTraces::Auto)
    trace.cross_features = options.feature_traces == FeatureTraces::Cross;
  TracedTMesh traced = trace_tmesh(mesh, trace, source);
  const double trace_s = t.lap();
  RequantizeOptions timed = options;
  if (options.progress) {
    options.progress({trace_s, "traced", progress_summary(traced.tmesh)});
    timed.progress = [&](RequantizeProgress p) {
      p.elapsed_s += trace_s;
      options.progress(p);
    };
  }
  RequantizeResult r = requantize_tmesh(std::move(traced), &mesh, timed, source);
  r.time_trace_s = trace_s;
  return r;
}

RequantizeResult requantize_tmesh(TracedTMesh traced, const QuadMesh* mesh,
                                  const RequantizeOptions& options, const std::string& source) {
  RequantizeResult r;
  r.traced = std::move(traced);
  bimdf::detail::Stopwatch t;
  const auto start = std::chrono::steady_clock::now();
  const auto report = [&](const char* stage, const std::string& detail) {
    if (options.progress) options.progress({bimdf::detail::seconds_since(start), stage, detail});
  };
  r.incidence = validate_tmesh(r.traced.tmesh, source);
  // The T-mesh every stage below works on: the input, or it cut open along the two-gons, whose
  // repairs and smoothing see the cuts glued (the zips close them in the collapse).
  TMeshIncidence glued;
  std::vector<Zip> zips;
  std::vector<std::vector<int>> more_charts;
  std::vector<std::vector<int>> two_gons_at;  // per patch: the two-gons along it
  if (options.half_arc) {
    if (options.quantize.relaxed)
      throw std::invalid_argument("half-arc quantization does not combine with relaxed patches");
    r.half_arc = prepare_half_arcs(r.traced.tmesh, r.incidence, options.reorder_weight,
                                   options.keep_crossings);
    glued = glued_incidence(*r.half_arc);
    report("half-arc", counted(r.half_arc->relaxed.size(), "non-zero path") + " cut open into " +
                           counted(r.half_arc->inflated.two_gons.size(), "two-gon") + " (" +
                           (options.reorder_weight >= 0 ? "bounded" : "exact") + ")");
    for (const TwoGon& g : r.half_arc->inflated.two_gons) zips.push_back(two_gon_zip(g));
    more_charts.resize(r.traced.tmesh.num_patches());
    two_gons_at.resize(r.traced.tmesh.num_patches());
    for (size_t k = 0; k < r.half_arc->inflated.two_gons.size(); ++k) {
      const TwoGon& g = r.half_arc->inflated.two_gons[k];
      // A left copy's half-arcs lie on the patches left of the path and (glued) right of it.
      std::vector<int> along;
      for (int h : g.left)
        for (int half : {h, TMesh::opposite(h)}) along.push_back(glued.half_arc_patch[half]);
      std::sort(along.begin(), along.end());
      along.erase(std::unique(along.begin(), along.end()), along.end());
      for (int p : along) {
        more_charts[p].insert(more_charts[p].end(), along.begin(), along.end());
        two_gons_at[p].push_back(static_cast<int>(k));
      }
    }
  }
  TMesh& tm = r.half_arc ? r.half_arc->inflated.tmesh : r.traced.tmesh;
  const TMeshIncidence& cut_incidence = r.half_arc ? r.half_arc->incidence : r.incidence;
  const TMeshIncidence& incidence = r.half_arc ? glued : r.incidence;
  // Half-arc repair: the two-gons along `patches` (all: every two-gon) not aligned yet.
  const auto unaligned = [&](const std::vector<int>& patches, bool all) {
    std::vector<int> two_gons;
    if (!r.half_arc) return two_gons;
    for (int p : patches)
      if (p >= 0 && p < static_cast<int>(two_gons_at.size()))
        for (int k : two_gons_at[p])
          if (!r.half_arc->aligned[k]) two_gons.push_back(k);
    for (int k = 0; all && k < static_cast<int>(r.half_arc->aligned.size()); ++k)
      if (!r.half_arc->aligned[k]) two_gons.push_back(k);
    return two_gons;
  };
  const auto align = [&](const std::vector<int>& two_gons, const std::string& why) {
    // `two_gons` may repeat one (once per patch it runs along): count those aligned now.
    const int aligned = align_two_gons(*r.half_arc, r.traced.tmesh, r.incidence, two_gons);
    ++r.repair_rounds;
    report("repair", why + ": " + counted(aligned, "two-gon") + " held to the arc quantization");
  };
  const bool on_mesh = mesh && !tm.patch_grid.empty();
  // The angle bound the separatrices are measured against (< 0: none; 90 bounds nothing).
  const double angle_bound = options.trace.max_angle_deg >= 0 && options.trace.max_angle_deg < 90
                                 ? options.trace.max_angle_deg
                                 : -1;
  QuantizeOptions quantize = options.quantize;
  const auto quantize_once = [&] {
    return r.half_arc ? quantize_inflated(*r.half_arc, quantize)
                      : quantize_tmesh(tm, r.incidence, quantize);
  };
  // Calibrated again after every repair: the bounds a repair adds raise the quad count.
  const bool calibrate = options.target_quads > 0 && !quantize.coarse;
  const std::vector<double> base = tm.arc_target;
  // The last smoothed result and its inverted and degenerate quads, kept while a quad-splitting
  // repair tries another quantization: restored when that one is infeasible (bounds of 2 can
  // conflict with arcs fixed to 0) or smooths no better (the split quad's halves can stay
  // inverted, or turn others over).
  std::optional<RequantizeResult> smoothed;
  SmoothedQuads smoothed_left;
  int smoothed_bad = 0, smoothed_rounds = 0, aligned_rounds = 0;
  bool aligning = false;  // the last repair aligned two-gons
  const auto restore_smoothed = [&] {
    const double quantize_s = r.time_quantize_s, collapse_s = r.time_collapse_s,
                 smoothing_s = r.time_smoothing_s;
    r = std::move(*smoothed);
    r.time_quantize_s = quantize_s;
    r.time_collapse_s = collapse_s;
    r.time_smoothing_s = smoothing_s;
  };
  // A coarsening never grows the base complex (greedy's does not). Drift that splits a line of
  // the layout (a crossing moved apart) can: then every two-gon is aligned and the T-mesh
  // solved again, once.
  int base_complex_in = -1;
  for (bool again = true; again;) {
    again = false;
    for (;;) {
      r.quantization =
          calibrate ? calibrate_density(tm, base, quantize_once, options, r) : quantize_once();
      r.time_quantize_s += t.lap();
      {
        const TMeshQuantization& q = r.quantization;
        std::string found(status_name(q.status));
        if (!q.arc_length.empty())
          found += ", objective " + figure(q.objective) + ", " + std::to_string(q.zero_arcs) +
                   " arcs of length 0";
        if (calibrate) found += ", density factor " + figure(r.density_factor);
        report("quantized", found);
      }
      if (r.quantization.arc_length.empty()) {
        if (smoothed) restore_smoothed();
        return r;
      }
      // A border loop shorter than 3 is found on the lengths alone (and its collapse would be
      // refused): solve again before collapsing.
      if (add_border_loop_bounds(tm, incidence, r.quantization.arc_length,
                                 quantize.extra_constraints)) {
        ++r.repair_rounds;
        report("repair", "a border loop shorter than 3 edges: bounded");
        continue;
      }
      try {
        r.collapsed =
            collapse_and_tessellate(tm, cut_incidence, r.quantization.arc_length,
                                    on_mesh ? mesh : nullptr, options.quantize.relaxed, zips);
      } catch (const CollapseError& e) {
        if (!r.half_arc) {
          if (!add_collapse_failure_bounds(tm, r.quantization.arc_length, e.patches(),
                                           quantize.extra_constraints))
            throw;
          ++r.repair_rounds;
          report("repair", std::string(e.what()) + ": a zero element there bounded");
          continue;
        }
        // Drift the zips cannot close (two T-mesh vertices zipped into an interior vertex of two
        // quads, say): hold the two-gons there to the arc quantization and solve again.
        if (const std::vector<int> two_gons = unaligned(e.patches(), false); !two_gons.empty()) {
          align(two_gons, "the collapse could not close the two-gons");
          continue;
        }
        // The separation repairs act on a collapse that succeeded; a half-arc quantization that
        // zips two T-mesh vertices into an interior vertex of two quads (say) has none. Arcs
        // only, then, as the result says.
        RequantizeOptions arcs_only = options;
        arcs_only.half_arc = false;
        report("fallback", std::string(e.what()) + ": quantizing the arcs instead");
        RequantizeResult fallback = requantize_tmesh(std::move(r.traced), mesh, arcs_only, source);
        fallback.half_arc_fallback = e.what();
        fallback.time_quantize_s += r.time_quantize_s;
        fallback.time_collapse_s += r.time_collapse_s + t.lap();
        return fallback;
      }
      r.time_collapse_s += t.lap();
      report("collapsed", counted(r.collapsed.mesh.quads.size(), "quad"));
      // Both checks run, so that one round bounds every fault found.
      const bool merged = add_separation_bounds(tm, incidence, r.quantization.arc_length,
                                                r.collapsed, quantize.extra_constraints);
      const bool folded = add_valence_bounds(tm, r.quantization.arc_length, r.collapsed,
                                             quantize.extra_constraints);
      if (merged || folded) {
        ++r.repair_rounds;
        report("repair", merged ? "the collapse merged separated vertices: bounded"
                                : "a vertex lost its valence in the collapse: bounded");
        continue;
      }
      // Half-arc under an angle bound: the model bounds no drift (a two-gon's sides may slide
      // past each other by any amount), so a separatrix crossing a drifting two-gon can turn
      // past the bound the traces kept. Measured here, on the collapse's grid places (before
      // smoothing, cheap): the two-gons along such separatrices are held to the arc
      // quantization and the T-mesh solved again, until none turns past it or all are held.
      if (r.half_arc && options.hold_angle_bound && on_mesh && angle_bound >= 0) {
        const double bound = angle_bound;
        const SeparatrixDeviation d = measure_separatrix_deviation(*mesh, tm, r.collapsed, bound);
        if (d.over_bound > 0) {
          std::vector<int> patches;
          for (const SeparatrixDeviation::Measured& line : d.separatrices)
            if (!line.to_border && line.deg > bound + 1e-9)
              patches.insert(patches.end(), line.patches.begin(), line.patches.end());
          if (const std::vector<int> two_gons = unaligned(patches, false); !two_gons.empty()) {
            align(two_gons, counted(d.over_bound, "separatrix", "separatrices") +
                                " turned past the angle bound");
            continue;
          }
        }
      }
      r.repair_constraints = quantize.extra_constraints;
      if (options.give_up_at_base_complex > 0 && !smoothed) {
        const int patches = measure_quad_mesh(r.collapsed.mesh).base_complex_faces;
        if (patches >= options.give_up_at_base_complex) {
          r.given_up_at_base_complex = patches;
          report("given up", "base complex " + std::to_string(patches) + " before smoothing");
          return r;
        }
      }
      if (!on_mesh) break;
      SmoothedQuads left =
          smooth_requantized(*mesh, tm, incidence, r.traced.feature_edges, r.traced.feature_corners,
                             r.collapsed, options.smoothing, more_charts);
      r.time_smoothing_s += t.lap();
      report("smoothed", counted(left.inverted, "quad") + " inverted, " +
                             std::to_string(left.degenerate) + " degenerate");
      int bad = left.inverted + left.degenerate;
      if (smoothed && bad >= smoothed_bad) {
        report("repair", "no better than before the last repair: that result kept");
        restore_smoothed();
        if (!aligning) break;
        // Aligning did not help there: no more of it; a split may still.
        left = smoothed_left;
        bad = smoothed_bad;
        aligned_rounds = options.max_split_repairs;
      }
      aligning = false;
      const auto keep_smoothed = [&] {
        smoothed = r;
        smoothed_left = left;
        smoothed_bad = bad;
      };
      // Half-arc: quads smoothing did not right (inverted or degenerate) where the re-embedding
      // could not follow the drift of a two-gon along them: align those two-gons and solve again.
      if (r.half_arc && aligned_rounds < options.max_split_repairs) {
        std::vector<int> patches;
        for (const std::vector<int>* quads : {&left.to_split, &left.degenerate_quads})
          for (int f : *quads) patches.push_back(r.collapsed.mesh.quad_patch[f]);
        if (const std::vector<int> two_gons = unaligned(patches, false); !two_gons.empty()) {
          keep_smoothed();
          align(two_gons, "quads smoothing did not right along two-gons");
          ++aligned_rounds;
          aligning = true;
          continue;
        }
      }
      // Quads smoothing did not right: split them by bounding the quantization and smooth the
      // new one, a few times at most (each round smooths the whole mesh again); where no split
      // reaches them, other lengths: strip lengths give way to one factor, and uniform coarse
      // lengths to fitted ones (inverted quads only: those grow the base complex). Flat quads
      // get no split, only the first.
      const bool only_flat = left.to_split.empty();
      if ((only_flat && left.degenerate_quads.empty()) ||
          smoothed_rounds >= options.max_split_repairs)
        break;
      MinOneConstraints bounds = quantize.extra_constraints;
      const bool split =
          add_quad_split_bounds(tm, r.quantization.arc_length, r.collapsed, left.to_split, bounds);
      // Lengths per strip can squeeze a quad flat where one factor for the mesh does not (elk at
      // 45°, ending at feature curves): the same zero arcs, so the same base complex — tried
      // before fitted lengths, which grow it.
      const bool unstrip =
          !split && options.refit_uniform && quantize.coarse_uniform && quantize.coarse_strips;
      const bool refit =
          !split && !unstrip && !only_flat && options.refit_uniform && quantize.coarse_uniform;
      if (!split && !unstrip && !refit) break;
      keep_smoothed();
      // Half-arc: before fitted lengths grow the base complex, every two-gon held to arcs — the
      // half-arc optimum's other choices may be what stretched those quads.
      if (refit && r.half_arc && aligned_rounds < options.max_split_repairs) {
        if (const std::vector<int> two_gons = unaligned({}, true); !two_gons.empty()) {
          align(two_gons, "quads no split reaches");
          ++aligned_rounds;
          aligning = true;
          continue;
        }
      }
      if (split) quantize.extra_constraints = std::move(bounds);
      if (unstrip) quantize.coarse_strips = false;
      if (refit) quantize.coarse_uniform = false;
      ++smoothed_rounds;
      ++r.repair_rounds;
      report("repair", split ? counted(left.to_split.size(), "quad") + " split"
                       : unstrip
                           ? "quads no split reaches: one coarse factor instead of one per strip"
                           : "quads no split reaches: the coarse lengths fitted");
    }
    if (r.half_arc && options.quantize.coarse && on_mesh && !r.collapsed.mesh.quads.empty()) {
      if (base_complex_in < 0) base_complex_in = measure_quad_mesh(*mesh).base_complex_faces;
      const std::vector<int> two_gons = unaligned({}, true);
      const int base_complex =
          two_gons.empty() ? 0 : measure_quad_mesh(r.collapsed.mesh).base_complex_faces;
      if (!two_gons.empty() && base_complex > base_complex_in) {
        align(two_gons, "the base complex grew (" + std::to_string(base_complex_in) + " faces to " +
                            std::to_string(base_complex) + ")");
        smoothed.reset();
        aligning = false;
        smoothed_rounds = aligned_rounds = 0;
        quantize.coarse_uniform = options.quantize.coarse_uniform;
        quantize.coarse_strips = options.quantize.coarse_strips;
        again = true;
      }
    }
  }
  r.coarse_refitted = options.quantize.coarse && options.quantize.coarse_uniform &&
                      r.quantization.coarse_factor == 0;
  if (r.half_arc && !r.quantization.arc_length.empty()) {
    const DeflatedTMesh d = deflate_two_gons(r.half_arc->inflated, r.quantization.arc_length);
    r.adapted_arcs = d.tmesh.num_arcs();
    r.aligned_two_gons =
        static_cast<int>(std::count(r.half_arc->aligned.begin(), r.half_arc->aligned.end(), 1));
    r.reordered_junctions = d.reordered_junctions;
    // The input keeps the calibrated targets too (its arcs are T''s first ones).
    for (int a = 0; a < r.traced.tmesh.num_arcs(); ++a)
      r.traced.tmesh.arc_target[a] = tm.arc_target[a];
  }
  if (on_mesh && !r.collapsed.mesh.quads.empty())
    r.deviation = measure_separatrix_deviation(*mesh, r, angle_bound);
  return r;
}

}  // namespace bimdf::tmesh
