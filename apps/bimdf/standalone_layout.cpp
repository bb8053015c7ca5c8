#include "standalone_layout.hpp"

#include <filesystem>
#include <map>
#include <sstream>

#include "bimdf/error.hpp"
#include "bimdf/layout/surface.hpp"
#include "number_checks.hpp"
#include "output.hpp"

namespace bimdf::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Features from --feature: its `face,edge` pairs name the input's own triangles, so they are
// read against the file's faces as written, then mapped to the prepared mesh's vertex ids.
layout::Features features_from_file(const std::string& path, const PolygonMesh& input,
                                    const layout::Surface& surface,
                                    const layout::FeatureOptions& options) {
  if (surface.repairs.triangulated_polygons > 0)
    throw InputError(path, "",
                     "--feature names faces of a triangle mesh, but the mesh has polygons (" +
                         std::to_string(surface.repairs.triangulated_polygons) + " triangulated)");
  TriangleMesh as_read;
  as_read.vertices = input.vertices;
  for (const auto& f : input.faces) as_read.faces.push_back({f[0], f[1], f[2]});
  std::vector<int> prepared(input.num_vertices(), -1);
  for (int v = surface.mesh.num_vertices() - 1; v >= 0; --v) prepared[surface.input_vertex[v]] = v;
  std::vector<std::array<int, 2>> edges;
  for (const auto& [a, b] : quant::read_feature_edges(path, as_read))
    edges.push_back({prepared[a], prepared[b]});
  return layout::features_from_edges(surface.mesh, edges, options, path);
}

std::string plural(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

void add_standalone_options(CLI::App* cmd, StandaloneOptions& o) {
  cmd->add_option("--sharp-angle", o.features.sharp_angle_deg,
                  "Bare mesh: edges whose faces' normals differ by more than this many degrees "
                  "are features (180: none)")
      ->default_val(35.0)
      ->check(number_from(0.0, 180.0));
  cmd->add_option("--feature", o.feature_file,
                  "Bare mesh: its feature edges (QuadWild-style: count, then `face,edge` lines) "
                  "instead of --sharp-angle");
  cmd->add_option("--layout-out", o.layout_out,
                  "Bare mesh: also write the patch layout made for it as QuadWild's files "
                  "(NAME.obj, NAME.patch, NAME.corners, NAME.feature, NAME.c_feature)");
  cmd->add_option("--pairing-radii", o.layout.pairing_radii,
                  "Bare mesh: a separatrix passing this close to another singularity (in average "
                  "edge lengths) is traced into it; one layout per radius, the one whose quad mesh "
                  "is least bad (inverted and flat quads, then scaled Jacobian mean and 5th "
                  "percentile) is kept (with the one of --spare-radii). Each radius is a layout "
                  "and a remesh more")
      ->delimiter(',')
      ->expected(1, 8)
      ->default_str("1,1.25")
      ->check(number_from(0.0, 100.0));
  CLI::Option* spare =
      cmd->add_option("--spare-radii", o.layout.spare_pairing_radii,
                      "Bare mesh: one more layout per radius here (as --pairing-radii), traced "
                      "with fewer lines — no separatrix alongside a feature curve or the border, "
                      "no patch corner where the surface is flat — kept when its quad mesh is less "
                      "bad; helps parts with many features")
          ->delimiter(',')
          ->expected(1, 8)
          ->default_str("1")
          ->check(number_from(0.0, 100.0));
  cmd->add_flag_callback(
         "--no-spare", [&o] { o.layout.spare_pairing_radii.clear(); },
         "Bare mesh: no layout with fewer lines (--spare-radii): about a third less time")
      ->excludes(spare);
  cmd->add_option("--cancel-pairs", o.layout.cancel_pair_radius,
                  "Bare mesh: field singularities of opposite sign (valence 3 and 5) closer than "
                  "this many average edge lengths, off feature curves, are left out of the "
                  "parametrization in pairs (0: none)")
      ->default_val(1.5)
      ->check(number_from(0.0, 100.0));
  cmd->add_flag("--info", o.info,
                "Describe the input (bare mesh: components, border loops, genus, features, the "
                "cross field's singularities) and stop; no -o needed");
  cmd->add_flag("--progress", o.progress, "A line on stderr as each stage ends");
}

bool is_quadwild_layout(const std::string& path) {
  std::error_code ec;
  return fs::exists(fs::path(path).replace_extension(".patch"), ec);
}

StandaloneLayout build_standalone_layout(const std::string& mesh_path, const StandaloneOptions& o,
                                         std::chrono::steady_clock::time_point start,
                                         const layout::LayoutCheck& check) {
  StandaloneLayout out;
  const PolygonMesh input = read_polygon_mesh(mesh_path);
  const layout::Surface surface = layout::prepare_surface(input, mesh_path);
  const layout::Features features =
      o.feature_file.empty() ? layout::detect_features(surface.mesh, o.features)
                             : features_from_file(o.feature_file, input, surface, o.features);
  const layout::SurfaceInfo info = layout::describe_surface(surface.mesh);
  const double read_s = seconds_since(start);
  if (o.progress)
    print_stage(
        read_s, "read",
        plural(surface.mesh.num_faces(), "triangle", "triangles") + ", " +
            plural(static_cast<int>(features.sharp_edges.size()), "sharp edge", "sharp edges"));

  json genus = json::array(), loops = json::array();
  for (int g : info.component_genus) genus.push_back(g);
  for (int b : info.component_border_loops) loops.push_back(b);
  out.json["input"] = {{"mesh", mesh_path},
                       {"triangles", info.faces},
                       {"vertices", info.vertices},
                       {"edges", info.edges},
                       {"components", info.components},
                       {"border_loops", info.border_loops},
                       {"euler_characteristic", info.euler_characteristic},
                       {"component_genus", genus},
                       {"component_border_loops", loops},
                       {"sharp_edges", features.sharp_edges.size()},
                       {"feature_corners", features.corners.size()},
                       {"average_edge_length", info.average_edge_length},
                       {"repairs",
                        {{"triangulated_polygons", surface.repairs.triangulated_polygons},
                         {"flipped_faces", surface.repairs.flipped_faces},
                         {"unreferenced_vertices", surface.repairs.unreferenced_vertices},
                         {"split_vertices", surface.repairs.split_vertices}}}};
  std::ostringstream s;
  std::map<int, int> genus_count;
  for (int g : info.component_genus) ++genus_count[g];
  std::string genus_text;
  for (auto [g, n] : genus_count)
    genus_text +=
        (genus_text.empty() ? "" : ", ") + std::to_string(n) + " of genus " + std::to_string(g);
  s << "input         " << mesh_path << ": " << info.faces << " triangles, " << info.vertices
    << " vertices; " << plural(info.components, "component", "components") << " (" << genus_text
    << "), " << plural(info.border_loops, "border loop", "border loops") << "; "
    << plural(static_cast<int>(features.sharp_edges.size()), "sharp edge", "sharp edges") << ", "
    << plural(static_cast<int>(features.corners.size()), "feature corner", "feature corners")
    << "\n";
  const layout::SurfaceRepairs& r = surface.repairs;
  if (r.triangulated_polygons + r.flipped_faces + r.unreferenced_vertices + r.split_vertices > 0)
    s << "repaired      " << r.triangulated_polygons << " polygons triangulated, "
      << r.flipped_faces << " faces flipped, " << r.unreferenced_vertices
      << " unused vertices dropped, " << r.split_vertices << " pinched vertices split\n";
  out.time["read_s"] = read_s;

  layout::GeneratedLayout g;
  try {
    g = layout::generate_layout(
        surface.mesh, features, o.layout,
        [&](const layout::LayoutProgress& p) {
          if (o.progress) print_stage(read_s + p.elapsed_s, p.stage, p.detail);
        },
        check);
  } catch (const std::runtime_error& e) {
    if (!o.info) throw;
    s << "layout        not possible: " << e.what() << "\n";
    out.json["layout"] = {{"error", e.what()}};
    out.text = s.str();
    return out;
  }
  std::map<int, int> inside, on_border;
  for (const auto& x : g.indices.singularities)
    ++(x.on_border ? on_border : inside)[4 - x.quarter_index];
  json by_valence = json::object();
  std::string valence_text;
  int singular = 0;
  for (auto [valence, n] : inside) {
    by_valence[std::to_string(valence)] = n;
    singular += n;
    valence_text += (valence_text.empty() ? "" : ", ") + std::to_string(n) + " of valence " +
                    std::to_string(valence);
  }
  out.json["field"] = {{"singularities", singular},
                       {"singularities_by_valence", by_valence},
                       {"index_sum", g.indices.quarter_index_sum / 4.0}};
  s << "cross field   " << singular << " singularities inside"
    << (valence_text.empty() ? "" : " (" + valence_text + ")") << "; index sum "
    << g.indices.quarter_index_sum / 4 << " = Euler characteristic\n";
  out.json["layout"] = {{"traced_along", g.traced_parametrization ? "parametrization" : "field"},
                        {"folded_faces", g.folded_faces},
                        {"attempts", g.attempts},
                        {"pairing_radius", g.pairing_radius},
                        {"spare", g.spare},
                        {"cancelled_pairs", g.cancelled_pairs},
                        {"candidates", g.candidates},
                        {"trace_starts", g.trace_starts},
                        {"traces", g.traces},
                        {"removed_traces", g.removed_traces},
                        {"banned_traces", g.banned_traces},
                        {"seeds", g.seeds},
                        {"cuts_across", g.cuts_across},
                        {"triangles", g.layout.mesh.num_faces()},
                        {"patches", g.layout.charts.size()}};
  s << "layout        " << g.traces << " separatrices from " << g.trace_starts << " vertices ("
    << g.removed_traces << " removed), " << g.layout.charts.size() << " patches on "
    << g.layout.mesh.num_faces() << " triangles, traced along the "
    << (g.traced_parametrization ? "parametrization" : "field's streamlines") << " ("
    << g.folded_faces << " folded faces, " << g.cancelled_pairs
    << " close singularity pairs left out"
    << (g.attempts > 1 ? "; tracing attempt " + std::to_string(g.attempts) : std::string());
  if (g.candidates > 1)
    s << "; pairing radius " << g.pairing_radius << (g.spare ? " with fewer lines" : "")
      << ", least bad of " << g.candidates;
  s << ")\n";
  out.time["field_s"] = g.time_field_s;
  out.time["parametrization_s"] = g.time_parametrization_s;
  out.time["trace_s"] = g.time_trace_s;
  out.time["cut_s"] = g.time_cut_s;
  out.time["patches_s"] = g.time_patches_s;
  if (!o.layout_out.empty() && !o.info) {
    const layout::QuadwildFiles files = layout::to_quadwild_files(g.layout);
    const fs::path base(o.layout_out);
    const std::vector<std::string> inputs{mesh_path};
    write_output_file(o.layout_out, files.obj, inputs);
    const auto beside = [&](const char* ext) {
      return fs::path(base).replace_extension(ext).string();
    };
    write_output_file(beside(".patch"), files.patch, inputs);
    write_output_file(beside(".corners"), files.corners, inputs);
    write_output_file(beside(".feature"), files.feature, inputs);
    write_output_file(beside(".c_feature"), files.c_feature, inputs);
  }
  out.layout = std::move(g.layout);
  out.checked = g.checked;
  out.text = s.str();
  return out;
}

}  // namespace bimdf::cli
