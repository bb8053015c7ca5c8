// min_cost_flow.hpp: LEMON's network simplex for cold starts, shortest_path_flow.hpp for warm
// ones. Compiled as C++17 (Debian's LEMON 1.3.1 headers do not
// compile as C++20, DESIGN §6); no LEMON type leaves this file.
#include "backend/min_cost_flow.hpp"

#include <lemon/network_simplex.h>
#include <lemon/static_graph.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "backend/shortest_path_flow.hpp"

namespace bimdf::detail {

double integer_cost_scale(const std::vector<double>& costs, int num_nodes, int limit_log2) {
  double max_abs = 0;
  for (double c : costs) max_abs = std::max(max_abs, std::fabs(c));
  if (max_abs == 0) return 1;
  const double limit = std::ldexp(1.0, limit_log2) / (static_cast<double>(num_nodes) + 1);
  // Largest k with max_abs·2^k ≤ limit, capped at 62.
  int k = static_cast<int>(std::floor(std::log2(limit / max_abs)));
  k = std::min(k, 62);
  while (k > -1074 && max_abs * std::ldexp(1.0, k) > limit) --k;
  return std::ldexp(1.0, k);
}

std::vector<double> potentials_in_cost_units(const MinCostFlowResult& r) {
  std::vector<double> p(r.potential.size());
  for (size_t v = 0; v < p.size(); ++v) p[v] = static_cast<double>(r.potential[v]) / r.cost_scale;
  return p;
}

namespace {

// A warm start is taken when it leaves at most one unit of imbalance per this many nodes, and
// given up (for the network simplex) once its searches have scanned this many arcs per arc of
// the network. The cost of a search grows with the distance to the nearest deficit, so the
// imbalance alone cannot tell: the covers of bull (37k edges) finish warm in ~15 scans per arc
// at half the network simplex's time, while on a generated instance of 10^5 edges the cover's
// searches reach 70 scans per arc, twice the network simplex's time. The limit bounds the loss
// to about the network simplex's own time.
constexpr int64_t kWarmStartNodesPerUnit = 10;
constexpr int64_t kWorkLimitPerArc = 20;

// LEMON's network simplex from scratch on the scaled integer costs: decides unboundedness.
MinCostFlowResult network_simplex(const DirectedMcf& mcf, double scale) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  // StaticDigraph wants arcs sorted by source; remember the permutation.
  std::vector<std::pair<int, int>> arcs(m);
  std::vector<int> order(m);
  for (int i = 0; i < m; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return mcf.source[x] < mcf.source[y]; });
  for (int i = 0; i < m; ++i) arcs[i] = {mcf.source[order[i]], mcf.target[order[i]]};
  lemon::StaticDigraph g;
  g.build(n, arcs.begin(), arcs.end());

  MinCostFlowResult result;
  result.cost_scale = scale;
  lemon::StaticDigraph::ArcMap<int64_t> upper(g), cost(g);
  lemon::StaticDigraph::NodeMap<int64_t> supply(g);
  for (int i = 0; i < m; ++i) {
    const lemon::StaticDigraph::Arc a = g.arc(i);
    upper[a] = mcf.capacity[order[i]];  // kInfinity is LEMON's INF for int64_t
    cost[a] = std::llround(mcf.cost[order[i]] * result.cost_scale);
  }
  for (int v = 0; v < n; ++v) supply[g.node(v)] = mcf.supply[v];

  lemon::NetworkSimplex<lemon::StaticDigraph, int64_t, int64_t> simplex(g);
  simplex.upperMap(upper).costMap(cost).supplyMap(supply);
  switch (simplex.run()) {
    case decltype(simplex)::INFEASIBLE:
      result.status = MinCostFlowStatus::Infeasible;
      return result;
    case decltype(simplex)::UNBOUNDED:
      result.status = MinCostFlowStatus::Unbounded;
      return result;
    case decltype(simplex)::OPTIMAL:
      break;
  }
  result.status = MinCostFlowStatus::Optimal;
  result.flow.assign(m, 0);
  result.scaled_cost.assign(m, 0);
  result.reduced_cost.assign(m, 0);
  for (int i = 0; i < m; ++i) {
    const lemon::StaticDigraph::Arc a = g.arc(i);
    result.flow[order[i]] = simplex.flow(a);
    result.scaled_cost[order[i]] = cost[a];
    result.reduced_cost[order[i]] =
        cost[a] + simplex.potential(g.source(a)) - simplex.potential(g.target(a));
  }
  result.potential.resize(n);
  for (int v = 0; v < n; ++v) result.potential[v] = simplex.potential(g.node(v));
  return result;
}

}  // namespace

MinCostFlowResult solve_min_cost_flow(const DirectedMcf& mcf, int limit_log2,
                                      const std::vector<double>& start_potential) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  MinCostFlowResult result;
  if (n == 0) {  // LEMON reports an empty network as infeasible
    result.status = MinCostFlowStatus::Optimal;
    return result;
  }
  const double scale = integer_cost_scale(mcf.cost, n, std::min(limit_log2, 60));
  if (static_cast<int>(start_potential.size()) != n) return network_simplex(mcf, scale);
  // Started, but the network simplex answers: the start was too far off, or the solver could
  // not decide (see shortest_path_flow.hpp).
  auto abandoned = [&] {
    MinCostFlowResult fallback = network_simplex(mcf, scale);
    fallback.method = MinCostFlowMethod::WarmStartAbandoned;
    return fallback;
  };
  std::vector<int64_t> cost(m);
  for (int a = 0; a < m; ++a) cost[a] = std::llround(mcf.cost[a] * scale);
  // Potentials matter only up to a common shift: centred on their largest, so that a chain of
  // solves, whose potentials only ever decrease, never drifts out of the solver's bounds.
  const double top = *std::max_element(start_potential.begin(), start_potential.end());
  std::vector<int64_t> start(n);
  for (int v = 0; v < n; ++v) {
    const double p = (start_potential[v] - top) * scale;
    start[v] = std::llround(std::clamp(p, -0x1p62, 0x1p62));  // beyond ±2^60: refused
  }
  ShortestPathFlow solver(mcf.supply, mcf.source, mcf.target, mcf.capacity, cost);
  solver.initial_potentials(start).work_limit(kWorkLimitPerArc * static_cast<int64_t>(m));
  // Shortest paths pay per unit of imbalance the start leaves, the network simplex per arc:
  // on the refinement LPs and covers of the shared instances the crossover lies between 0.05
  // and 0.2 units per node (docs/benchmarks.md).
  if (solver.start_imbalance() > n / kWarmStartNodesPerUnit) return abandoned();
  switch (solver.run()) {
    case ShortestPathFlow::Status::Optimal:
      break;
    case ShortestPathFlow::Status::Infeasible:
      result.status = MinCostFlowStatus::Infeasible;
      return result;
    default:
      return abandoned();
  }
  result.status = MinCostFlowStatus::Optimal;
  result.method = MinCostFlowMethod::WarmStart;
  result.cost_scale = scale;
  result.flow = solver.flow();
  result.potential = solver.potential();
  result.scaled_cost = std::move(cost);
  result.reduced_cost.resize(m);
  for (int a = 0; a < m; ++a)
    result.reduced_cost[a] =
        result.scaled_cost[a] + result.potential[mcf.source[a]] - result.potential[mcf.target[a]];
  return result;
}

}  // namespace bimdf::detail
