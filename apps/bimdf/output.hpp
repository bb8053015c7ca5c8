// How the CLI hands results to the user: stdout, or a file that appears complete or not at all.
#pragma once

#include <string>
#include <vector>

namespace bimdf::cli {

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
