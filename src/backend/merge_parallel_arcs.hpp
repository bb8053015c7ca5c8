// Parallel and opposite arcs of a directed min-cost flow merged into convex piecewise-linear
// arcs (backend/convex_network_simplex.hpp), and the merged flow split back. The linearized
// double covers (reduce/linearize.hpp, reduce/double_cover.hpp) give every edge a run of pieces
// between the same two nodes — forward pieces one way, backward ones the other — at costs that
// rise away from the guess, so one arc with a breakpoint per piece carries them all.
//
// Arcs u → v and v → u between the same two nodes u < v become one arc u → v whose flow is the
// net flow: the u → v pieces sorted by cost ascending lie right of 0, the v → u pieces left of
// it with their costs negated (the cheapest nearest 0). The result is convex when the cheapest
// v → u cost plus the cheapest u → v cost is ≥ 0 (no negative two-cycle); otherwise the two
// directions stay two arcs, each convex on its own. Pieces beyond an infinite one are dropped
// (an optimum never needs them), adjacent pieces of equal cost share a segment, and loops stay
// arcs of their own. Every merged arc starts at flow 0.
//
// Splitting: a net flow f ≥ 0 fills the u → v pieces cheapest first, f < 0 the v → u pieces.
// Under the same potentials this split satisfies complementary slackness piece by piece
// whenever the merged flow is optimal (a filled piece is no dearer than the left slope at f, an
// empty one no cheaper than the right slope, the other direction priced out by convexity).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "backend/convex_network_simplex.hpp"
#include "graph/directed_mcf.hpp"

namespace bimdf::detail {

struct MergedArcs {
  ConvexMcf convex;
  // Merged arc j holds the original arcs member[member_first[j] …]: the `forward_count[j]`
  // arcs along it by ascending cost, then those against it by ascending cost.
  std::vector<int> member_first, member, forward_count;

  // Per original arc, its share of the merged flows (see above).
  std::vector<int64_t> split(const std::vector<int64_t>& merged_flow,
                             const std::vector<int64_t>& capacity) const;
};

// `cost` holds the arcs' integer costs. Nothing when a merged arc's range would leave ±2^62
// (then the caller solves `mcf` as it is).
std::optional<MergedArcs> merge_parallel_arcs(const DirectedMcf& mcf,
                                              const std::vector<int64_t>& cost);

}  // namespace bimdf::detail
