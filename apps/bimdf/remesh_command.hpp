// `bimdf remesh`, `bimdf tessellate`, `bimdf metrics`: from a layout (and a quantization) to a
// quad mesh, and what that mesh is worth (include/bimdf/quant/tessellate.hpp, metrics.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "bimdf/metrics.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "quantize_command.hpp"
#include "standalone_layout.hpp"

namespace bimdf::cli {

struct RemeshCommandOptions {
  QuantizeCommandOptions quantize;  // layout, quantization options, --json / report file
  std::string quantization;         // tessellate: the QUANT.json of `bimdf quantize`
  std::string mesh_out;             // -o OUT.obj
  std::string feature_out;          // --feature-out: the mesh's feature edges (face,edge)
  quant::SmoothingOptions smoothing;
  std::string compare;  // --compare OTHER.obj: its metrics beside the output's
  bool verbose = false;
  StandaloneOptions standalone;  // remesh of a bare triangle mesh
};

struct MetricsCommandOptions {
  std::string mesh, reference;
  std::string compare;  // --compare OTHER.obj
  OutputOptions out;
};

// A result for both outputs: the JSON report and the human summary.
struct TessellationReport {
  nlohmann::json j;
  std::string text;
};

// --smooth-iterations and --smooth-damping (remesh, tessellate, requantize).
void add_smoothing_options(CLI::App* cmd, quant::SmoothingOptions& smoothing);

// The mesh part of the remesh report (also used by requantize).
TessellationReport report_metrics(const QuadMeshMetrics& metrics);

CLI::App* add_metrics_command(CLI::App& app, MetricsCommandOptions& options);
int run_metrics(const MetricsCommandOptions& options);

CLI::App* add_remesh_command(CLI::App& app, RemeshCommandOptions& options);
CLI::App* add_tessellate_command(CLI::App& app, RemeshCommandOptions& options);

// Return the exit code; throw InputError / UsageError.
int run_remesh(const RemeshCommandOptions& options);
int run_tessellate(const RemeshCommandOptions& options);

}  // namespace bimdf::cli
