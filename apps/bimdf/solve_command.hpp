// `bimdf solve`: options and the command itself.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "bimdf/solve.hpp"
#include "output.hpp"

namespace bimdf::cli {

struct SolveCommandOptions {
  std::string problem;
  bool approximate = false;
  int max_deviation = 5;
  std::string parity = "tjoin";
  std::string cover = "asymmetric";
  bool no_simplify = false;
  int threads = 1;
  int64_t max_rounds = 0;  // 0: unlimited
  double time_limit = 0;   // seconds; 0: unlimited
  bool no_lower_bound = false;
  MatchingBackend matching = MatchingBackend::Blossom;
  bool verbose = false;
  bool progress = false;  // a line on stderr per approximation and refinement round
  OutputOptions out;
};

// Registers the subcommand's options on `app`; returns it.
CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& options);

// `--matching blossom|lemon` into `backend`, whose current value is the default (shared with
// `quantize` and `remesh`).
void add_matching_option(CLI::App* cmd, MatchingBackend& backend, const std::string& description);

// Runs it; returns the exit code (0 solved, 1 infeasible). Throws InputError / UsageError.
int run_solve(const SolveCommandOptions& options);

}  // namespace bimdf::cli
