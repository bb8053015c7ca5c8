#include "remesh_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/metrics.hpp"
#include "bimdf/quant/remesh_layout.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "number_checks.hpp"

namespace bimdf::cli {
namespace {

using nlohmann::json;

void add_compare_option(CLI::App* cmd, std::string& compare) {
  cmd->add_option("--compare", compare,
                  "Another quad mesh of the same surface (e.g. QuadWild's, OBJ): its metrics "
                  "side by side with this one's, against the same reference");
}

void add_mesh_output(CLI::App* cmd, RemeshCommandOptions& o, bool required = true) {
  auto* out = cmd->add_option("-o,--output", o.mesh_out,
                              "The quad mesh OBJ to write (one group per patch)");
  if (required) out->required();
  cmd->add_option("--feature-out", o.feature_out,
                  "Also write the quad mesh's edges along the layout's feature curves, as "
                  "`bimdf requantize --feature` reads them (a count, then `face,edge` lines)");
  cmd->add_flag("--json", o.quantize.out.json, "Print the report as JSON on stdout");
  cmd->add_option("--report", o.quantize.out.file, "Also write the report JSON to this file");
  cmd->add_flag("-v,--verbose", o.verbose, "Per-chart pattern details");
  add_compare_option(cmd, o.compare);
  add_smoothing_options(cmd, o.smoothing);
}

// Subside lengths from a `bimdf quantize` JSON.
std::vector<int64_t> read_quantization(const std::string& path, const quant::Layout& layout) {
  const std::string text = read_text_file(path);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(path, "byte " + std::to_string(e.byte), "not valid JSON");
  }
  if (!j.is_object() || !j.contains("subside_lengths") || !j["subside_lengths"].is_array())
    throw InputError(path, "/subside_lengths",
                     "missing: expected the output of `bimdf quantize` (an array of integers)");
  const json& a = j["subside_lengths"];
  if (a.size() != layout.subsides.size())
    throw InputError(path, "/subside_lengths",
                     std::to_string(a.size()) + " lengths, but the layout has " +
                         std::to_string(layout.subsides.size()) + " subsides");
  std::vector<int64_t> lengths;
  for (size_t s = 0; s < a.size(); ++s) {
    if (!a[s].is_number_integer() || a[s].get<int64_t>() < 1)
      throw InputError(path, "/subside_lengths/" + std::to_string(s),
                       "expected a positive integer, got " + a[s].dump());
    lengths.push_back(a[s].get<int64_t>());
  }
  return lengths;
}

TessellationReport report_tessellation(const quant::Tessellation& t, const std::string& out,
                                       bool verbose) {
  std::map<quant::PatternKind, int> kinds;
  int singular = 0, charts = 0;
  json per_chart = json::array();
  for (const quant::ChartTiling& c : t.charts) {
    if (c.quads == 0) {
      per_chart.push_back(nullptr);
      continue;
    }
    ++charts;
    ++kinds[c.kind];
    singular += c.singularities;
    per_chart.push_back({{"pattern", quant::to_string(c.kind)},
                         {"cuts", c.cuts},
                         {"quads", c.quads},
                         {"singularities", c.singularities}});
  }
  TessellationReport r;
  r.j = {{"mesh", out},
         {"quads", t.mesh.num_quads()},
         {"vertices", t.mesh.num_vertices()},
         {"patterns",
          {{"regular", kinds[quant::PatternKind::Regular]},
           {"cut", kinds[quant::PatternKind::Cut]},
           {"fan", kinds[quant::PatternKind::Fan]}}},
         {"pattern_singularities", singular},
         {"removed_doublets", t.removed_doublets},
         {"collapsed_inverted", t.collapsed_inverted},
         {"released_from_features", t.released_from_features},
         {"released_max_offset", t.released_max_offset},
         {"charts", per_chart},
         {"time",
          {{"patterns_s", t.time_patterns_s},
           {"mapping_s", t.time_mapping_s},
           {"smoothing_s", t.time_smoothing_s},
           {"polish_s", t.time_polish_s}}}};
  std::ostringstream s;
  s << "quad mesh     " << out << ": " << t.mesh.num_quads() << " quads, " << t.mesh.num_vertices()
    << " vertices\n";
  s << "patterns      " << kinds[quant::PatternKind::Regular] << " regular, "
    << kinds[quant::PatternKind::Cut] << " cut into regular parts, "
    << kinds[quant::PatternKind::Fan] << " fans (of " << charts << " charts); " << singular
    << " interior singularities";
  if (t.removed_doublets > 0)
    s << "; " << t.removed_doublets << " vertices of valence 2 removed (quads merged)";
  if (t.collapsed_inverted > 0)
    s << "; " << t.collapsed_inverted << " inverted quads collapsed (opposite corners merged)";
  if (t.released_from_features > 0)
    s << "; " << t.released_from_features
      << " feature vertices let off the features (inverted quads there; at most "
      << t.released_max_offset << " edge lengths off)";
  s << "\n";
  s << "tessellation  patterns " << ms(t.time_patterns_s) << ", mapping " << ms(t.time_mapping_s)
    << ", smoothing " << ms(t.time_smoothing_s) << ", polish " << ms(t.time_polish_s) << "\n";
  if (verbose)
    for (size_t c = 0; c < t.charts.size(); ++c)
      if (t.charts[c].quads > 0 && t.charts[c].kind != quant::PatternKind::Regular)
        s << "  chart " << c << ": " << quant::to_string(t.charts[c].kind) << ", "
          << t.charts[c].cuts << " cuts, " << t.charts[c].quads << " quads, "
          << t.charts[c].singularities << " singularities\n";
  r.text = s.str();
  return r;
}

void write_mesh(const quant::Layout& layout, const quant::Tessellation& t,
                const RemeshCommandOptions& o, const std::vector<std::string>& inputs) {
  // The feature file first: if it may not be written, neither is the mesh.
  if (!o.feature_out.empty()) {
    if (o.feature_out == o.mesh_out)
      throw UsageError{"--feature-out and --output name the same file " + o.mesh_out};
    std::ostringstream features;
    tmesh::write_quad_feature_file(features, t.mesh, quant::feature_edges_of(layout, t));
    write_output_file(o.feature_out, features.str(), inputs);
  }
  std::ostringstream obj;
  write_obj(obj, t.mesh, "bimdf quad mesh from " + o.quantize.layout);
  write_output_file(o.mesh_out, obj.str(), inputs);
}

}  // namespace

namespace {

std::string valence_list(const std::map<int, int>& counts) {
  std::string text;
  for (auto [valence, n] : counts)
    text +=
        (text.empty() ? "" : ", ") + std::to_string(n) + " of valence " + std::to_string(valence);
  return text.empty() ? "none" : text;
}

}  // namespace

void add_smoothing_options(CLI::App* cmd, quant::SmoothingOptions& smoothing) {
  cmd->add_option("--smooth-iterations", smoothing.iterations,
                  "Smoothing rounds on the surface after stitching (0: none)")
      ->default_val(30)
      ->check(whole_number_from(0, 100000));
  cmd->add_option("--smooth-damping", smoothing.damping,
                  "How far each round moves a vertex towards its smoothed position")
      ->default_val(0.5)
      ->check(number_from(0.0, 1.0));
  cmd->add_option("--quality-rounds", smoothing.quality_rounds,
                  "Rounds of quality polishing after smoothing: corners moved towards right "
                  "angles, never lowering a vertex's worst quad or leaving the surface (0: none)")
      ->default_val(30)
      ->check(whole_number_from(0, 1000));
}

TessellationReport report_metrics(const QuadMeshMetrics& m) {
  TessellationReport r;
  const auto by_valence = [](const std::map<int, int>& counts) {
    json j = json::object();
    for (auto [valence, n] : counts) j[std::to_string(valence)] = n;
    return j;
  };
  r.j = {{"faces", m.faces},
         {"vertices", m.vertices},
         {"edges", m.edges},
         {"euler_characteristic", m.euler_characteristic},
         {"boundary_edges", m.boundary_edges},
         {"border_loops", m.border_loops},
         {"manifold", m.manifold()},
         {"non_manifold_edges", m.non_manifold_edges},
         {"non_manifold_vertices", m.non_manifold_vertices},
         {"singular_vertices", m.singular_vertices()},
         {"interior_singularities", by_valence(m.interior_singularities)},
         {"boundary_singularities", by_valence(m.boundary_singularities)},
         {"scaled_jacobian",
          {{"min", m.scaled_jacobian_min},
           {"mean", m.scaled_jacobian_mean},
           {"p5", m.scaled_jacobian_p5}}},
         {"inverted", m.inverted},
         {"degenerate", m.degenerate},
         {"base_complex_faces", m.base_complex_faces}};
  if (m.hausdorff >= 0) {
    r.j["hausdorff"] = m.hausdorff;
    r.j["hausdorff_relative"] = m.hausdorff_relative;
    r.j["flipped"] = m.flipped;
  }
  std::ostringstream s;
  s << "mesh          " << m.faces << " quads, " << m.vertices << " vertices, " << m.edges
    << " edges; Euler characteristic " << m.euler_characteristic << ", " << m.boundary_edges
    << " boundary edges, "
    << (m.manifold() ? std::string("manifold")
                     : "NOT manifold (" + std::to_string(m.non_manifold_edges) + " edges, " +
                           std::to_string(m.non_manifold_vertices) + " vertices)")
    << "\n";
  s << "singularities " << m.singular_vertices() << ": inside "
    << valence_list(m.interior_singularities) << "; on the boundary "
    << valence_list(m.boundary_singularities) << "\n";
  s << "scaled Jac.   min " << significant(m.scaled_jacobian_min, 4) << ", mean "
    << significant(m.scaled_jacobian_mean, 4) << ", 5th percentile "
    << significant(m.scaled_jacobian_p5, 4) << "; " << m.inverted << " inverted, " << m.degenerate
    << " degenerate\n";
  s << "base complex  " << m.base_complex_faces << " patches\n";
  if (m.hausdorff >= 0)
    s << "distance      Hausdorff " << significant(m.hausdorff, 4) << " ("
      << significant(100 * m.hausdorff_relative, 4) << "% of the bounding-box diagonal); "
      << m.flipped << " faces facing away from the surface\n";
  r.text = s.str();
  return r;
}

// `other_path`'s metrics (against the same `reference`, if any) beside `ours`: returns the
// report's "compare" object {"mesh", "metrics"} and appends a two-column table to `text`.
json compare_with(const QuadMeshMetrics& ours, const std::string& other_path,
                  const TriangleMesh* reference, std::string& text) {
  const QuadMesh other = read_obj_quads(other_path);
  if (other.quads.empty())
    throw InputError(other_path, "", "no faces: expected an OBJ quad mesh to compare with");
  const QuadMeshMetrics theirs = measure_quad_mesh(other, reference);
  std::ostringstream s;
  const auto row = [&](const char* label, const std::string& a, const std::string& b) {
    char line[160];
    std::snprintf(line, sizeof line, "%-14s%-16s%s\n", label, a.c_str(), b.c_str());
    s << line;
  };
  const auto fixed = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return std::string(buf);
  };
  row("compared", "this mesh", other_path);
  row("quads", std::to_string(ours.faces), std::to_string(theirs.faces));
  row("singular", std::to_string(ours.singular_vertices()),
      std::to_string(theirs.singular_vertices()));
  row("SJ min", fixed(ours.scaled_jacobian_min), fixed(theirs.scaled_jacobian_min));
  row("SJ mean", fixed(ours.scaled_jacobian_mean), fixed(theirs.scaled_jacobian_mean));
  row("SJ p5", fixed(ours.scaled_jacobian_p5), fixed(theirs.scaled_jacobian_p5));
  row("inverted", std::to_string(ours.inverted), std::to_string(theirs.inverted));
  row("degenerate", std::to_string(ours.degenerate), std::to_string(theirs.degenerate));
  row("base complex", std::to_string(ours.base_complex_faces),
      std::to_string(theirs.base_complex_faces));
  if (reference)
    row("Hausdorff %", fixed(100 * ours.hausdorff_relative),
        fixed(100 * theirs.hausdorff_relative));
  text += s.str();
  return {{"mesh", other_path}, {"metrics", report_metrics(theirs).j}};
}

CLI::App* add_remesh_command(CLI::App& app, RemeshCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "remesh",
      "Remesh a triangle mesh into quads: from a QuadWild patch layout, or from a bare mesh "
      "(cross field and patch layout made here), quantized and tessellated");
  cmd->add_option("MESH", o.quantize.layout,
                  "A QuadWild layout NAME.obj (NAME.patch and NAME.corners beside it, and if "
                  "present NAME.feature, NAME.c_feature), or a bare triangle or polygon mesh "
                  "(.obj, .off, .ply)")
      ->required();
  add_quantize_options(cmd, o.quantize);
  add_mesh_output(cmd, o, false);  // not with --info; run_remesh checks it
  add_standalone_options(cmd, o.standalone);
  return cmd;
}

CLI::App* add_tessellate_command(CLI::App& app, RemeshCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "tessellate", "Tessellate a QuadWild patch layout with the lengths of `bimdf quantize`");
  add_layout_argument(cmd, o.quantize.layout);
  cmd->add_option("QUANTIZATION", o.quantization, "The JSON written by `bimdf quantize -o`")
      ->required();
  add_mesh_output(cmd, o);
  return cmd;
}

CLI::App* add_metrics_command(CLI::App& app, MetricsCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "metrics", "Quality of a quad mesh: topology, singularities, scaled Jacobian, distance");
  cmd->add_option("MESH", o.mesh, "An all-quad OBJ mesh")->required();
  cmd->add_option("--reference", o.reference,
                  "The surface it should follow (triangle OBJ): adds the Hausdorff distance and "
                  "faces facing away");
  add_compare_option(cmd, o.compare);
  add_output_options(cmd, o.out);
  return cmd;
}

int run_metrics(const MetricsCommandOptions& o) {
  const QuadMesh mesh = read_obj_quads(o.mesh);
  if (mesh.quads.empty()) throw InputError(o.mesh, "", "no faces: expected an OBJ quad mesh");
  TriangleMesh reference;
  if (!o.reference.empty()) reference = read_obj_triangles(o.reference);
  const TriangleMesh* against = o.reference.empty() ? nullptr : &reference;
  const QuadMeshMetrics m = measure_quad_mesh(mesh, against);
  TessellationReport r = report_metrics(m);
  if (!o.compare.empty()) r.j["compare"] = compare_with(m, o.compare, against, r.text);
  r.j["mesh"] = o.mesh;
  if (!o.reference.empty()) r.j["reference"] = o.reference;
  std::vector<std::string> inputs{o.mesh};
  if (!o.reference.empty()) inputs.push_back(o.reference);
  if (!o.compare.empty()) inputs.push_back(o.compare);
  deliver(o.out, r.text, r.j.dump(1) + "\n", inputs);
  return kOk;
}

int run_remesh(const RemeshCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const bool bare = !is_quadwild_layout(o.quantize.layout);
  if (o.standalone.info && !bare)
    throw UsageError{"--info describes a bare mesh; " + o.quantize.layout +
                     " is a QuadWild layout (bimdf quantize reports on it)"};
  if (!o.standalone.info && o.mesh_out.empty())
    throw UsageError{"--output is required\nRun 'bimdf remesh --help' for the options."};
  quant::QuantizeOptions quantize_options = effective_quantize_options(o.quantize);
  quantize_options.model.min_border_loop = quant::kRemeshMinBorderLoop;
  // Quantizes and tessellates a layout, says what is wrong with the quad mesh's topology and
  // how bad the mesh is; each result is kept, for the layout generate_layout chooses.
  std::vector<quant::RemeshedLayout> results;
  std::vector<double> ready_s;  // per result: when its layout was ready
  const auto quad_mesh_of = [&](const quant::Layout& layout) {
    ready_s.push_back(seconds_since(start));
    if (o.standalone.progress)
      print_stage(ready_s.back(), "layout", std::to_string(layout.charts.size()) + " patches");
    quant::RemeshProgress progress;
    if (o.standalone.progress)
      progress = [&](const std::string& stage, const std::string& detail) {
        print_stage(seconds_since(start), stage, detail);
      };
    results.push_back(quant::remesh_layout(layout, quantize_options, o.smoothing, progress));
    return layout::LayoutVerdict{results.back().topology_difference,
                                 quant::layout_badness(results.back())};
  };
  StandaloneLayout made;
  if (bare) {
    // A layout whose quad mesh does not have the input's topology is traced another way.
    made = build_standalone_layout(o.quantize.layout, o.standalone, start,
                                   o.standalone.info ? layout::LayoutCheck{} : quad_mesh_of);
    if (o.standalone.info) {
      json j = made.json;
      j["time"] = made.time;
      deliver(o.quantize.out, made.text, j.dump(1) + "\n", {o.quantize.layout});
      return kOk;
    }
  } else if (!o.standalone.layout_out.empty() || !o.standalone.feature_file.empty()) {
    throw UsageError{"--layout-out and --feature apply to a bare mesh; " + o.quantize.layout +
                     " is a QuadWild layout already"};
  }
  const quant::Layout layout =
      bare ? std::move(made.layout) : quant::read_quadwild_layout(o.quantize.layout);
  if (!bare) {
    const std::string wrong = quad_mesh_of(layout).wrong;
    if (!wrong.empty())
      throw std::runtime_error("the quad mesh of " + o.quantize.layout +
                               " would not have the layout's topology (" + wrong +
                               "); nothing written");
  }
  const size_t chosen = bare ? made.checked : results.size() - 1;
  const quant::RemeshedLayout& r = results.at(chosen);
  const double read_s = ready_s.at(chosen);
  const quant::Tessellation& t = r.tessellation;
  write_quantization_model(r.quantization, o.quantize);
  write_mesh(layout, t, o, {o.quantize.layout});
  const QuantizationReport qr =
      report_quantization(layout, r.quantization, o.quantize, read_s, read_s + r.quantize_s);
  TessellationReport tr = report_tessellation(t, o.mesh_out, o.verbose);
  TessellationReport mr = report_metrics(r.metrics);
  json j = tr.j;
  if (!o.compare.empty()) j["compare"] = compare_with(r.metrics, o.compare, &layout.mesh, mr.text);
  j["quantization"] = qr.json;
  j["metrics"] = mr.j;
  j["time"]["read_s"] = read_s;
  j["time"]["quantize_s"] = r.quantize_s;
  j["time"]["metrics_s"] = r.metrics_s;
  j["time"]["total_s"] = seconds_since(start);
  if (bare) {
    for (const auto& [key, value] : made.json.items()) j[key] = value;
    for (const auto& [key, value] : made.time.items()) j["time"][key] = value;
  }
  tr.text += mr.text + "total time    " + ms(seconds_since(start)) + "\n";
  for (const std::string& w : layout.warnings) std::cerr << "warning: " << w << "\n";
  std::vector<std::string> inputs{o.quantize.layout};
  if (!o.compare.empty()) inputs.push_back(o.compare);
  deliver(o.quantize.out, made.text + qr.text + tr.text, j.dump(1) + "\n", inputs);
  return kOk;
}

int run_tessellate(const RemeshCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const quant::Layout layout = quant::read_quadwild_layout(o.quantize.layout);
  const std::vector<int64_t> lengths = read_quantization(o.quantization, layout);
  quant::Tessellation t;
  try {
    t = quant::tessellate(layout, lengths, o.smoothing);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.quantization, "/subside_lengths", e.what());
  }
  write_mesh(layout, t, o, {o.quantize.layout, o.quantization});
  TessellationReport tr = report_tessellation(t, o.mesh_out, o.verbose);
  const QuadMeshMetrics metrics = measure_quad_mesh(t.mesh, &layout.mesh);
  TessellationReport mr = report_metrics(metrics);
  if (!o.compare.empty()) tr.j["compare"] = compare_with(metrics, o.compare, &layout.mesh, mr.text);
  tr.j["metrics"] = mr.j;
  tr.text += mr.text;
  tr.j["time"]["total_s"] = seconds_since(start);
  for (const std::string& w : layout.warnings) std::cerr << "warning: " << w << "\n";
  std::vector<std::string> inputs{o.quantize.layout, o.quantization};
  if (!o.compare.empty()) inputs.push_back(o.compare);
  deliver(o.quantize.out, tr.text, tr.j.dump(1) + "\n", inputs);
  return kOk;
}

}  // namespace bimdf::cli
