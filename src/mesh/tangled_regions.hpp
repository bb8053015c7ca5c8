// Re-embedding tangled regions: the last resort of smoothing where relaxation and untangling
// leave quads inverted. Both move one vertex at a time, so a cluster in which every single
// move turns another quad over stays as it is — in `requantize`, output patches placed through
// the input grid and stretched over strips that collapsed next to them (issue 21). Here each
// cluster of inverted quads, grown by a few rings of quads, gets its inner vertices (those all
// of whose quads are in the region, unless pinned) placed anew, in up to four ways:
//  1. Tutte's barycentric embedding of the region's boundary laid flat on the plane of its
//     quads' mean normal (each free vertex the mean of its neighbours; vertices on curves are
//     part of that boundary), put back onto the surface;
//  2. and 3. all inner vertices moved at once down the untangling energy of
//     surface_untangling.hpp (curve vertices along their curves), from the current positions
//     and from Tutte's;
//  4. the positions before smoothing, where given: smoothing may turn a quad over against its
//     own normal to right others against the surface's, which on slivers can point astray.
// The first three are smoothed again afterwards. Tutte's embedding is one-to-one on the plane
// when the boundary's projection is convex; the descent needs neither a convex nor a flat
// boundary, but may stop in a local minimum. The best placement is kept only if the region
// then has fewer inverted quads, or as many with a better worst one, so the pass never makes
// the mesh worse by that count.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "bimdf/mesh.hpp"
#include "mesh/mesh_on_surface.hpp"

namespace bimdf::detail {

struct TangledRegionInput : MeshOnSurface {
  // How a vertex may move: not at all, along its curve (border or feature; `project` keeps it
  // there), or anywhere on its part of the surface. Tutte's embedding places only the last
  // kind (the others are part of the region's boundary); the descent and the way back to
  // `placed` move the last two.
  enum class Freedom { kPinned, kOnCurve, kFree };
  std::function<Freedom(int)> freedom;
  // A quad's scaled Jacobian against its own normal (what metrics.hpp reports) and against the
  // surface's under it, negative where it is inverted: both count, so that a region laid flat
  // the wrong way round does not pass for untangled.
  std::function<std::array<double, 2>(int)> quality;
  // The surface's unit normal under a quad (zero where unknown: the quad's own is taken).
  std::function<Vec3(int)> surface_normal;
  // Relaxes and untangles the given vertices (the others stay).
  std::function<void(const std::vector<int>&)> smooth;
  // Where every vertex was placed before smoothing, if known: smoothing can turn a quad over
  // against its own normal to right others against the surface's, and the region's last
  // alternative is to go back there (unsmoothed).
  const std::vector<Vec3>* placed = nullptr;
};

struct TangledRegionReport {
  int regions = 0;          // regions re-embedded
  int kept = 0;             // of which the new positions were kept
  int inverted_before = 0;  // inverted quads in the mesh before the pass
  int inverted_after = 0;   // and after it
};

// Re-embeds the regions around inverted quads; only the vertices `vertices` may move.
TangledRegionReport reembed_tangled_regions(const TangledRegionInput& input,
                                            const std::vector<int>& vertices);

}  // namespace bimdf::detail
