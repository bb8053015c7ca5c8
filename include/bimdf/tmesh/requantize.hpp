// Re-quantizing a quad mesh (issue 21): the whole pipeline in one call — motorcycle T-mesh
// (from_quad_mesh.hpp), exact quantization with zero-length arcs (quantize.hpp), collapse and
// tessellation (collapse.hpp), smoothing on the input surface with features and border kept.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "bimdf/mesh.hpp"
#include "bimdf/metrics.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/half_arc.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "bimdf/tmesh/separatrix_deviation.hpp"

namespace bimdf::tmesh {

// One progress report of requantize (RequantizeOptions::progress): a stage has just ended.
struct RequantizeProgress {
  double elapsed_s = 0;  // since requantize (or requantize_tmesh) began
  // "traced", "half-arc" (the cut), "quantized", "collapsed", "smoothed", "repair" (what was
  // found and what is done about it: a solve again follows), "fallback" (half-arc given up),
  // "compared" (FeatureTraces::Auto: which run was kept; every stage before it reported twice),
  // "given up" (give_up_at_base_complex).
  std::string stage;
  std::string detail;  // what the stage found, in words and figures
};

// Where angle-bounded traces (TraceOptions::max_angle_deg ≥ 0) reach a feature curve. Cross:
// they go on across it (TraceOptions::cross_features); Stop: they end there; Auto: requantize
// runs both and keeps what prefer_coarser_layout picks (one run when the mesh has no feature
// curve). Measured at 45° on the 23 remeshed shared layouts (docs/benchmarks.md, "Coarse
// layouts"): stopping gives organic models with feature lines coarser layouts
// (mannequin-devil's base complex 0.67 → 0.39 of the input's, joint 0.59 → 0.40), mechanical
// ones worse quads (anchor mean scaled Jacobian 0.97 → 0.87) or even finer layouts with an
// inverted quad (rotor 0.17 → 1.67).
enum class FeatureTraces { Cross, Stop, Auto };

struct RequantizeOptions {
  TraceOptions trace;  // density, features
  QuantizeOptions quantize;
  quant::SmoothingOptions smoothing;
  // Density calibration (> 0; not with quantize.coarse): the quad count to aim at. Separation
  // keeps every non-zero path ≥ 1, so where singularities or traces lie closer than one output
  // edge apart, short arcs round up and a coarsening makes more quads than the density asks
  // for (up to 3× on meshes with a singularity every few quads). Calibration scales every arc
  // target by one factor, searched (secant steps on log quads against log factor, at most
  // `calibration_solves` quantizations) until the quads are within `calibration_tolerance` of
  // this count, the closest result kept. The factor stays within [1/max_density_change,
  // max_density_change]; when that leaves too many quads, the factor may go down to
  // 1/max_density_reach if that reaches the count (the constraints nearly fill the quads asked
  // for). Where even that leaves too many, the constraints alone force more quads than asked,
  // and the open regions are not coarsened beyond 1/max_density_change to make up for it.
  int64_t target_quads = 0;
  double calibration_tolerance = 0.02;
  int calibration_solves = 8;
  double max_density_change = 2;
  double max_density_reach = 4;
  // Quad-splitting repair: how many times at most a quantization is bounded again, and the
  // mesh smoothed again, because smoothing left quads inverted (requantize_tmesh; each try
  // costs a smoothing of the whole mesh). 0 turns it off.
  int max_split_repairs = 2;
  // With quantize.coarse_uniform: when smoothing leaves quads inverted and no split reaches
  // them (a quad inside a patch that the coarse lengths, multiplied by one integer, fill with
  // lines far denser than the input's grid there), quantize once more with fitted lengths
  // (quantize.coarse_uniform off: the coarse layout's zero arcs kept, lengths at the target
  // density) and keep that if it leaves fewer quads inverted or degenerate. The base complex
  // then grows (separatrices no longer meet exactly); RequantizeResult::coarse_refitted says so.
  // Counts as one of the max_split_repairs tries. With quantize.coarse_strips, one factor for
  // the mesh is tried first (the same zero arcs and base complex; lengths per strip can squeeze
  // a quad flat where one factor does not), also where smoothing left only degenerate quads.
  bool refit_uniform = true;
  // Half-arc quantization (half_arc.hpp): the T-mesh is cut open along every relaxable
  // non-zero path and quantized with its two-gons; repairs, calibration, collapse (the two-gons
  // zipped) and smoothing then work on the cut T-mesh. Not with quantize.relaxed.
  bool half_arc = false;
  // With half_arc: < 0 exact two-gons; ≥ 0 bounded ones, each unit of drift between a path's
  // two sides at one of its vertices costing this much (HalfArcSetup::reorder_weight).
  double reorder_weight = -1;
  bool keep_crossings = false;  // HalfArcSetup::keep_crossings (bounded only)
  // With half_arc and trace.max_angle_deg in [0, 90): after each collapse, the two-gons along
  // separatrices that turn past the bound (measure_separatrix_deviation) are held to the arc
  // quantization and the T-mesh quantized again (requantize_tmesh). Off: the bound is reported,
  // not kept, where drift breaks it (the paper's half-arc: no angle guarantee).
  bool hold_angle_bound = false;
  // Angle-bounded tracing only (requantize, not requantize_tmesh): see FeatureTraces. With Auto,
  // trace.cross_features is ignored; otherwise Cross and Stop set it.
  FeatureTraces feature_traces = FeatureTraces::Cross;
  double coarser_quality_slack = 0.05;  // prefer_coarser_layout's slack, for Auto
  // > 0: requantize_tmesh returns before the first smoothing when the collapsed mesh's base
  // complex has at least this many patches (RequantizeResult::given_up_at_base_complex) — Auto's
  // second run, which only wins with fewer patches than the first (a heuristic: the repairs
  // after smoothing split quads or refit lengths, and rarely make a layout coarser).
  int give_up_at_base_complex = 0;
  // Called after every stage (RequantizeProgress) on the calling thread; empty: none. A coarse
  // exact half-arc run on a large layout can take minutes of repairs, which this shows.
  std::function<void(const RequantizeProgress&)> progress;
};

struct RequantizeResult {
  TracedTMesh traced;
  TMeshIncidence incidence;
  TMeshQuantization quantization;  // status Infeasible: no mesh (collapsed is empty)
  CollapsedMesh collapsed;
  // Separation repair: solves beyond the first, and the min-one bounds they added.
  int repair_rounds = 0;
  MinOneConstraints repair_constraints;
  // Density calibration: the factor the T-mesh's arc targets were multiplied by (1 without
  // calibration; traced.tmesh holds the scaled targets), and the quantizations it took (at
  // most 2·calibration_solves + 1 per round: calibration runs again after each repair round).
  // calibration_floor: the quads at factor 1/max_density_reach when the last calibration tried
  // it and still had too many — the separation constraints force more quads than asked for,
  // and the result stays at 1/max_density_change (−1 otherwise).
  double density_factor = 1;
  int calibration_solves = 0;
  double calibration_floor = -1;
  // Whether refit_uniform replaced the uniform coarse lengths by fitted ones.
  bool coarse_refitted = false;
  // With half_arc: the cut T-mesh that `quantization`, `repair_constraints` and `collapsed`
  // refer to (its arcs and vertices), the paths made two-gons, and the deflated T-mesh's
  // arcs and reordered T-junctions (deflate_two_gons). Without: empty, 0.
  std::optional<HalfArcSetup> half_arc;
  int adapted_arcs = 0;
  int reordered_junctions = 0;
  // Two-gons the repairs aligned (HalfArcSetup::aligned; see requantize_tmesh).
  int aligned_two_gons = 0;
  // Not empty when the half-arc quantization did not collapse into a mesh (the collapse's
  // message): the result is then the arc quantization's (half_arc empty), as without half_arc.
  std::string half_arc_fallback;
  // With FeatureTraces::Auto and feature curves (how the kept run's traces met them:
  // traced.feature_traces): the other run's base complex and mean scaled Jacobian (−1 / 0 when
  // there was one run, or the other failed: its message in other_failure). Times then add up
  // both runs.
  int other_base_complex = -1;
  double other_scaled_jacobian_mean = 0;
  int other_over_bound = 0;   // the other run's deviation.over_bound
  std::string other_failure;  // or why it was given up (give_up_at_base_complex)
  // With give_up_at_base_complex: the base complex the run stopped at before smoothing (its
  // collapsed mesh is then unsmoothed); 0 when it went on.
  int given_up_at_base_complex = 0;
  // With a mesh (patch grids): the output's separatrices measured against the input's grid
  // (separatrix_deviation.hpp), over_bound against options.trace.max_angle_deg when it is in
  // [0, 90).
  SeparatrixDeviation deviation;
  double time_trace_s = 0, time_quantize_s = 0, time_collapse_s = 0, time_smoothing_s = 0;
};

// FeatureTraces::Auto's choice between two requantizations of one mesh: `coarser` is preferred
// to `other` when its base complex has fewer patches, it has no more inverted and degenerate
// quads, and its mean scaled Jacobian is at most `slack` below the other's — the tolerance
// issue 52 allows a coarse layout against its input (0.05).
bool prefer_coarser_layout(const QuadMeshMetrics& coarser, const QuadMeshMetrics& other,
                           double slack);

// FeatureTraces::Auto's rule between two requantizations of one mesh, traced with
// cross_features true (`cross`) and false (`stop`), with their meshes' metrics: `stop` wins
// when prefer_coarser_layout(stop_metrics, cross_metrics, slack) and it has no more
// separatrices above the angle bound (deviation.over_bound) than `cross`.
bool stop_wins(const RequantizeResult& cross, const QuadMeshMetrics& cross_metrics,
               const RequantizeResult& stop, const QuadMeshMetrics& stop_metrics, double slack);

// Whether `stop` loses to `cross` only for having more inverted and degenerate quads: it would
// win (stop_wins) with as many as `cross` has.
bool stop_wins_but_for_bad_quads(const RequantizeResult& cross,
                                 const QuadMeshMetrics& cross_metrics, const RequantizeResult& stop,
                                 const QuadMeshMetrics& stop_metrics, double slack);

// FeatureTraces::Auto's last step: `stop` when stop_wins, else `cross` (a run without a mesh
// loses), with the other's base complex, mean scaled Jacobian and separatrices above the bound
// (RequantizeResult::other_*) and both runs' times added up.
RequantizeResult keep_coarser_run(RequantizeResult cross, RequantizeResult stop, double slack);

// FeatureTraces::Auto after a first run `cross` of `mesh` (traced with cross_features true, and
// feature_traces "cross"): traces `mesh` again with options.trace.cross_features false,
// requantizes that T-mesh with `options` — but without the repairs after smoothing
// (max_split_repairs 0, refit_uniform off: one smoothing) — and returns keep_coarser_run's
// pick. When that run would win but for its bad quads (stop_wins_but_for_bad_quads), it is made
// again with `options`' repairs first (their smoothings are spent only where they can change
// the pick; the times of both are added). When the first T-mesh had no feature curve, the first
// run; when the second run's collapse fails, the first with the message in other_failure; when
// the second run's collapsed mesh, before smoothing, has no fewer base-complex patches than the
// first's (give_up_at_base_complex), the first, with that count in other_base_complex and
// other_failure. Reports "traced", "repair" and "compared" (elapsed since this call).
RequantizeResult compare_feature_stops(RequantizeResult cross, const QuadMesh& mesh,
                                       RequantizeOptions options, const std::string& source);

// FeatureTraces::Auto's other run as reports give it (`feature_traces_other` of the CLI and
// Python): its base complex when there was a second run, its mean scaled Jacobian and
// separatrices above the angle bound when it was smoothed (the latter with a bound), and why it
// failed or was given up; empty() when there was no other run.
struct OtherRunSummary {
  std::optional<int> base_complex;
  std::optional<double> scaled_jacobian_mean;
  std::optional<int> over_bound;
  std::string failure;
  bool empty() const { return !base_complex && failure.empty(); }
};
OtherRunSummary other_run_summary(const RequantizeResult& r);

// "traces end at feature curves; kept against crossing them (base complex 885, mean scaled
// Jacobian 0.949)": traced.feature_traces and the comparison in words ("" for the
// plain motorcycle graph).
std::string feature_traces_summary(const RequantizeResult& r);

// The largest deviation of separatrices from the input's grid lines, in degrees, that
// `--coarse` traces with when none is given (TraceOptions::max_angle_deg; Lyon et al. 2021).
inline constexpr double kDefaultCoarseMaxAngle = 20;

// Sets options.half_arc and options.reorder_weight for a half-arc mode as users name it:
// "exact", "bounded" (drift at `reorder_weight`), "off", or "auto" — bounded with
// options.quantize.coarse (unless relaxed), off otherwise: measured on the 23 shared layouts,
// bounded coarse layouts are a median 20–25% smaller than greedy's with nearly as good quads,
// exact ones barely smaller with worse quads and several times the time (docs/benchmarks.md).
// Returns the mode used ("exact", "bounded" or "off"); throws std::invalid_argument for another
// name.
std::string set_half_arc_mode(RequantizeOptions& options, const std::string& mode,
                              double reorder_weight = 1);

// "12 patches, 40 arcs, 9 non-zero paths": the T-mesh in a progress report ("traced").
std::string progress_summary(const TMesh& tmesh);

// The mean length of the mesh's edges (each counted once per quad side); 0 without quads.
double mean_edge_length(const QuadMesh& mesh);

// Output quad edges per input edge (TraceOptions::density) for what a user asks for: with
// target_faces > 0, sqrt(target_faces / quads); else with edge_length > 0, the mesh's mean
// edge length / edge_length; else 1 / scale. Throws InputError naming `source` when the edge
// lengths are needed and all are 0, std::invalid_argument for a mesh without quads or a
// non-positive scale.
double requested_density(const QuadMesh& mesh, double scale, double edge_length,
                         int64_t target_faces, const std::string& source);

// Traces `mesh` (all quads; errors name `source`), then as requantize_tmesh.
RequantizeResult requantize(const QuadMesh& mesh, const RequantizeOptions& options,
                            const std::string& source);

// Quantizes a given T-mesh (validated here; errors name `source`), collapses and tessellates
// it, and — when it has patch grids and `mesh` is the quad mesh they index — smooths the
// result on `mesh`.
//
// Separation repair: the non-zero paths are sufficient in theory but, as constructed, not
// always in practice (angle-bounded paths at large angles). When the collapse merges two
// T-mesh vertices that start non-zero paths (seeds: singularities, corners), the zero arcs and
// zero-width patches that joined them are found and the one with the longest target gets a
// min-one bound; when a seed keeps its place but not its valence (traces leaving it folded
// together where a patch cornered there collapsed), every zero element at it gets one; a
// border loop shorter than 3 edges (a hole with fewer than three seeds closing into two edges)
// gets bounds that make it ≥ 3; and when smoothing leaves a quad inverted (but for one that
// repeats an inverted quad of the input), an arc of length 1 along it gets a bound of 2, so
// that the quad splits, and the new quantization is smoothed too — kept only if it leaves
// fewer quads inverted or degenerate, at most max_split_repairs times
// (src/tmesh/separation_repair.hpp; for uniform coarse lengths see refit_uniform). Then the
// T-mesh is quantized again — the lazy constraints the paper (§4.2.3) mentions as unexplored. Each
// round bounds an element that was 0, so this ends; all elements bounded means nothing collapses.
// With half_arc, one more repair comes first: where the collapse fails (CollapseError::patches)
// or smoothing leaves quads inverted or degenerate, the drift of the two-gons along those
// patches is more than the re-embedding in the patches' parameter domains can follow (the
// exact model may even drift where an equally good solution does not: its objective has no
// term for drift). Those two-gons are aligned (align_two_gons: an arc quantization along their
// paths, with Algorithm 2's bounds) and the T-mesh quantized again — at most max_split_repairs
// times after smoothing, and kept only if it smooths better, as a split is; on collapse
// failures until nothing is left to align. Where no two-gon runs along those quads and no split
// reaches them, every two-gon is aligned before uniform coarse lengths would be refitted (the
// half-arc optimum's other choices may be what stretched them; all aligned, the model is
// Algorithm 2's but for exact one-arc paths).
// With half_arc and uniform coarse lengths, refit_uniform therefore acts only once all are aligned.
// And a coarsening never grows the base complex: where the half-arc result's is larger than the
// input mesh's (drift split a line of the layout — mushroom: 10 patches became 19), every
// two-gon is aligned and the whole pipeline runs again, once.
// `options.trace` is not used. Throws CollapseError if the quantized T-mesh does not collapse into
// a conforming mesh (see collapse.hpp) — with half_arc, only if the arc quantization it then
// falls back to does not either (RequantizeResult::half_arc_fallback).
RequantizeResult requantize_tmesh(TracedTMesh traced, const QuadMesh* mesh,
                                  const RequantizeOptions& options, const std::string& source);

}  // namespace bimdf::tmesh
