// remesh_layout (remesh_layout.hpp): quantize, tessellate, measure, check the topology.
#include "bimdf/quant/remesh_layout.hpp"

#include "core/stopwatch.hpp"

namespace bimdf::quant {

RemeshedLayout remesh_layout(const Layout& layout, const QuantizeOptions& quantize_options,
                             const SmoothingOptions& smoothing, const RemeshProgress& progress) {
  RemeshedLayout out;
  detail::Stopwatch watch;
  out.quantization = quantize(layout, quantize_options);
  out.quantize_s = watch.lap();
  if (progress) progress("quantized", std::to_string(layout.subsides.size()) + " subsides");
  out.tessellation = tessellate(layout, out.quantization.lengths(), smoothing);
  out.tessellate_s = watch.lap();
  if (progress)
    progress("tessellated", std::to_string(out.tessellation.mesh.num_quads()) + " quads, smoothed");
  out.metrics = measure_quad_mesh(out.tessellation.mesh, &layout.mesh);
  out.metrics_s = watch.lap();
  out.topology_difference = topology_difference(out.metrics, layout.mesh);
  return out;
}

double layout_badness(const RemeshedLayout& remeshed) {
  const QuadMeshMetrics& m = remeshed.metrics;
  return m.inverted + m.degenerate + (2 - m.scaled_jacobian_mean - m.scaled_jacobian_p5) / 5;
}

}  // namespace bimdf::quant
