// `bimdf render`: a PNG picture of a quad mesh (include/bimdf/render.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bimdf/render.hpp"

namespace bimdf::cli {

struct RenderCommandOptions {
  std::string mesh, picture;
  std::vector<double> view;  // empty: automatic
  bool no_edges = false, no_patches = false, no_singularities = false;
  bool base_complex = false;  // colour the base complex's patches instead of the groups
  RenderOptions render;
};

CLI::App* add_render_command(CLI::App& app, RenderCommandOptions& options);
int run_render(RenderCommandOptions options);

}  // namespace bimdf::cli
