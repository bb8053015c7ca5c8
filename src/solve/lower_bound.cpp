#include "solve/lower_bound.hpp"

#include <limits>

#include "backend/min_cost_flow.hpp"
#include "reduce/double_cover.hpp"
#include "reduce/linearize.hpp"

namespace bimdf::detail {

double relaxation_lower_bound(const Problem& p, std::span<const int64_t> center,
                              int max_deviation) {
  LinearizeOptions opt;
  opt.max_deviation = max_deviation;
  opt.step = 1;
  opt.underestimating_tails = true;
  const Linearization lin = linearize(p, center, opt);
  const DoubleCover dc = build_double_cover(lin.mcf, DoubleCoverKind::Relaxation);
  const MinCostFlowResult r = solve_min_cost_flow(dc.mcf);
  if (r.status == MinCostFlowStatus::Infeasible) return std::numeric_limits<double>::infinity();
  if (r.status == MinCostFlowStatus::Unbounded) return -std::numeric_limits<double>::infinity();
  double value = 0;
  for (int e = 0; e < p.num_edges(); ++e) value += p.cost[e](center[e]);
  // The directed flow is twice the Bi-MCF flow (Relaxation), so halve its cost.
  double arc_cost = 0, units = 0;
  for (int k = 0; k < dc.mcf.num_arcs(); ++k) {
    arc_cost += dc.mcf.cost[k] * static_cast<double>(r.flow[k]);
    units += static_cast<double>(r.flow[k]);
  }
  // Costs rounded to multiples of 1/S make the solver's optimum cost at most (|f| + |f*|)/(2S)
  // more than the true LP optimum f*'s. |f*| is unknown; one 1/S per unit of the solver's flow
  // covers optima of similar size. S ≥ 2^40 / max|cost| on real instances: the margin is
  // far below the 1e-9 relative tolerance the tests allow.
  return value + arc_cost / 2 - units / r.cost_scale;
}

}  // namespace bimdf::detail
