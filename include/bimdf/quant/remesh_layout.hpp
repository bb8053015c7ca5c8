// The stages every layout goes through in `bimdf remesh` and Python's bimdf.remesh, whether
// read from QuadWild's files or made from a bare mesh (layout/generate.hpp): quantization
// (quantize.hpp), tessellation with smoothing (tessellate.hpp), the quad mesh's metrics against
// the layout's triangle mesh (metrics.hpp), and the check that the quad mesh keeps that
// surface's topology (topology_difference). One function, so that the command line and the
// bindings cannot drift apart, and so that generate_layout's LayoutCheck can ask it.
#pragma once

#include <functional>
#include <string>

#include "bimdf/metrics.hpp"
#include "bimdf/quant/quantize.hpp"
#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

struct RemeshedLayout {
  Quantization quantization;
  Tessellation tessellation;
  QuadMeshMetrics metrics;
  // Empty when the quad mesh is manifold with the layout mesh's Euler characteristic and
  // border loops; else what differs, in words (topology_difference).
  std::string topology_difference;
  double quantize_s = 0, tessellate_s = 0, metrics_s = 0;  // wall-clock seconds per stage
};

// Called as each stage ends: "quantized" (detail: the subside count) and "tessellated" (the
// quad count). The caller times and prints; the library never does.
using RemeshProgress = std::function<void(const std::string& stage, const std::string& detail)>;

// How bad a remeshed layout is, for choosing among layouts of one surface
// (layout::LayoutOptions::pairing_radii): inverted and flat quads first, then the mean and 5th
// percentile of the scaled Jacobian — inverted + flat + (2 − mean − p5) / 5, so one inverted
// or flat quad outweighs any difference in the two (a flat quad is as unusable as an inverted
// one, and smoothing cannot tell them apart by the mean and p5).
double layout_badness(const RemeshedLayout& remeshed);

// Throws what quantize and tessellate throw.
RemeshedLayout remesh_layout(const Layout& layout, const QuantizeOptions& quantize_options,
                             const SmoothingOptions& smoothing,
                             const RemeshProgress& progress = {});

}  // namespace bimdf::quant
