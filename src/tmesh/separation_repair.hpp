// Separation repair (requantize.hpp, paper §4.2.3's unexplored lazy constraints): after a
// quantized T-mesh collapses, find what the non-zero paths, as constructed, failed to keep
// apart, and name the zero elements to bound by min-one constraints before solving again.
// Each function adds only elements that are 0 in `length` and not yet in `bounds`, so every
// round of requantize's loop bounds something new and the loop ends.
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

// Seeds (T-mesh vertices where non-zero paths start: singularities, corners) merged into one
// output vertex, or a seed off every curve merged onto a curve (a feature or border arc's
// end): for each such vertex, a breadth-first search from one seed to the other, or to the
// curve vertex, over what merged the points — zero arcs (joining their ends) and zero-width
// patches (joining every T-mesh vertex of their two long sides, through a node of their own)
// — and a min-one bound on the element of that path with the longest target. A singularity
// pulled onto a straight feature curve keeps its valence but, at valence 3, leaves a single
// quad on one side with a 180° corner, which no placement can fix. Returns whether any was
// added.
bool add_separation_bounds(const TMesh& tmesh, const TMeshIncidence& incidence,
                           const std::vector<int64_t>& length, const CollapsedMesh& collapsed,
                           MinOneConstraints& bounds);

// Seeds whose output vertex has a different number of quads around it than the seed has patch
// corners (every quad at a seed is a patch corner, since all its edges are cut): traces leaving
// the seed folded onto each other, or onto the border, where a patch with a corner at the seed
// collapsed — the seed keeps its position but changes valence, which the paths along the
// traces do not prevent (they only need some arc of each trace to be non-zero). Bounds every
// zero element at such a seed: its zero arcs, and the zero side pairs of the patches cornered
// there. Returns whether any was added.
bool add_valence_bounds(const TMesh& tmesh, const std::vector<int64_t>& length,
                        const CollapsedMesh& collapsed, MinOneConstraints& bounds);

// A collapse that failed (CollapseError naming `patches`: two quads folded onto each other, a
// vertex left inside with two quads, a non-manifold vertex): camel's coarse layout with its own
// feature curves merges four T-mesh vertices into an interior vertex of two quads, which no
// non-zero path forbids. Bounds, among the zero elements of those patches — zero arcs along
// their sides, zero side pairs — the one with the longest target not bounded yet, so that the
// repair undoes as little coarsening as it can; each round bounds one more. Returns whether any
// was added (false: nothing there is zero, the failure is not a collapse's to undo).
bool add_collapse_failure_bounds(const TMesh& tmesh, const std::vector<int64_t>& length,
                                 const std::vector<int>& patches, MinOneConstraints& bounds);

// Border loops shorter than 3 (a loop of two edges reads as no hole at all, its two edges
// joining the same vertices; the curve paths keep only each piece between seeds ≥ 1, so a loop
// with fewer than three seeds can shrink to 2): every zero arc of such a loop gets a min-one
// bound, and when the loop has only two arcs, the one with the longer target gets a bound of
// 2 (MinOneConstraints::arcs_two; the input, ≥ 3 edges round the loop, gives it ≥ 2 edges, so
// the bounds stay feasible). Returns whether any was added.
bool add_border_loop_bounds(const TMesh& tmesh, const TMeshIncidence& incidence,
                            const std::vector<int64_t>& length, MinOneConstraints& bounds);

// Quads that smoothing left inverted (`to_split`, quad ids of collapsed.mesh, from
// smooth_requantized): where a quad's corners are pinned (feature corners, ends of curves) or
// smoothing cannot move them without turning a neighbour over, only the quantization can right
// it. On dino at scale 2 such a quad joins two input quads across a bend; on pig a quad of a
// 50:1 sliver strip between feature curves, inverted by the sliding of two of its corners.
// Each gets a bound of 2 on the arc of length 1 with the longest target among those its edges
// run along (MinOneConstraints::arcs_two): the quad splits in two, and the vertex between them
// can move. A quad inside a patch, no edge along an arc of length 1, gets none. Returns whether
// any was added (not when every such arc is bounded already).
bool add_quad_split_bounds(const TMesh& tmesh, const std::vector<int64_t>& length,
                           const CollapsedMesh& collapsed, const std::vector<int>& to_split,
                           MinOneConstraints& bounds);

}  // namespace bimdf::tmesh
