// `bimdf quantize`: integer subside lengths for a QuadWild patch layout (include/bimdf/quant).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bimdf/quant/quantize.hpp"
#include "output.hpp"

namespace bimdf::cli {

struct QuantizeCommandOptions {
  std::string layout;       // NAME.obj beside NAME.patch, NAME.corners, …
  std::string write_bimdf;  // export the final round's Bi-MDF model
  bool half_targets = false;
  std::vector<double> unalign_weights;  // rounds 1 and 2; empty: the defaults
  bool verbose = false;
  quant::QuantizeOptions quantize;
  OutputOptions out;
};

CLI::App* add_quantize_command(CLI::App& app, QuantizeCommandOptions& options);

// Returns the exit code; throws InputError / UsageError.
int run_quantize(const QuantizeCommandOptions& options);

// Pieces shared with `bimdf remesh`, which quantizes first.
void add_layout_argument(CLI::App* cmd, std::string& layout);
void add_quantize_options(CLI::App* cmd, QuantizeCommandOptions& options);  // all but LAYOUT, -o
quant::QuantizeOptions effective_quantize_options(const QuantizeCommandOptions& options);

struct QuantizationReport {
  nlohmann::json json;  // docs/formats.md §5
  std::string text;     // the human summary
};
QuantizationReport report_quantization(const quant::Layout& layout, const quant::Quantization& q,
                                       const QuantizeCommandOptions& options, double read_s,
                                       double total_s);
// --write-bimdf, if given.
void write_quantization_model(const quant::Quantization& q, const QuantizeCommandOptions& options);

}  // namespace bimdf::cli
