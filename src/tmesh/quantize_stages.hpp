// The solve stages shared by quantize_tmesh (quantize.hpp) and quantize_half_arcs
// (half_arc.hpp), internal to src/tmesh.
#pragma once

#include <algorithm>
#include <vector>

#include "bimdf/tmesh/quantize.hpp"

namespace bimdf::tmesh::detail {

// Sorts v and drops repeated entries.
template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Builds the arc model of `tmesh` with `constraints` (`model_options` as given, its cost,
// coarse, side and relaxed fields taken from `options`), solves it exactly — and for a coarse
// layout the second stage or the uniform factor — and fills `result`'s status, objective,
// coarse fields, lengths, zero_arcs, model size, times and solution. Checks nothing.
void run_quantization(const TMesh& tmesh, const TMeshIncidence& incidence,
                      const MinOneConstraints& constraints, ArcModelOptions model_options,
                      const QuantizeOptions& options, TMeshQuantization& result);

}  // namespace bimdf::tmesh::detail
