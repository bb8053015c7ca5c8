// Re-quantizing a quad mesh (issue 21): the whole pipeline in one call — motorcycle T-mesh
// (from_quad_mesh.hpp), exact quantization with zero-length arcs (quantize.hpp), collapse and
// tessellation (collapse.hpp), smoothing on the input surface with features and border kept.
#pragma once

#include <string>

#include "bimdf/mesh.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/quantize.hpp"

namespace bimdf::tmesh {

struct RequantizeOptions {
  TraceOptions trace;  // density, features
  QuantizeOptions quantize;
  quant::SmoothingOptions smoothing;
};

struct RequantizeResult {
  TracedTMesh traced;
  TMeshIncidence incidence;
  TMeshQuantization quantization;  // status Infeasible: no mesh (collapsed is empty)
  CollapsedMesh collapsed;
  double time_trace_s = 0, time_quantize_s = 0, time_collapse_s = 0, time_smoothing_s = 0;
};

// Traces `mesh` (all quads; errors name `source`), then as requantize_tmesh.
RequantizeResult requantize(const QuadMesh& mesh, const RequantizeOptions& options,
                            const std::string& source);

// Quantizes a given T-mesh (validated here; errors name `source`), collapses and tessellates
// it, and — when it has patch grids and `mesh` is the quad mesh they index — smooths the
// result on `mesh`. `options.trace` is not used. Throws CollapseError if the quantized
// T-mesh does not collapse into a conforming mesh (see collapse.hpp).
RequantizeResult requantize_tmesh(TracedTMesh traced, const QuadMesh* mesh,
                                  const RequantizeOptions& options, const std::string& source);

}  // namespace bimdf::tmesh
