// How the CLI hands results to the user: stdout, or a file that appears complete or not at all.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <string>
#include <vector>

namespace bimdf::cli {

enum ExitCode { kOk = 0, kNoSolution = 1, kBadInput = 2, kInternal = 3 };

// Where a subcommand's result goes (README: the CLI contract).
struct OutputOptions {
  bool json = false;  // --json: the result JSON on stdout instead of the human text
  std::string file;   // -o FILE: the result JSON into FILE
};
void add_output_options(CLI::App* cmd, OutputOptions& out);

// Prints `human` (or `json_text` with --json) and writes `json_text` to -o FILE if given,
// refusing to overwrite any of `inputs`.
void deliver(const OutputOptions& out, const std::string& human, const std::string& json_text,
             const std::vector<std::string>& inputs);

// Seconds elapsed since `start`, and a duration in milliseconds for the human summaries:
// "12.3 ms" by default, "12.345 ms" with decimals = 3 (solve's stage breakdown, where stages of
// small instances take microseconds).
double seconds_since(std::chrono::steady_clock::time_point start);
std::string ms(double seconds, int decimals = 1);

// `v` rounded to `significant_digits` as printf's %g writes it (1.135, 0.0001234, 1.5e+07): the
// human summaries' objectives (9 digits) and quality figures (4 digits).
std::string significant(double v, int significant_digits);

// The shortest decimal that reads back as exactly `x` (1.135, not 1.1350000000000000).
std::string shortest_decimal(double x);

// One line per stage, on stderr (stdout may carry the report), timed from the command's start:
//   progress 2.871 s: quantized: optimal, objective 2112, 310 arcs of length 0
void print_stage(double elapsed_s, const std::string& stage, const std::string& detail);

// Thrown for usage errors the CLI detects itself (exit code 2).
struct UsageError {
  std::string message;
};

// Writes `content` to `path` atomically: into a temporary file beside it, then renamed over it,
// so a failure never leaves a partial file. Refuses (UsageError) when `path` is one of `inputs`:
// the user's input files are never overwritten.
void write_output_file(const std::string& path, const std::string& content,
                       const std::vector<std::string>& inputs);

}  // namespace bimdf::cli
