// `bimdf quantize`: integer subside lengths for a QuadWild patch layout (include/bimdf/quant).
#pragma once

#include <CLI/CLI.hpp>
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
int run_quantize(QuantizeCommandOptions options);

}  // namespace bimdf::cli
