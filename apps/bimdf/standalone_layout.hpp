// `bimdf remesh` on a bare triangle mesh (issue 51): reads and repairs the mesh, finds its
// features, builds the patch layout (include/bimdf/layout/), and reports what it found; the
// remesh command then quantizes and tessellates that layout as it does QuadWild's.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

#include "bimdf/layout/generate.hpp"
#include "bimdf/quant/layout.hpp"

namespace bimdf::cli {

struct StandaloneOptions {
  layout::FeatureOptions features;
  std::string feature_file;  // --feature: sharp edges as QuadWild's `face,edge` file
  std::string layout_out;    // --layout-out NAME.obj: the layout as QuadWild's files
  bool info = false;         // --info: describe the input and stop
  bool progress = false;     // --progress: a line per stage on stderr
  layout::LayoutOptions layout;
};

void add_standalone_options(CLI::App* cmd, StandaloneOptions& options);

// Whether `path` is a QuadWild layout (an .obj with NAME.patch beside it) rather than a bare
// mesh.
bool is_quadwild_layout(const std::string& path);

struct StandaloneLayout {
  quant::Layout layout;
  nlohmann::json json;  // "input" and "layout" sections of the report
  std::string text;     // their human summary
  nlohmann::json time;  // per stage, seconds
  int checked = -1;     // which call of `check` rated the layout kept (GeneratedLayout::checked)
};

// Reads `mesh_path`, and unless options.info builds its layout (writing --layout-out's files,
// never over `mesh_path`), tracing another way where `check` rejects it and keeping the least
// bad of the layouts it takes (layout::generate_layout). Throws InputError for bad input.
StandaloneLayout build_standalone_layout(const std::string& mesh_path,
                                         const StandaloneOptions& options,
                                         std::chrono::steady_clock::time_point start,
                                         const layout::LayoutCheck& check = {});

}  // namespace bimdf::cli
