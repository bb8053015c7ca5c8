// Helpers shared by the benchmark programs: running the CLI in its own process, medians,
// number formatting, shell output, and replacing a generated section of a Markdown file.
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace bimdf::bench {

struct Run {
  nlohmann::json solution;  // the CLI's JSON output
  double peak_rss_mb = 0;   // the child's peak resident memory
};

// Runs `cli` with `args` (the last one names the input, for error messages); exit codes 0 and
// 1 are results, anything else throws.
Run run_cli(const std::string& cli, const std::vector<std::string>& args);

double median(std::vector<double> v);

// Runs `cli` with `args` `repeats` times (3 when the first run takes over a second) and returns
// the JSON output of the run whose `time.total_s` is closest to the median, and that median.
struct MedianRun {
  nlohmann::json output;
  double seconds = 0;
};
MedianRun median_run(const std::string& cli, const std::vector<std::string>& args, int repeats);

// One row of a shared layouts folder's expected.tsv: the reference quantizer's optima and
// quad counts without and with alignment.
struct LayoutReference {
  std::string mesh;
  double noalign_opt = 0, align_opt = 0;
  int noalign_quads = 0, align_quads = 0;
};
std::vector<LayoutReference> read_layout_references(const std::string& dir);

// Remeshes every layout of the shared layouts folder `dir` with `bimdf remesh` into a scratch
// folder (removed afterwards) and calls visit(layout name, the remeshed OBJ — "" if remesh
// failed —, a scratch path for outputs), in expected.tsv's order.
void for_each_remeshed_layout(
    const std::string& cli, const std::string& dir,
    const std::function<void(const std::string&, const std::string&, const std::string&)>& visit);

// Fixed-point text, "–" for NaN.
std::string fmt(double v, int precision = 3);

// A shell command's output without the trailing newline.
std::string shell(const std::string& cmd);

// Replaces what lies between "<!-- NAME:begin -->" and "<!-- NAME:end -->" in the file at
// `path` by `body`; false if the markers are missing.
bool replace_section(const std::string& path, const std::string& name, const std::string& body);

}  // namespace bimdf::bench
