// The quad mesher on QuadWild layouts (`bimdf remesh`, default options): per layout, quads
// against the reference quantizer's quad mesh, pattern kinds, singularities, scaled Jacobian,
// inverted quads, distance to the input, and time per stage (median of repeated runs).
#pragma once

#include <string>

namespace bimdf::bench {

// `dir`: ../shared/data/layouts (one folder per mesh, expected.tsv with the references).
// Returns the Markdown section (table and totals).
std::string benchmark_remesh(const std::string& cli, const std::string& dir, int repeats);

}  // namespace bimdf::bench
