// The requantize benchmark (issue 21): every shared layout remeshed by `bimdf remesh`, then that
// quad mesh re-quantized at several settings by `bimdf requantize`.
#pragma once

#include <string>

namespace bimdf::bench {

// Returns the Markdown section (table and summary). `dir`: the shared layouts folder.
std::string benchmark_requantize(const std::string& cli, const std::string& dir, int repeats);

}  // namespace bimdf::bench
