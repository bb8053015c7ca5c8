// `bimdf remesh`, `bimdf tessellate`, `bimdf metrics`: from a layout (and a quantization) to a
// quad mesh, and what that mesh is worth (include/bimdf/quant/tessellate.hpp, metrics.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "bimdf/quant/tessellate.hpp"
#include "quantize_command.hpp"

namespace bimdf::cli {

struct RemeshCommandOptions {
  QuantizeCommandOptions quantize;  // layout, quantization options, --json / report file
  std::string quantization;         // tessellate: the QUANT.json of `bimdf quantize`
  std::string mesh_out;             // -o OUT.obj
  quant::SmoothingOptions smoothing;
  bool verbose = false;
};

struct MetricsCommandOptions {
  std::string mesh, reference;
  OutputOptions out;
};

CLI::App* add_metrics_command(CLI::App& app, MetricsCommandOptions& options);
int run_metrics(const MetricsCommandOptions& options);

CLI::App* add_remesh_command(CLI::App& app, RemeshCommandOptions& options);
CLI::App* add_tessellate_command(CLI::App& app, RemeshCommandOptions& options);

// Return the exit code; throw InputError / UsageError.
int run_remesh(const RemeshCommandOptions& options);
int run_tessellate(const RemeshCommandOptions& options);

}  // namespace bimdf::cli
