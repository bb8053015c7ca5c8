// The density factor search of requantize's calibration (tmesh/requantize.hpp), apart from
// the quantizations it runs, so that it can be tested on any quad count function.
//
// Quads grow with the factor about as its square, less where separation holds short arcs at
// 1; the count is a step function (lengths are integers) whose steps can be large where many
// arcs round alike (symmetric parts). The search takes secant steps on log quads against log
// factor (the measured slope, kept within [0.5, 4], else 2; where the count did not change,
// half the last slope, down to 0.25, so that the steps double across a flat), clamped to
// [1/limit, limit], and keeps a bracket — the largest factor seen with too few quads and the
// smallest with too many — so that a step that would leave it (hopping over the wanted count
// from side to side) bisects it geometrically instead. It stops within `tolerance` of the wanted
// count, after `max_solves` evaluations, when a step would not move (at a limit or a closed
// bracket), or when quads_at fails (returns a negative count).
#pragma once

#include <functional>

namespace bimdf::tmesh::detail {

struct DensitySearch {
  double factor = 1;  // of the evaluation closest to the wanted count (the first of equals)
  double quads = -1;  // its count (negative: the first evaluation failed)
  int solves = 0;     // evaluations run
  // search_density_factor_within_reach only: the count at 1/reach when it probed there and
  // found too many quads even so — the constraints force more than wanted (else −1).
  double floor_quads = -1;
};

DensitySearch search_density_factor(double wanted, double start, double tolerance, int max_solves,
                                    double limit, const std::function<double(double)>& quads_at);

// As search_density_factor within [1/limit, limit]; then, if that ends with too many quads (at
// 1/limit, or on a flat step before it), one evaluation at 1/reach decides. Where it has too
// many quads as well, the constraints force more quads than wanted and the first search's
// result stands (the open regions are not thinned out for nothing); where it is within
// tolerance, it is taken; where it has too few, a second search starts between 1/reach and
// 1/limit (clamped to [1/reach, reach]). The result is the evaluation closest to the wanted
// count among those the rule accepts; solves counts them all.
DensitySearch search_density_factor_within_reach(double wanted, double start, double tolerance,
                                                 int max_solves, double limit, double reach,
                                                 const std::function<double(double)>& quads_at);

}  // namespace bimdf::tmesh::detail
