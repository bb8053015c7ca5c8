// Meshes through Python: QuadWild layouts quantized and remeshed (quant/), quad meshes
// requantized (tmesh/requantize.hpp), quality measured (metrics.hpp), OBJ files. Meshes cross
// as numpy arrays — vertices float64 (n, 3), faces int64 (m, 3|4) — and reports as dicts
// with the keys of the CLI's JSON reports (docs/formats.md), so that scripts can switch between
// the two. The options and their defaults are the CLI's, so both give the same meshes.
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "arrays.hpp"
#include "bimdf/io.hpp"
#include "bimdf/layout/generate.hpp"
#include "bimdf/layout/surface.hpp"
#include "bimdf/metrics.hpp"
#include "bimdf/quant/quantize.hpp"
#include "bimdf/quant/remesh_layout.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "bindings.hpp"

namespace bimdf::python {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <size_t N>
std::vector<std::array<int, N>> faces_from_python(py::handle faces, int num_vertices) {
  auto rows = index_rows<N>(faces, "F");
  for (size_t f = 0; f < rows.size(); ++f)
    for (int v : rows[f])
      if (v < 0 || v >= num_vertices)
        throw py::value_error("F[" + std::to_string(f) + "]: vertex " + std::to_string(v) +
                              " out of range (V has " + std::to_string(num_vertices) + " rows)");
  return rows;
}

QuadMesh quad_mesh_from_python(py::handle V, py::handle F) {
  QuadMesh mesh;
  mesh.vertices = point_rows(V, "V");
  mesh.quads = faces_from_python<4>(F, mesh.num_vertices());
  mesh.quad_patch.assign(mesh.quads.size(), -1);
  if (mesh.quads.empty()) throw py::value_error("F: no faces");
  return mesh;
}

py::tuple mesh_to_python(const QuadMesh& mesh) {
  return py::make_tuple(rows_to_numpy<double>(mesh.vertices), rows_to_numpy<int64_t>(mesh.quads));
}

py::dict by_valence(const std::map<int, int>& counts) {
  py::dict d;
  for (auto [valence, n] : counts) d[py::str(std::to_string(valence))] = n;
  return d;
}

// The dict of `bimdf metrics --json` (apps/bimdf/remesh_command.cpp: report_metrics).
py::dict metrics_to_python(const QuadMeshMetrics& m) {
  py::dict d;
  d["faces"] = m.faces;
  d["vertices"] = m.vertices;
  d["edges"] = m.edges;
  d["euler_characteristic"] = m.euler_characteristic;
  d["boundary_edges"] = m.boundary_edges;
  d["border_loops"] = m.border_loops;
  d["manifold"] = m.manifold();
  d["non_manifold_edges"] = m.non_manifold_edges;
  d["non_manifold_vertices"] = m.non_manifold_vertices;
  d["singular_vertices"] = m.singular_vertices();
  d["interior_singularities"] = by_valence(m.interior_singularities);
  d["boundary_singularities"] = by_valence(m.boundary_singularities);
  py::dict sj;
  sj["min"] = m.scaled_jacobian_min;
  sj["mean"] = m.scaled_jacobian_mean;
  sj["p5"] = m.scaled_jacobian_p5;
  d["scaled_jacobian"] = sj;
  d["inverted"] = m.inverted;
  d["degenerate"] = m.degenerate;
  d["base_complex_faces"] = m.base_complex_faces;
  if (m.hausdorff >= 0) {
    d["hausdorff"] = m.hausdorff;
    d["hausdorff_relative"] = m.hausdorff_relative;
    d["flipped"] = m.flipped;
  }
  return d;
}

// A layout: a path to QuadWild's NAME.obj (beside NAME.patch, NAME.corners, …) or a tuple
// (V, F, patch, corners): triangles, the chart of each face, each chart's corner vertices.
quant::Layout layout_from_python(py::handle layout) {
  if (py::isinstance<py::str>(layout) || py::hasattr(layout, "__fspath__")) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(layout));
    require_file(path);
    py::gil_scoped_release release;
    return quant::read_quadwild_layout(path);
  }
  if (!py::isinstance<py::tuple>(layout) || py::len(layout) != 4)
    throw py::type_error("layout: expected a path or a tuple (V, F, patch, corners)");
  const auto t = py::reinterpret_borrow<py::tuple>(layout);
  TriangleMesh mesh;
  mesh.vertices = point_rows(t[0], "V");
  mesh.faces = faces_from_python<3>(t[1], mesh.num_vertices());
  std::vector<int> face_chart;
  for (int64_t c : int64_vector(t[2], "patch", mesh.num_faces())) {
    if (c < 0 || c > std::numeric_limits<int>::max())
      throw py::value_error("patch: chart ids must be >= 0, got " + std::to_string(c));
    face_chart.push_back(static_cast<int>(c));
  }
  std::vector<std::vector<int>> corners;
  for (py::handle c : t[3]) {
    corners.emplace_back();
    for (int64_t v : int64_vector(c, "corners")) corners.back().push_back(static_cast<int>(v));
  }
  return quant::build_layout(std::move(mesh), std::move(face_chart), corners, "<arrays>");
}

// What remesh works on: a QuadWild layout (layout_from_python), or a layout made here from a
// bare triangle or polygon mesh — a path with no NAME.patch beside it, or a tuple (V, F) — as
// `bimdf remesh MESH` makes it; `made` then describes it for the report.
struct RemeshInput {
  quant::Layout layout;
  std::optional<py::dict> made;
  int checked = -1;  // bare mesh: which call of the check rated the layout kept
};

RemeshInput remesh_input_from_python(py::handle arg, double sharp_angle,
                                     const std::vector<double>& pairing_radii,
                                     const std::vector<double>& spare_radii, double cancel_pairs,
                                     const layout::LayoutCheck& check) {
  if (!(sharp_angle >= 0 && sharp_angle <= 180))
    throw py::value_error("sharp_angle must be in [0, 180]");
  const auto radii_in_range = [](const std::vector<double>& radii) {
    return std::all_of(radii.begin(), radii.end(), [](double r) { return r >= 0 && r <= 100; });
  };
  if (pairing_radii.empty() || !radii_in_range(pairing_radii))
    throw py::value_error("pairing_radii must be a non-empty list of numbers in [0, 100]");
  if (!radii_in_range(spare_radii))
    throw py::value_error("spare_radii must be a list of numbers in [0, 100]");
  if (!(cancel_pairs >= 0 && cancel_pairs <= 100))
    throw py::value_error("cancel_pairs must be in [0, 100]");
  PolygonMesh bare;
  std::string source;
  if (py::isinstance<py::str>(arg) || py::hasattr(arg, "__fspath__")) {
    source = py::str(py::module_::import("os").attr("fspath")(arg));
    require_file(source);
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::path(source).replace_extension(".patch"), ec))
      return {layout_from_python(arg), std::nullopt};
    py::gil_scoped_release release;
    bare = read_polygon_mesh(source);
  } else if (py::isinstance<py::tuple>(arg) && py::len(arg) == 2) {
    const auto t = py::reinterpret_borrow<py::tuple>(arg);
    bare.vertices = point_rows(t[0], "V");
    for (const auto& f : faces_from_python<3>(t[1], bare.num_vertices()))
      bare.faces.push_back({f[0], f[1], f[2]});
    source = "<arrays>";
  } else {
    return {layout_from_python(arg), std::nullopt};
  }
  layout::FeatureOptions feature_options;
  feature_options.sharp_angle_deg = sharp_angle;
  std::optional<layout::GeneratedLayout> g;
  int sharp_edges = 0;
  {
    py::gil_scoped_release release;
    const layout::Surface surface = layout::prepare_surface(bare, source);
    const layout::Features features = layout::detect_features(surface.mesh, feature_options);
    sharp_edges = static_cast<int>(features.sharp_edges.size());
    layout::LayoutOptions options;
    options.pairing_radii = pairing_radii;
    options.spare_pairing_radii = spare_radii;
    options.cancel_pair_radius = cancel_pairs;
    g = layout::generate_layout(surface.mesh, features, options, {}, check);
  }
  int singular = 0;
  for (const auto& x : g->indices.singularities) singular += !x.on_border;
  py::dict made;
  made["sharp_edges"] = sharp_edges;
  made["field_singularities"] = singular;
  made["traced_along"] = g->traced_parametrization ? "parametrization" : "field";
  made["folded_faces"] = g->folded_faces;
  made["cancelled_pairs"] = g->cancelled_pairs;
  made["attempts"] = g->attempts;
  made["pairing_radius"] = g->pairing_radius;
  made["spare"] = g->spare;
  made["candidates"] = g->candidates;
  made["patches"] = g->layout.charts.size();
  made["time"] = py::dict(
      py::arg("field_s") = g->time_field_s, py::arg("parametrization_s") = g->time_parametrization_s,
      py::arg("trace_s") = g->time_trace_s, py::arg("cut_s") = g->time_cut_s,
      py::arg("patches_s") = g->time_patches_s);
  return {std::move(g->layout), made, g->checked};
}

quant::QuantizeOptions quantize_options(double scale, std::optional<double> edge_length,
                                        std::optional<int64_t> target_faces, bool align,
                                        int threads, std::optional<double> time_limit) {
  if (!(scale > 0) || !std::isfinite(scale)) throw py::value_error("scale must be > 0");
  if (edge_length && !(*edge_length > 0 && std::isfinite(*edge_length)))
    throw py::value_error("edge_length must be > 0");
  if (target_faces && *target_faces < 1) throw py::value_error("target_faces must be >= 1");
  if (int(scale != 1) + int(bool(edge_length)) + int(bool(target_faces)) > 1)
    throw py::value_error("give at most one of scale, edge_length, target_faces");
  if (threads < 1) throw py::value_error("threads must be >= 1");
  if (time_limit && !(*time_limit > 0 && std::isfinite(*time_limit)))
    throw py::value_error("time_limit must be a positive number of seconds");
  quant::QuantizeOptions q;
  q.scale = scale;
  q.edge_length = edge_length.value_or(0);
  q.target_faces = target_faces.value_or(0);
  q.align = align;
  q.threads = threads;
  q.time_limit = time_limit.value_or(-1);
  return q;
}

quant::SmoothingOptions smoothing_options(int iterations, double damping, int quality_rounds) {
  if (iterations < 0) throw py::value_error("smooth_iterations must be >= 0");
  if (!(damping >= 0 && damping <= 1)) throw py::value_error("smooth_damping must be in [0, 1]");
  if (quality_rounds < 0) throw py::value_error("quality_rounds must be >= 0");
  return {iterations, damping, quality_rounds};
}

py::dict quantization_to_python(const quant::Quantization& q) {
  const quant::QuantizationRound& last = q.final_round();
  py::dict d;
  d["status"] = std::string(status_name(last.solution.status));
  d["objective"] = last.solution.objective;
  d["edge_length"] = q.edge_length;
  d["estimated_quads"] = std::llround(last.estimated_quads);
  d["rounds"] = q.rounds.size();
  d["lengths"] = to_numpy(q.lengths());
  d["targets"] = to_numpy(q.targets);
  double model_s = 0, solve_s = 0;
  for (const auto& r : q.rounds) model_s += r.time_model_s, solve_s += r.time_solve_s;
  d["time"] = py::dict(py::arg("model_s") = model_s, py::arg("solve_s") = solve_s);
  return d;
}

py::dict quantize(py::handle layout_arg, double scale, std::optional<double> edge_length,
                  std::optional<int64_t> target_faces, bool align, int threads,
                  std::optional<double> time_limit) {
  const quant::QuantizeOptions options =
      quantize_options(scale, edge_length, target_faces, align, threads, time_limit);
  const quant::Layout layout = layout_from_python(layout_arg);
  std::optional<quant::Quantization> q;
  {
    py::gil_scoped_release release;
    q = quant::quantize(layout, options);
  }
  py::dict d = quantization_to_python(*q);
  d["subsides"] = layout.subsides.size();
  d["warnings"] = layout.warnings;
  return d;
}

py::tuple remesh(py::handle layout_arg, double scale, std::optional<double> edge_length,
                 std::optional<int64_t> target_faces, bool align, int smooth_iterations,
                 double smooth_damping, int quality_rounds, int threads,
                 std::optional<double> time_limit, double sharp_angle,
                 const std::vector<double>& pairing_radii, const std::vector<double>& spare_radii,
                 double cancel_pairs) {
  const auto start = std::chrono::steady_clock::now();
  quant::QuantizeOptions options =
      quantize_options(scale, edge_length, target_faces, align, threads, time_limit);
  options.model.min_border_loop = quant::kRemeshMinBorderLoop;
  const quant::SmoothingOptions smoothing =
      smoothing_options(smooth_iterations, smooth_damping, quality_rounds);
  // A bare mesh's layout whose quad mesh lacks the input's topology is traced another way; of
  // those taken the least bad is kept (layout::generate_layout).
  std::vector<quant::RemeshedLayout> results;
  const auto quad_mesh_of = [&](const quant::Layout& layout) {
    results.push_back(quant::remesh_layout(layout, options, smoothing));
    return layout::LayoutVerdict{results.back().topology_difference,
                                 quant::layout_badness(results.back())};
  };
  RemeshInput input = remesh_input_from_python(layout_arg, sharp_angle, pairing_radii, spare_radii,
                                               cancel_pairs, quad_mesh_of);
  const quant::Layout& layout = input.layout;
  if (!input.made) {
    std::string wrong;
    {
      py::gil_scoped_release release;
      wrong = quad_mesh_of(layout).wrong;
    }
    if (!wrong.empty())
      throw std::runtime_error("the quad mesh would not have the layout's topology (" + wrong +
                               ")");
  }
  const quant::RemeshedLayout& r = results.at(input.checked >= 0 ? input.checked : 0);
  const quant::Tessellation& t = r.tessellation;
  py::dict report;
  report["quads"] = t.mesh.num_quads();
  report["quantization"] = quantization_to_python(r.quantization);
  report["metrics"] = metrics_to_python(r.metrics);
  report["warnings"] = layout.warnings;
  if (input.made) report["layout"] = *input.made;
  report["time"] =
      py::dict(py::arg("quantize_s") = r.quantize_s, py::arg("metrics_s") = r.metrics_s,
               py::arg("patterns_s") = t.time_patterns_s, py::arg("mapping_s") = t.time_mapping_s,
               py::arg("smoothing_s") = t.time_smoothing_s, py::arg("polish_s") = t.time_polish_s,
               py::arg("total_s") = seconds_since(start));
  py::tuple vf = mesh_to_python(t.mesh);
  return py::make_tuple(vf[0], vf[1], report);
}

py::tuple requantize(py::handle V, py::handle F, double scale, std::optional<double> edge_length,
                     std::optional<int64_t> target_faces, bool coarse,
                     std::optional<double> max_angle, bool relaxed, double relaxed_weight,
                     double sharp_angle, const std::string& cost, const std::string& coarse_lengths,
                     bool calibrate, int smooth_iterations, double smooth_damping,
                     int quality_rounds, int threads, const std::string& half_arc,
                     double reorder_weight, bool keep_crossings, bool hold_angle_bound,
                     const std::string& feature_traces) {
  const auto start = std::chrono::steady_clock::now();
  const QuadMesh mesh = quad_mesh_from_python(V, F);
  if (feature_traces != "cross" && feature_traces != "stop" && feature_traces != "auto")
    throw py::value_error("feature_traces must be 'cross', 'stop' or 'auto'");
  const bool angle_bounded = coarse || max_angle.has_value();
  if (feature_traces != "auto" && !angle_bounded)
    throw py::value_error(
        "feature_traces applies to the angle-bounded traces (coarse=True or max_angle)");
  if (int(scale != 1) + int(bool(edge_length)) + int(bool(target_faces)) > 1)
    throw py::value_error("give at most one of scale, edge_length, target_faces");
  if (coarse && relaxed) throw py::value_error("coarse and relaxed exclude each other");
  if (cost != "quadratic" && cost != "abs")
    throw py::value_error("cost must be 'quadratic' or 'abs', got '" + cost + "'");
  if (coarse_lengths != "uniform" && coarse_lengths != "fitted" &&
      coarse_lengths != "strict-uniform" && coarse_lengths != "strips")
    throw py::value_error(
        "coarse_lengths must be 'uniform', 'fitted', 'strict-uniform' or 'strips'");
  if (max_angle && !(*max_angle >= 0 && *max_angle <= 90))
    throw py::value_error("max_angle must be in [0, 90]");
  if (!(sharp_angle >= 0 && sharp_angle <= 180))
    throw py::value_error("sharp_angle must be in [0, 180]");
  if (!(relaxed_weight > 0) || !std::isfinite(relaxed_weight))
    throw py::value_error("relaxed_weight must be > 0");
  if (edge_length && !(*edge_length > 0 && std::isfinite(*edge_length)))
    throw py::value_error("edge_length must be > 0");
  if (target_faces && *target_faces < 1) throw py::value_error("target_faces must be >= 1");
  if (threads < 1) throw py::value_error("threads must be >= 1");
  tmesh::RequantizeOptions ro;
  ro.quantize.cost =
      cost == "abs" ? tmesh::DeviationCost::Absolute : tmesh::DeviationCost::Quadratic;
  ro.quantize.coarse = coarse;
  ro.quantize.coarse_uniform = coarse_lengths != "fitted";
  ro.quantize.coarse_strips = coarse_lengths == "strips";
  ro.refit_uniform = coarse_lengths == "uniform" || coarse_lengths == "strips";
  ro.quantize.relaxed = relaxed;
  ro.quantize.relaxed_weight = relaxed_weight;
  std::string half_arc_used;
  try {
    half_arc_used = tmesh::set_half_arc_mode(ro, half_arc, reorder_weight);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  if (relaxed && half_arc_used != "off")
    throw py::value_error("half_arc and relaxed exclude each other");
  if (!(reorder_weight >= 0) || !std::isfinite(reorder_weight))
    throw py::value_error("reorder_weight must be >= 0");
  if ((keep_crossings || reorder_weight != 1) && half_arc_used != "bounded")
    throw py::value_error("reorder_weight and keep_crossings need bounded half-arc quantization");
  ro.keep_crossings = keep_crossings;
  if (hold_angle_bound && (half_arc_used == "off" || !angle_bounded))
    throw py::value_error(
        "hold_angle_bound needs half-arc quantization and an angle bound "
        "(coarse or max_angle)");
  ro.hold_angle_bound = hold_angle_bound;
  ro.quantize.threads = threads;
  ro.smoothing = smoothing_options(smooth_iterations, smooth_damping, quality_rounds);
  ro.trace.sharp_angle_deg = sharp_angle;
  ro.trace.cross_features = feature_traces != "stop";
  ro.trace.max_angle_deg = max_angle ? *max_angle : coarse ? tmesh::kDefaultCoarseMaxAngle : -1;
  ro.trace.density = tmesh::requested_density(mesh, scale, edge_length.value_or(0),
                                              target_faces.value_or(0), "<arrays>");
  tmesh::RequantizeResult r;
  QuadMeshMetrics out_metrics;
  {
    py::gil_scoped_release release;
    tmesh::TracedTMesh traced = tmesh::trace_tmesh(mesh, ro.trace, "<arrays>");
    if (calibrate && !coarse)
      ro.target_quads = std::max<int64_t>(1, std::llround(tmesh::target_quads(traced.tmesh)));
    r = tmesh::requantize_tmesh(std::move(traced), &mesh, ro, "<arrays>");
    if (feature_traces == "auto" && coarse && ro.trace.max_angle_deg >= 0)
      r = tmesh::compare_feature_stops(std::move(r), mesh, ro, "<arrays>");
    if (!r.collapsed.mesh.quads.empty()) {
      TriangleMesh reference;
      reference.vertices = mesh.vertices;
      for (const auto& quad : mesh.quads) {
        reference.faces.push_back({quad[0], quad[1], quad[2]});
        reference.faces.push_back({quad[0], quad[2], quad[3]});
      }
      out_metrics = measure_quad_mesh(r.collapsed.mesh, &reference);
    }
  }
  const tmesh::TMeshQuantization& q = r.quantization;
  if (q.arc_length.empty())
    throw py::value_error(
        "the T-mesh has no valid quantization (opposite sides cannot be made "
        "equal with the non-zero paths kept)");
  py::dict report;
  report["status"] = std::string(status_name(q.status));
  report["objective"] = q.objective;
  report["tmesh_patches"] = r.traced.tmesh.num_patches();
  report["tmesh_arcs"] = r.traced.tmesh.num_arcs();
  report["nonzero_paths"] = r.traced.tmesh.nonzero_paths.size();
  report["min_one_constraints"] = q.constraints.size();
  report["zero_arcs"] = q.zero_arcs;
  report["repair_rounds"] = r.repair_rounds;
  report["half_arc"] = half_arc_used;
  if (!r.traced.feature_traces.empty()) {
    report["feature_traces"] = r.traced.feature_traces;
    if (const tmesh::OtherRunSummary other = tmesh::other_run_summary(r); !other.empty()) {
      py::dict o;
      if (other.base_complex) o["base_complex"] = *other.base_complex;
      if (other.scaled_jacobian_mean) o["scaled_jacobian_mean"] = *other.scaled_jacobian_mean;
      if (other.over_bound) o["over_bound"] = *other.over_bound;
      if (!other.failure.empty()) o["failure"] = other.failure;
      report["feature_traces_other"] = o;
    }
  }
  if (r.half_arc) {
    report["half_arc_paths"] = r.half_arc->relaxed.size();
    report["reordered_junctions"] = r.reordered_junctions;
    report["aligned_two_gons"] = r.aligned_two_gons;
  }
  if (coarse)
    report["coarse_lengths"] = q.coarse_factor <= 0 ? "fitted"
                               : q.strip_lengths    ? "strips"
                                                    : "uniform";
  report["density"] = ro.trace.density;
  if (ro.target_quads > 0) {
    report["target_quads"] = ro.target_quads;
    report["density_factor"] = r.density_factor;
    if (r.calibration_floor >= 0) report["calibration_floor"] = r.calibration_floor;
  }
  report["quads"] = r.collapsed.mesh.num_quads();
  report["quads_in"] = mesh.num_quads();
  report["collapsed_patches"] = r.collapsed.collapsed_patches;
  report["irregular_patches"] = r.collapsed.irregular_patches;
  report["metrics"] = metrics_to_python(out_metrics);
  const tmesh::SeparatrixDeviation& d = r.deviation;
  py::dict deviation(py::arg("measured") = d.measured, py::arg("unmeasured") = d.unmeasured,
                     py::arg("max_deg") = d.max_deg,
                     py::arg("max_to_border_deg") = d.max_to_border_deg);
  if (d.bound_deg >= 0) deviation["over_bound"] = d.over_bound;
  report["separatrix_deviation"] = deviation;
  report["time"] = py::dict(
      py::arg("trace_s") = r.time_trace_s, py::arg("quantize_s") = r.time_quantize_s,
      py::arg("collapse_s") = r.time_collapse_s, py::arg("smoothing_s") = r.time_smoothing_s,
      py::arg("total_s") = seconds_since(start));
  py::tuple vf = mesh_to_python(r.collapsed.mesh);
  return py::make_tuple(vf[0], vf[1], report);
}

TriangleMesh reference_from_python(py::handle reference) {
  if (py::isinstance<py::str>(reference) || py::hasattr(reference, "__fspath__")) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(reference));
    require_file(path);
    return read_obj_triangles(path);
  }
  if (!py::isinstance<py::tuple>(reference) || py::len(reference) != 2)
    throw py::type_error("reference: expected a path to a triangle OBJ or a tuple (V, F)");
  const auto t = py::reinterpret_borrow<py::tuple>(reference);
  TriangleMesh mesh;
  mesh.vertices = point_rows(t[0], "reference V");
  const py::array faces = py::array::ensure(t[1]);
  if (faces && faces.ndim() == 2 && faces.shape(1) == 4) {
    for (const auto& q : faces_from_python<4>(t[1], mesh.num_vertices())) {
      mesh.faces.push_back({q[0], q[1], q[2]});
      mesh.faces.push_back({q[0], q[2], q[3]});
    }
  } else {
    mesh.faces = faces_from_python<3>(t[1], mesh.num_vertices());
  }
  return mesh;
}

}  // namespace

void bind_mesh(py::module_& m) {
  m.def("quantize", &quantize, py::arg("layout"), py::kw_only(), py::arg("scale") = 1.0,
        py::arg("edge_length") = py::none(), py::arg("target_faces") = py::none(),
        py::arg("align") = true, py::arg("threads") = 1, py::arg("time_limit") = py::none(),
        "Quantizes a QuadWild layout (a path to NAME.obj, or a tuple (V, F, patch, corners)) "
        "as `bimdf quantize` does. Returns a dict: status, objective, edge_length, "
        "estimated_quads, lengths (int64 per subside), targets, time.");
  m.def("remesh", &remesh, py::arg("layout"), py::kw_only(), py::arg("scale") = 1.0,
        py::arg("edge_length") = py::none(), py::arg("target_faces") = py::none(),
        py::arg("align") = true, py::arg("smooth_iterations") = 30, py::arg("smooth_damping") = 0.5,
        py::arg("quality_rounds") = 30, py::arg("threads") = 1, py::arg("time_limit") = py::none(),
        py::arg("sharp_angle") = 35.0, py::arg("pairing_radii") = std::vector<double>{1, 1.25},
        py::arg("spare_radii") = std::vector<double>{1}, py::arg("cancel_pairs") = 1.5,
        "Remeshes as `bimdf remesh` does: a QuadWild layout (a path to NAME.obj with NAME.patch "
        "beside it, or a tuple (V, F, patch, corners)) is quantized and tessellated; a bare "
        "triangle or polygon mesh (a path to .obj/.off/.ply without NAME.patch, or a tuple "
        "(V, F)) first gets its own cross field and layout (features above sharp_angle "
        "degrees, one layout per pairing radius and the least bad kept, as --pairing-radii, and "
        "one with fewer lines per spare radius, as --spare-radii; close "
        "pairs of opposite singularities left out of the parametrization, as --cancel-pairs; the "
        "report's 'layout' says how it was made). Returns (V, F, report): "
        "vertices float64 (n, 3), quads int64 (m, 4), the report dict.");
  m.def(
      "requantize", &requantize, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("scale") = 1.0,
      py::arg("edge_length") = py::none(), py::arg("target_faces") = py::none(),
      py::arg("coarse") = false, py::arg("max_angle") = py::none(), py::arg("relaxed") = false,
      py::arg("relaxed_weight") = 1.0, py::arg("sharp_angle") = 35.0, py::arg("cost") = "quadratic",
      py::arg("coarse_lengths") = "strips", py::arg("calibrate") = true,
      py::arg("smooth_iterations") = 30, py::arg("smooth_damping") = 0.5,
      py::arg("quality_rounds") = 30, py::arg("threads") = 1, py::arg("half_arc") = "auto",
      py::arg("reorder_weight") = 1.0, py::arg("keep_crossings") = false,
      py::arg("hold_angle_bound") = false, py::arg("feature_traces") = "auto",
      "Re-quantizes a quad mesh's layout as `bimdf requantize` does (new density, or with "
      "coarse=True the coarsest layout the separation constraints allow; half_arc: 'auto' — "
      "bounded with coarse, else off —, 'exact', 'bounded' or 'off'; feature_traces: 'cross', "
      "'stop' or 'auto' — with coarse both, the smaller base complex kept unless its quads are "
      "worse —, as --feature-traces). Returns (V, F, report).");
  m.def(
      "metrics",
      [](py::handle V, py::handle F, py::handle reference) {
        const QuadMesh mesh = quad_mesh_from_python(V, F);
        std::optional<TriangleMesh> ref;
        if (!reference.is_none()) ref = reference_from_python(reference);
        QuadMeshMetrics m;
        {
          py::gil_scoped_release release;
          m = measure_quad_mesh(mesh, ref ? &*ref : nullptr);
        }
        return metrics_to_python(m);
      },
      py::arg("V"), py::arg("F"), py::arg("reference") = py::none(),
      "Quality of a quad mesh as `bimdf metrics` reports it; reference: a triangle OBJ path or "
      "(V, F) of triangles or quads, for the Hausdorff distance and flipped faces.");
  m.def(
      "base_complex_patches",
      [](py::handle V, py::handle F) {
        const QuadMesh mesh = quad_mesh_from_python(V, F);
        std::vector<int> patch;
        {
          py::gil_scoped_release release;
          patch = base_complex_patches(mesh);
        }
        py::array_t<int64_t> out(static_cast<py::ssize_t>(patch.size()));
        std::copy(patch.begin(), patch.end(), out.mutable_data());
        return out;
      },
      py::arg("V"), py::arg("F"),
      "Per quad, the patch of the mesh's base complex it lies in (0 … base_complex_faces − 1, "
      "as `bimdf render --base-complex` colours them).");
  m.def(
      "read_obj",
      [](const std::string& path) {
        require_file(path);
        return mesh_to_python(read_obj_quads(path));
      },
      py::arg("path"), "Reads an all-quad OBJ: (V, F).");
  m.def(
      "write_obj",
      [](const std::string& path, py::handle V, py::handle F) {
        const QuadMesh mesh = quad_mesh_from_python(V, F);
        std::ofstream out(path, std::ios::binary);
        if (!out) throw py::value_error(path + ": cannot be written");
        write_obj(out, mesh);
        if (!out.flush()) throw py::value_error(path + ": writing failed");
      },
      py::arg("path"), py::arg("V"), py::arg("F"), "Writes a quad mesh as OBJ.");
}

}  // namespace bimdf::python
