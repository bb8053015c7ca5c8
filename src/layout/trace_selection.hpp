// Which traced separatrices a layout keeps (issue 51, item 4). The motorcycle graph
// (tracing.hpp) traces every separatrix; some of them make poor patch borders, and the layout
// generator (generate.cpp) bans them — TraceOptions::banned — and traces again, or drops them
// from the graph it cuts along.
#pragma once

#include <array>
#include <vector>

#include "layout/tracing.hpp"

namespace bimdf::layout {

// Removes unfinished traces, then traces that end on a removed one (their end would dangle),
// until none is left to remove. A trace that ends at a singularity keeps its end whatever
// becomes of the trace that passed there first. Returns how many were removed.
int drop_dangling(std::vector<Trace>& traces);

// Bans (appends to `banned`) every trace that ends on another trace at less than `on_trace`
// radians, or on a curve at less than `on_curve` (Trace::end_angle): it is that line, drifted,
// and would leave a sliver. Traces from `seeds` that end on a trace are kept: they are there
// to cut a patch open, and around a tube the two halves of a loop meet head on. Those that end
// on a curve are not: a seed's way that spirals into a curve leaves the same sliver (on
// couplingdown, genus 9 with 135 seeds, such slivers made a 6-sided patch of 1,013 quads and
// another fanned around one vertex of valence 75), and the opposite way still cuts the patch.
void ban_shallow_ends(const std::vector<Trace>& traces, double on_trace, double on_curve,
                      const std::vector<int>& seeds, std::vector<std::array<int, 2>>& banned);

// A start off the curves (`curve_vertex` false) whose consecutive separatrices (start ways
// i, i + 1, … modulo Trace::start_ways) all end on a curve within `short_length` sits
// practically on that curve: traced, they would cut off small three-sided patches between
// them and the curve, each needing a singularity of its own in its pattern. Bans all but the
// shortest of each such run of two or more; a lone short one stays (a stub joining the
// singularity to the curve). `seeds` are left alone, as by ban_shallow_ends. `short_length` ≤ 0
// bans nothing.
void ban_short_to_curve(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                        const std::vector<int>& seeds, double short_length,
                        std::vector<std::array<int, 2>>& banned);

// A seed (off the curves, four ways) whose two opposite separatrices both end on a curve
// within `short_length` has cut a thin ring across already (a strip between two feature
// loops): its other two, a loop round the ring parallel to the curves, are banned. They would
// split the strip lengthwise into two thinner ones, and closing on themselves they may meet a
// singularity near the seed first and leave a sliver. (Round a wider ring the loop stays: it
// is structure the patches there use.)
void ban_seed_loops(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                    const std::vector<int>& seeds, double short_length,
                    std::vector<std::array<int, 2>>& banned);

// Per vertex of `top`: the length of the shortest path along mesh edges to a vertex of a curve
// (`curve_vertex`), infinity in a component without curves.
std::vector<double> distance_to_curves(const SurfaceTopology& top,
                                       const std::vector<bool>& curve_vertex);

// A separatrix that runs alongside a curve, closer than `near` to it (distance_to_curves,
// `to_curve`) over more than `along` of its length, splits a thin band off the patch beside
// the curve: its quads are squeezed wherever another curve comes near (couplingdown: a
// singularity 2 edges from the rim sent a separatrix along it past a bolt hole, a band 2.7
// edges wide whose chart held 405 of the mesh's 529 quads below a scaled Jacobian of 0.6).
// Bans it (the singularity's other separatrices still bound its patches).
// `seeds` are left alone, as by ban_shallow_ends: in a ring between two feature loops every
// trace runs near a curve, and the seeds are what cut the ring.
void ban_along_curves(const SurfaceTopology& top, const std::vector<Trace>& traces,
                      const std::vector<double>& to_curve, const std::vector<int>& seeds,
                      double near, double along, std::vector<std::array<int, 2>>& banned);

}  // namespace bimdf::layout
