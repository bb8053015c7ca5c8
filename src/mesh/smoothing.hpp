// Smoothing in parts (smooth_on_surface in quant/tessellate.hpp smooths everything once):
// tessellate smooths the whole mesh, then gives tangled charts more starts, each smoothed
// alone (chart_placement.hpp). The setup that depends only on the layout and the mesh's
// connectivity — curves, adjacency, closest-point trees — is built once for all those runs.
#pragma once

#include <memory>
#include <vector>

#include "bimdf/quant/tessellate.hpp"

namespace bimdf::quant {

class SurfaceSmoother {
 public:
  // Prepares smoothing `tessellation` (a tessellation of `layout`; both must outlive the
  // smoother, and the mesh's connectivity must not change). `vertex_charts`, when given, has
  // one entry per quad mesh vertex: a non-empty entry replaces the charts that vertex may move
  // on (and be projected onto), which its origin would otherwise decide — for vertices made of
  // several layout points (tmesh collapse) that belong to more charts than one origin names,
  // and for feature-curve vertices let off their curve (inverted_cleanup.hpp): a non-empty
  // entry also frees the vertex from the curve it would slide along. Empty entries change
  // nothing.
  SurfaceSmoother(const Layout& layout, Tessellation& tessellation,
                  const std::vector<std::vector<int>>* vertex_charts = nullptr);
  ~SurfaceSmoother();

  // Relaxation and untangling (`options.iterations` rounds): every vertex may move.
  void run(const SmoothingOptions& options);
  // The same restricted to the quad mesh vertices `vertices`: the others stay where they are.
  void run(const SmoothingOptions& options, const std::vector<int>& vertices);

  // Re-embedding of the regions around quads still inverted after run() (tangled_regions.hpp),
  // each smoothed again with `options`; only `vertices` move. Meant for requantize, whose
  // patches are placed through the input's grid rather than flattened chart by chart.
  // `placed`, when given, holds every vertex's position before run(): a region may go back
  // to it where smoothing turned quads over that the placement had not.
  void reembed_tangled(const SmoothingOptions& options, const std::vector<int>& vertices,
                       const std::vector<std::array<double, 3>>* placed = nullptr);

  // Quality polishing (`options.quality_rounds` rounds, quality_polish.hpp), meant as the last
  // step, after every run: moving vertices before a tangled chart's retries changes where
  // those start.
  void polish(const SmoothingOptions& options);
  void polish(const SmoothingOptions& options, const std::vector<int>& vertices);

 private:
  // Whether quad mesh vertex v may move at all: it has charts to move on or a curve to slide
  // along (pinned vertices — feature corners, ends of curves — and isolated ones stay).
  bool can_move(int v) const;

  struct Setup;
  std::unique_ptr<Setup> setup_;
  enum class Phase { kRelaxAndUntangle, kTangledRegions, kPolish };
  void run(const SmoothingOptions& options, const std::vector<int>* only, Phase phase,
           const std::vector<std::array<double, 3>>* placed = nullptr);
};

}  // namespace bimdf::quant
