#include "requantize_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "number_checks.hpp"
#include "remesh_command.hpp"

namespace bimdf::cli {
namespace {

using nlohmann::json;

// Output quad edges per input edge, from --scale / --edge-length / --target-faces.
double density(const RequantizeCommandOptions& o, const QuadMesh* mesh) {
  if ((o.target_faces > 0 || o.edge_length > 0) && (!mesh || mesh->quads.empty()))
    throw UsageError{std::string(o.target_faces > 0 ? "--target-faces" : "--edge-length") +
                     " needs the quad mesh the T-mesh was made from"};
  if (!mesh) return 1 / o.scale;
  return tmesh::requested_density(*mesh, o.scale, o.edge_length, o.target_faces, o.mesh);
}

json valences(const std::map<int, int>& counts) {
  json j = json::object();
  for (auto [valence, n] : counts) j[std::to_string(valence)] = n;
  return j;
}

void write_text(const std::string& path, const std::string& text,
                const std::vector<std::string>& inputs) {
  if (!path.empty()) write_output_file(path, text, inputs);
}

}  // namespace

CLI::App* add_requantize_command(CLI::App& app, RequantizeCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "requantize",
      "Re-quantize a quad mesh's layout (motorcycle T-mesh): new density or a coarser layout, "
      "same singularities, features and border");
  cmd->add_option("MESH", o.mesh, "An all-quad, manifold OBJ mesh (optional with --tmesh-in)");
  cmd->add_option("-o,--output", o.mesh_out, "The quad mesh OBJ to write (one group per patch)");
  auto* scale = cmd->add_option("--scale", o.scale,
                                "Output edge length as a multiple of the input's (quads ≈ "
                                "input quads / F²)")
                    ->default_val(1.0)
                    ->check(positive_number());
  auto* length = cmd->add_option("--edge-length", o.edge_length,
                                 "Absolute target edge length (in the mesh's units)")
                     ->check(positive_number());
  auto* faces = cmd->add_option("--target-faces", o.target_faces, "Aim at about this many quads")
                    ->check(positive_whole_number());
  scale->excludes(length)->excludes(faces);
  length->excludes(faces);
  cmd->add_flag("--no-calibration", o.no_calibration,
                "Use the density as given (each arc's target: its input edges times the density) "
                "instead of fitting it to the quad count asked for; where singularities lie "
                "closer than an output edge, separation then rounds short arcs up and "
                "coarsenings make more quads than asked");
  cmd->add_flag("--coarse", o.coarse,
                "The coarsest layout the separation constraints allow (zero-length arcs "
                "collapse strips), tessellated at the requested density");
  auto* relaxed = cmd->add_flag(
      "--relaxed", o.relaxed,
      "Allow irregular quad patches (opposite sides of different lengths, tessellated by a "
      "pattern) at a cost per unit of flow turning a corner; no arc collapses");
  cmd->add_option("--relaxed-weight", o.relaxed_weight,
                  "With --relaxed: the cost per unit of flow turning a corner (smaller: more "
                  "irregular patches)")
      ->default_val(1.0)
      ->check(positive_number())
      ->needs(relaxed);
  // The coarse objective exists to collapse arcs, which relaxed quantization never does.
  relaxed->excludes("--coarse");
  cmd->add_option("--coarse-lengths", o.coarse_lengths,
                  "With --coarse: `strips` (the default) multiplies the coarse lengths by one "
                  "integer per strip of the coarse layout, fitted to the input's size along it "
                  "(keeps the coarse layout's base complex exactly), and falls back to `uniform` "
                  "(the same base complex) where that leaves quads inverted or flat that no split "
                  "reaches and one integer does not, then to `fitted` where inverted quads "
                  "remain that fitted lengths right; `uniform`: the "
                  "same with one integer for the whole mesh; `fitted` solves again for lengths "
                  "at the requested density with the zero arcs kept (separatrices drift apart "
                  "and the base complex grows); `strict-uniform`: uniform, never refitted")
      ->default_val("strips")
      ->check(CLI::IsMember({"fitted", "uniform", "strict-uniform", "strips"}));
  cmd->add_option("--half-arc", o.half_arc,
                  "Half-arc quantization (paper §4.3): the two sides of every non-zero path "
                  "that crosses no other (alone, or overlapping one other along its line) "
                  "are quantized separately, so that T-junctions on opposite sides of it may "
                  "trade places. `exact`: the path's own length is kept ≥ 1 (the other paths "
                  "keep Algorithm 2's bounds); `bounded`: every path keeps Algorithm 2's "
                  "bounds and each unit by which the two sides drift apart at a vertex costs "
                  "--reorder-weight; `off`: arcs only; `auto`: bounded with --coarse, else off "
                  "(measured in docs/benchmarks.md)")
      ->default_val("auto")
      ->check(CLI::IsMember({"exact", "bounded", "off", "auto"}))
      ->excludes(relaxed);
  cmd->add_option("--reorder-weight", o.reorder_weight,
                  "With bounded half-arc quantization: the cost of each unit of drift between a "
                  "path's two sides at one of its vertices (0: free; large: arcs only)")
      ->default_val(1.0)
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--compare-greedy", o.compare_greedy,
                "With half-arc quantization: also solve the same T-mesh at the same targets "
                "with Algorithm 2's bounds, and report both objectives before any repair "
                "(compare_greedy: greedy, half_arc)");
  cmd->add_flag("--keep-crossings", o.keep_crossings,
                "With bounded half-arc quantization: no drift where a path crosses another line "
                "(only T-junctions trade places; straight lines of the layout stay straight)");
  cmd->add_flag("--hold-angle-bound", o.hold_angle_bound,
                "With half-arc quantization and an angle bound (--coarse or --max-angle): where "
                "the two sides of paths drift so far that a separatrix between singular vertices "
                "turns past the bound (measured after each collapse), hold those paths to the arc "
                "quantization and solve again, so that the bound holds (costs patches)");
  cmd->add_option("--max-angle", o.max_angle,
                  "Trace the angle-bounded extended motorcycle graph (Lyon et al. 2021): "
                  "separatrices may deviate from the input's grid lines by at most this many "
                  "degrees (90: unbounded); default 20 with --coarse, else the plain graph")
      ->check(number_from(0.0, 90.0));
  cmd->add_option("--feature-traces", o.feature_traces,
                  "Angle-bounded traces and feature curves: `cross` goes on across them, `stop` "
                  "ends there (coarser layouts on organic models, worse ones on mechanical "
                  "parts), `auto` with --coarse runs both and keeps the smaller base complex "
                  "unless its quads are worse (more inverted or degenerate, or a mean scaled "
                  "Jacobian 0.05 lower); without --coarse `auto` is `cross`")
      ->default_str("auto")
      ->check(CLI::IsMember({"cross", "stop", "auto"}));
  cmd->add_option("--cost", o.cost, "Deviation cost of each arc from its target length")
      ->default_val("quadratic")
      ->check(CLI::IsMember({"quadratic", "abs"}));
  cmd->add_option("--sharp-angle", o.sharp_angle,
                  "Edges whose dihedral angle exceeds this many degrees are features (180: none)")
      ->default_val(35.0)
      ->check(number_from(0.0, 180.0));
  cmd->add_option("--feature", o.feature_file,
                  "Feature edges of the quad mesh (QuadWild-style: count, then `face,edge` lines)");
  cmd->add_option("--layout-out", o.layout_out,
                  "Write the output's conforming quad layout (OBJ: one face group per patch)");
  auto* out = cmd->add_option("--tmesh-out", o.tmesh_out, "Write the T-mesh as JSON");
  auto* in = cmd->add_option("--tmesh-in", o.tmesh_in,
                             "Quantize this T-mesh JSON instead of tracing MESH");
  out->excludes(in);
  cmd->add_option("--threads", o.threads, "Worker threads of the solver")
      ->default_val(1)
      ->check(whole_number_from(1, 256));
  add_smoothing_options(cmd, o.smoothing);
  cmd->add_flag("--json", o.out.json, "Print the report as JSON on stdout");
  cmd->add_option("--report", o.out.file, "Also write the report JSON to this file");
  cmd->add_flag("-v,--verbose", o.verbose, "Solver statistics");
  cmd->add_flag("--progress", o.progress,
                "A line on stderr as each stage ends (tracing, each quantization, collapse, "
                "smoothing, every repair)");
  return cmd;
}

int run_requantize(const RequantizeCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.mesh.empty() && o.tmesh_in.empty())
    throw UsageError{"requantize needs a quad mesh MESH, or --tmesh-in T.json"};
  if (o.mesh_out.empty() && o.layout_out.empty() && o.tmesh_out.empty() && !o.out.json &&
      o.out.file.empty())
    throw UsageError{"nothing to write: give -o OUT.obj (or --layout-out, --tmesh-out, --json)"};
  std::vector<std::string> inputs;
  for (const std::string& f : {o.mesh, o.tmesh_in, o.feature_file})
    if (!f.empty()) inputs.push_back(f);
  // Outputs are checked before any work, so that a refused one costs nothing.
  for (const std::string& f : {o.mesh_out, o.layout_out, o.tmesh_out, o.out.file})
    for (const std::string& i : inputs)
      if (!f.empty() && f == i) throw UsageError{"refusing to overwrite the input " + i};

  QuadMesh mesh;
  const bool have_mesh = !o.mesh.empty();
  if (have_mesh) {
    mesh = read_obj_quads(o.mesh);
    if (mesh.quads.empty()) throw InputError(o.mesh, "", "no faces: expected an all-quad mesh");
  }
  const double read_s = seconds_since(start);
  tmesh::RequantizeOptions ro;
  ro.quantize.cost =
      o.cost == "abs" ? tmesh::DeviationCost::Absolute : tmesh::DeviationCost::Quadratic;
  ro.quantize.coarse = o.coarse;
  ro.quantize.coarse_uniform = o.coarse_lengths != "fitted";
  ro.quantize.coarse_strips = o.coarse_lengths == "strips";
  ro.refit_uniform = o.coarse_lengths == "uniform" || o.coarse_lengths == "strips";
  ro.quantize.relaxed = o.relaxed;
  const std::string half_arc = tmesh::set_half_arc_mode(ro, o.half_arc, o.reorder_weight);
  ro.keep_crossings = o.keep_crossings;
  if ((o.keep_crossings || o.reorder_weight != 1) && half_arc != "bounded")
    throw UsageError{
        "--reorder-weight and --keep-crossings need bounded half-arc quantization "
        "(--half-arc bounded, or --coarse)"};
  // Angle-bounded traces of the quad mesh given (not a T-mesh read in).
  const bool angle_bounded = o.tmesh_in.empty() && (o.coarse || o.max_angle >= 0);
  ro.hold_angle_bound = o.hold_angle_bound;
  if (o.hold_angle_bound && (half_arc == "off" || !angle_bounded))
    throw UsageError{
        "--hold-angle-bound applies to half-arc quantization of angle-bounded traces of a quad "
        "mesh (--coarse or --max-angle, not --tmesh-in or --half-arc off)"};
  if (!o.feature_traces.empty() && !angle_bounded)
    throw UsageError{
        "--feature-traces applies to the angle-bounded traces of a quad mesh (--coarse or "
        "--max-angle, not --tmesh-in)"};
  if (o.compare_greedy && half_arc == "off")
    throw UsageError{
        "--compare-greedy needs half-arc quantization (--half-arc exact|bounded, or "
        "--coarse)"};
  ro.quantize.relaxed_weight = o.relaxed_weight;
  ro.quantize.threads = o.threads;
  ro.smoothing = o.smoothing;
  double requested_density = 1;
  tmesh::TracedTMesh traced;
  const std::string source = o.tmesh_in.empty() ? o.mesh : o.tmesh_in;
  if (!o.tmesh_in.empty()) {
    traced.tmesh = tmesh::read_tmesh_json(o.tmesh_in);
    requested_density = density(o, have_mesh ? &mesh : nullptr);
    for (double& t : traced.tmesh.arc_target) t *= requested_density;
    if (!traced.tmesh.patch_grid.empty() && !have_mesh)
      throw UsageError{o.tmesh_in + " refers to a quad mesh's vertices: give that mesh as MESH"};
  } else {
    ro.trace.sharp_angle_deg = o.sharp_angle;
    ro.trace.cross_features = o.feature_traces != "stop";  // "" (not given): auto
    ro.trace.max_angle_deg = o.max_angle >= 0 ? o.max_angle
                             : o.coarse       ? tmesh::kDefaultCoarseMaxAngle
                                              : -1;
    requested_density = ro.trace.density = density(o, &mesh);
    if (!o.feature_file.empty())
      ro.trace.feature_edges = tmesh::read_quad_feature_file(o.feature_file, mesh);
    traced = tmesh::trace_tmesh(mesh, ro.trace, o.mesh);
  }
  const double traced_s = seconds_since(start);
  if (o.progress) {
    print_stage(traced_s, o.tmesh_in.empty() ? "traced" : "read",
                tmesh::progress_summary(traced.tmesh));
    ro.progress = [start](const tmesh::RequantizeProgress& p) {
      print_stage(seconds_since(start), p.stage, p.detail);
    };
  }
  // --feature-traces auto with --coarse: a second run with traces ending at feature curves
  // (tmesh::FeatureTraces::Auto, as tmesh::requantize does), which may replace the first.
  const bool bounded = o.tmesh_in.empty() && ro.trace.max_angle_deg >= 0;
  const bool auto_traces = o.feature_traces.empty() || o.feature_traces == "auto";
  const bool compare_stops = bounded && auto_traces && o.coarse && !traced.feature_edges.empty();
  const auto write_tmesh_out = [&](const tmesh::TMesh& t) {
    if (o.tmesh_out.empty()) return;
    std::ostringstream text;
    tmesh::write_tmesh_json(text, t);
    write_text(o.tmesh_out, text.str(), inputs);
  };
  if (!compare_stops) write_tmesh_out(traced.tmesh);
  // The quads the density asks for: the targets' area (for a traced mesh, its quads times the
  // density squared). The coarse modes choose their own count.
  if (!o.no_calibration && !o.coarse)
    ro.target_quads = std::max<int64_t>(1, std::llround(tmesh::target_quads(traced.tmesh)));
  tmesh::RequantizeResult r;
  try {
    r = tmesh::requantize_tmesh(std::move(traced), have_mesh ? &mesh : nullptr, ro, source);
  } catch (const tmesh::CollapseError& e) {
    throw std::runtime_error(std::string("collapsing the quantized T-mesh failed: ") + e.what());
  }
  if (compare_stops) {  // coarse: no calibration, the kept T-mesh's targets are as traced
    r = tmesh::compare_feature_stops(std::move(r), mesh, ro, o.mesh);
    write_tmesh_out(r.traced.tmesh);
  }
  const tmesh::TMesh& tm = r.traced.tmesh;
  const tmesh::TMeshQuantization& q = r.quantization;
  const tmesh::CollapsedMesh& collapsed = r.collapsed;
  json j;
  std::ostringstream s;
  j["status"] = std::string(status_name(q.status));
  j["tmesh_patches"] = tm.num_patches();
  j["tmesh_arcs"] = tm.num_arcs();
  j["nonzero_paths"] = tm.nonzero_paths.size();
  j["min_one_constraints"] = q.constraints.size();
  j["seeds"] = r.traced.seeds.size();
  j["traces"] = r.traced.traces;
  if (ro.trace.max_angle_deg >= 0) {
    j["max_angle"] = ro.trace.max_angle_deg;
    j["crossings"] = r.traced.crossings;
  }
  if (!r.traced.feature_traces.empty()) {
    j["feature_traces"] = r.traced.feature_traces;
    if (const tmesh::OtherRunSummary other = tmesh::other_run_summary(r); !other.empty()) {
      json& o = j["feature_traces_other"];
      if (other.base_complex) o["base_complex"] = *other.base_complex;
      if (other.scaled_jacobian_mean) o["scaled_jacobian_mean"] = *other.scaled_jacobian_mean;
      if (other.over_bound) o["over_bound"] = *other.over_bound;
      if (!other.failure.empty()) o["failure"] = other.failure;
    }
  }
  j["model"] = {{"nodes", q.nodes}, {"edges", q.edges}};
  s << "t-mesh        " << tm.num_patches() << " patches, " << tm.num_arcs() << " arcs, "
    << r.traced.seeds.size() << " seeds, " << tm.nonzero_paths.size() << " non-zero paths ("
    << q.constraints.size() << " min-one constraints: " << q.constraints.sides.size() << " sides, "
    << q.constraints.arcs.size() << " arcs)\n";
  s << "status        " << status_name(q.status) << "\n";
  if (!r.traced.feature_traces.empty())
    s << "features      " << tmesh::feature_traces_summary(r) << "\n";
  if (q.arc_length.empty()) {
    // Only a T-mesh from elsewhere can lack a valid quantization: one traced on a quad mesh
    // always has one (the input's own edge counts).
    std::cerr << "error: the T-mesh has no valid quantization (opposite sides cannot be made "
                 "equal with the non-zero paths kept)\n";
    deliver(o.out, s.str(), j.dump(1) + "\n", inputs);
    return kNoSolution;
  }
  j["objective"] = q.objective;
  j["repair_rounds"] = r.repair_rounds;
  j["repair_constraints"] = r.repair_constraints.size();
  j["zero_arcs"] = q.zero_arcs;
  j["half_arc"] = half_arc;
  if (o.compare_greedy && r.half_arc) {
    // The same problem both ways, before repairs (whose bounds differ between the models).
    tmesh::QuantizeOptions plain = ro.quantize;
    const tmesh::TMeshQuantization greedy = tmesh::quantize_tmesh(tm, r.incidence, plain);
    // The cut T-mesh the run made, at the same targets (its arcs' are the input's), with no
    // two-gon aligned by the repairs.
    tmesh::HalfArcSetup unrepaired = *r.half_arc;
    tmesh::set_aligned(unrepaired, tm, r.incidence,
                       std::vector<char>(unrepaired.inflated.two_gons.size(), 0));
    const tmesh::TMeshQuantization half = tmesh::quantize_inflated(unrepaired, plain);
    const bool coarse = ro.quantize.coarse;
    const double g = coarse ? greedy.coarse_objective : greedy.objective;
    const double h = coarse ? half.coarse_objective : half.objective;
    j["compare_greedy"] = {
        {"greedy", g}, {"half_arc", h}, {"stage", coarse ? "coarse" : "deviation"}};
    s << "compare       " << (coarse ? "coarse objective" : "objective")
      << " before repairs: greedy " << g << ", half-arc " << h << "\n";
  }
  if (!r.half_arc_fallback.empty()) {
    j["half_arc_fallback"] = r.half_arc_fallback;
    std::cerr << "note: the half-arc quantization did not collapse into a quad mesh ("
              << r.half_arc_fallback << "); the arc quantization was used instead\n";
  }
  if (r.half_arc) {
    j["half_arc_paths"] = r.half_arc->relaxed.size();
    j["reordered_junctions"] = r.reordered_junctions;
    j["adapted_arcs"] = r.adapted_arcs;
    j["aligned_two_gons"] = r.aligned_two_gons;
    s << "half-arc      " << r.half_arc->relaxed.size() << " of " << tm.nonzero_paths.size()
      << " non-zero paths quantized on both sides (" << r.aligned_two_gons
      << " held to arcs by repairs); " << r.reordered_junctions
      << " T-junctions moved across a path, " << r.adapted_arcs << " arcs after adaptation\n";
  }
  if (o.coarse) j["coarse_objective"] = q.coarse_objective;
  if (o.coarse && q.coarse_factor > 0) j["coarse_factor"] = q.coarse_factor;
  if (o.coarse)
    j["coarse_lengths"] = q.coarse_factor <= 0 ? "fitted" : q.strip_lengths ? "strips" : "uniform";
  if (r.coarse_refitted)
    std::cerr << "note: uniform coarse lengths left quads inverted that no split reached; "
                 "the lengths were fitted instead (the base complex grows; "
                 "--coarse-lengths strict-uniform keeps uniform lengths)\n";
  if (ro.quantize.coarse_strips && !q.strip_lengths && q.coarse_factor > 0)
    std::cerr << "note: strip lengths left quads inverted or flat that no split reached; one "
                 "coarse factor for the whole mesh was used instead (the same base complex)\n";
  s << "objective     " << q.objective << (o.coarse ? " (coarse stage " : "")
    << (o.coarse ? std::to_string(q.coarse_objective) + ")" : "") << "; " << q.zero_arcs << " of "
    << (r.half_arc ? r.half_arc->inflated.tmesh.num_arcs() : tm.num_arcs())
    << (r.half_arc ? " arcs of the cut T-mesh (each copy counted)" : " arcs")
    << " quantized to 0\n";
  j["density"] = requested_density;
  if (ro.target_quads > 0) {
    j["target_quads"] = ro.target_quads;
    j["density_factor"] = r.density_factor;
    j["calibration_solves"] = r.calibration_solves;
    s << "density       " << requested_density << " requested, × " << r.density_factor
      << " to aim at " << ro.target_quads << " quads (" << r.calibration_solves
      << " quantizations)\n";
    if (r.calibration_floor >= 0) {
      j["calibration_floor"] = r.calibration_floor;
      std::cerr << "note: keeping singularities, features and the border apart takes more quads "
                   "than asked for: "
                << std::llround(r.calibration_floor) << " even at × " << 1 / ro.max_density_reach
                << " (asked for " << ro.target_quads << "); the result stays at × "
                << r.density_factor << "\n";
    }
  }
  if (r.repair_rounds > 0)
    s << "separation    " << r.repair_rounds << " more solves: " << r.repair_constraints.size()
      << " min-one bounds added where the collapse broke separation\n";
  if (o.verbose) {
    s << "model         " << q.nodes << " nodes, " << q.edges << " edges; model "
      << ms(q.time_model_s) << ", solve " << ms(q.time_solve_s) << "\n";
  }

  if (!o.mesh_out.empty()) {
    std::ostringstream obj;
    write_obj(obj, collapsed.mesh, "bimdf requantize of " + (have_mesh ? o.mesh : o.tmesh_in));
    write_output_file(o.mesh_out, obj.str(), inputs);
  }
  const tmesh::ConformingLayout layout = tmesh::conforming_layout(collapsed.mesh);
  if (!o.layout_out.empty()) {
    std::ostringstream obj;
    tmesh::write_layout_obj(obj, collapsed.mesh, layout);
    write_text(o.layout_out, obj.str(), inputs);
  }
  j["layout_patches"] = layout.patch_corners.size();
  j["quads"] = collapsed.mesh.num_quads();
  j["collapsed_patches"] = collapsed.collapsed_patches;
  j["irregular_patches"] = collapsed.irregular_patches;
  s << "layout        " << layout.patch_corners.size() << " patches ("
    << collapsed.collapsed_patches << " T-mesh patches collapsed"
    << (o.relaxed ? ", " + std::to_string(collapsed.irregular_patches) + " irregular" : "")
    << ")\n";
  s << "quad mesh     " << (o.mesh_out.empty() ? "(not written)" : o.mesh_out) << ": "
    << collapsed.mesh.num_quads() << " quads, " << collapsed.mesh.num_vertices() << " vertices\n";

  TriangleMesh reference;  // the input's quads split in two, for distances
  if (have_mesh)
    for (const auto& quad : mesh.quads) {
      reference.faces.push_back({quad[0], quad[1], quad[2]});
      reference.faces.push_back({quad[0], quad[2], quad[3]});
    }
  reference.vertices = mesh.vertices;
  const auto measuring = std::chrono::steady_clock::now();
  const QuadMeshMetrics out_metrics =
      measure_quad_mesh(collapsed.mesh, have_mesh ? &reference : nullptr);
  const TessellationReport mr = report_metrics(out_metrics);
  j["metrics"] = mr.j;
  j["singularities_out"] = {{"inside", valences(out_metrics.interior_singularities)},
                            {"border", valences(out_metrics.boundary_singularities)}};
  j["base_complex_out"] = out_metrics.base_complex_faces;
  if (have_mesh) {
    const tmesh::SeparatrixDeviation& d = r.deviation;
    const bool bound = d.bound_deg >= 0;
    j["separatrix_deviation"] = {{"measured", d.measured},
                                 {"unmeasured", d.unmeasured},
                                 {"max_deg", d.max_deg},
                                 {"max_to_border_deg", d.max_to_border_deg}};
    if (bound) j["separatrix_deviation"]["over_bound"] = d.over_bound;
    s << "deviation     " << significant(d.max_deg, 3)
      << "° at most from the input's grid between singular vertices ("
      << significant(d.max_to_border_deg, 3) << "° to the border) over " << d.measured
      << (d.measured == 1 ? " separatrix" : " separatrices")
      << (d.unmeasured ? ", " + std::to_string(d.unmeasured) + " not measured" : "")
      << (bound ? ", " + std::to_string(d.over_bound) + " above the bound" : "") << "\n";
  }
  if (have_mesh) {
    const QuadMeshMetrics in_metrics = measure_quad_mesh(mesh);
    j["singularities_in"] = {{"inside", valences(in_metrics.interior_singularities)},
                             {"border", valences(in_metrics.boundary_singularities)}};
    j["base_complex_in"] = in_metrics.base_complex_faces;
    j["quads_in"] = mesh.num_quads();
    s << "input         " << mesh.num_quads() << " quads, " << in_metrics.singular_vertices()
      << " singular vertices, base complex " << in_metrics.base_complex_faces << " patches\n";
  }
  s << mr.text;
  j["time"] = {{"read_s", read_s},
               {"trace_s", traced_s - read_s},
               {"model_s", q.time_model_s},
               {"solve_s", q.time_solve_s},
               {"collapse_s", r.time_collapse_s},
               {"smoothing_s", r.time_smoothing_s},
               {"metrics_s", seconds_since(measuring)},
               {"total_s", seconds_since(start)}};
  s << "time          " << ms(seconds_since(start)) << " (read " << ms(read_s) << ", trace "
    << ms(traced_s - read_s) << ", quantize " << ms(r.time_quantize_s) << ", collapse "
    << ms(r.time_collapse_s) << ", smoothing " << ms(r.time_smoothing_s) << ")\n";
  deliver(o.out, s.str(), j.dump(1) + "\n", inputs);
  return kOk;
}

}  // namespace bimdf::cli
