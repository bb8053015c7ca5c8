// The quantizer on QuadWild layouts (`bimdf quantize`): per layout and configuration, sizes,
// the objective against the reference quantizer's, QuadWild-style energies, quads and time per
// stage (median of repeated runs).
#pragma once

#include <string>

namespace bimdf::bench {

// `dir`: ../shared/data/layouts (one folder per mesh, expected.tsv with the references).
// Returns the Markdown section (table and totals).
std::string benchmark_layouts(const std::string& cli, const std::string& dir, int repeats);

}  // namespace bimdf::bench
