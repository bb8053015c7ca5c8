// The half-arc benchmark (issue 22): Table 1 of the paper on our data — every shared layout
// remeshed by `bimdf remesh`, then `bimdf requantize --coarse` at four angles with the greedy
// model and both half-arc models, base complexes, quantization times and mesh quality side by
// side.
#pragma once

#include <string>

namespace bimdf::bench {

// Returns the Markdown section (table and summary). `dir`: the shared layouts folder.
std::string benchmark_half_arc(const std::string& cli, const std::string& dir, int repeats);

}  // namespace bimdf::bench
