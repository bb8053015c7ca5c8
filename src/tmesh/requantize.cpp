// requantize (tmesh/requantize.hpp): the stages in order, each timed.
#include "bimdf/tmesh/requantize.hpp"

#include <utility>

#include "core/stopwatch.hpp"
#include "tmesh/smooth_requantized.hpp"

namespace bimdf::tmesh {

RequantizeResult requantize(const QuadMesh& mesh, const RequantizeOptions& options,
                            const std::string& source) {
  detail::Stopwatch t;
  TracedTMesh traced = trace_tmesh(mesh, options.trace, source);
  const double trace_s = t.lap();
  RequantizeResult r = requantize_tmesh(std::move(traced), &mesh, options, source);
  r.time_trace_s = trace_s;
  return r;
}

RequantizeResult requantize_tmesh(TracedTMesh traced, const QuadMesh* mesh,
                                  const RequantizeOptions& options, const std::string& source) {
  RequantizeResult r;
  r.traced = std::move(traced);
  const TMesh& tm = r.traced.tmesh;
  detail::Stopwatch t;
  r.incidence = validate_tmesh(tm, source);
  r.quantization = quantize_tmesh(tm, r.incidence, options.quantize);
  r.time_quantize_s = t.lap();
  if (r.quantization.arc_length.empty()) return r;
  const bool on_mesh = mesh && !tm.patch_grid.empty();
  r.collapsed = collapse_and_tessellate(tm, r.incidence, r.quantization.arc_length,
                                        on_mesh ? mesh : nullptr, options.quantize.relaxed);
  r.time_collapse_s = t.lap();
  if (on_mesh)
    smooth_requantized(*mesh, tm, r.incidence, r.traced.feature_edges, r.traced.feature_corners,
                       r.collapsed, options.smoothing);
  r.time_smoothing_s = t.lap();
  return r;
}

}  // namespace bimdf::tmesh
