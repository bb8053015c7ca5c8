// `bimdf requantize`: a quad mesh's layout re-quantized — a new density, or the coarsest
// layout its singularities and features allow — and tessellated again (include/bimdf/tmesh).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "output.hpp"

namespace bimdf::cli {

struct RequantizeCommandOptions {
  std::string mesh;      // QUAD.obj
  std::string mesh_out;  // -o OUT.obj
  double scale = 1;      // output edge length as a multiple of the input's
  double edge_length = 0;
  int64_t target_faces = 0;
  bool no_calibration = false;  // --no-calibration: the density as given, not fitted to quads
  double sharp_angle = 35;
  std::string feature_file;
  std::string layout_out, tmesh_out, tmesh_in;
  std::string cost = "quadratic";
  bool coarse = false;
  std::string coarse_lengths = "strips";
  std::string half_arc = "auto";  // --half-arc exact|bounded|off|auto (resolved in run)
  double reorder_weight = 1;      // --reorder-weight, with --half-arc bounded
  bool keep_crossings = false;    // --keep-crossings, with --half-arc bounded
  bool hold_angle_bound = false;  // --hold-angle-bound, with half-arc and an angle bound
  bool compare_greedy = false;    // --compare-greedy
  double max_angle = -1;  // < 0: not given (--coarse then uses tmesh::kDefaultCoarseMaxAngle)
  std::string feature_traces;  // --feature-traces cross|stop|auto; "": not given (auto)
  int threads = 1;
  bool relaxed = false;       // --relaxed: irregular quad patches allowed at a cost
  double relaxed_weight = 1;  // --relaxed-weight: cost per unit of flow turning a corner
  quant::SmoothingOptions smoothing;
  bool verbose = false;
  bool progress = false;  // a line on stderr per stage (tmesh::RequantizeProgress)
  OutputOptions out;      // --json, --report FILE
};

CLI::App* add_requantize_command(CLI::App& app, RequantizeCommandOptions& options);

// Returns the exit code; throws InputError / UsageError.
int run_requantize(const RequantizeCommandOptions& options);

}  // namespace bimdf::cli
