// min_cost_flow.hpp: LEMON's network simplex for cold starts, shortest_path_flow.hpp for warm
// ones. Compiled as C++17 (Debian's LEMON 1.3.1 headers do not
// compile as C++20, DESIGN §6); no LEMON type leaves this file.
#include "backend/min_cost_flow.hpp"

#include <lemon/network_simplex.h>
#include <lemon/static_graph.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

// The integer costs llround(c·S) the solvers see (min_cost_flow.hpp).
std::vector<int64_t> scaled_costs(const DirectedMcf& mcf, double scale) {
  std::vector<int64_t> cost(mcf.num_arcs());
  for (int a = 0; a < mcf.num_arcs(); ++a) cost[a] = std::llround(mcf.cost[a] * scale);
  return cost;
}

// LEMON's network simplex on the arcs source → target of `mcf`'s capacities, with integer
// costs `cost` and the supplies `supply`: status, and when optimal the flow and potentials.
struct SimplexOutcome {
  MinCostFlowStatus status = MinCostFlowStatus::Infeasible;
  std::vector<int64_t> flow, potential;
};

SimplexOutcome lemon_network_simplex(const DirectedMcf& mcf, const std::vector<int>& source,
                                     const std::vector<int>& target,
                                     const std::vector<int64_t>& cost,
                                     const std::vector<int64_t>& supply) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  // StaticDigraph wants arcs sorted by source; remember the permutation.
  std::vector<std::pair<int, int>> arcs(m);
  std::vector<int> order(m);
  for (int i = 0; i < m; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return source[x] < source[y]; });
  for (int i = 0; i < m; ++i) arcs[i] = {source[order[i]], target[order[i]]};
  lemon::StaticDigraph g;
  g.build(n, arcs.begin(), arcs.end());

  lemon::StaticDigraph::ArcMap<int64_t> upper(g), arc_cost(g);
  lemon::StaticDigraph::NodeMap<int64_t> node_supply(g);
  for (int i = 0; i < m; ++i) {
    const lemon::StaticDigraph::Arc a = g.arc(i);
    upper[a] = mcf.capacity[order[i]];  // kInfinity is LEMON's INF for int64_t
    arc_cost[a] = cost[order[i]];
  }
  for (int v = 0; v < n; ++v) node_supply[g.node(v)] = supply[v];

  lemon::NetworkSimplex<lemon::StaticDigraph, int64_t, int64_t> simplex(g);
  simplex.upperMap(upper).costMap(arc_cost).supplyMap(node_supply);
  SimplexOutcome out;
  switch (simplex.run()) {
    case decltype(simplex)::INFEASIBLE:
      out.status = MinCostFlowStatus::Infeasible;
      return out;
    case decltype(simplex)::UNBOUNDED:
      out.status = MinCostFlowStatus::Unbounded;
      return out;
    case decltype(simplex)::OPTIMAL:
      break;
  }
  out.status = MinCostFlowStatus::Optimal;
  out.flow.assign(m, 0);
  for (int i = 0; i < m; ++i) out.flow[order[i]] = simplex.flow(g.arc(i));
  out.potential.resize(n);
  for (int v = 0; v < n; ++v) out.potential[v] = simplex.potential(g.node(v));
  return out;
}

// The result for integer costs `cost` from a flow and potentials optimal for them.
MinCostFlowResult optimal_result(const DirectedMcf& mcf, double scale, std::vector<int64_t> cost,
                                 std::vector<int64_t> flow, std::vector<int64_t> potential) {
  MinCostFlowResult result;
  result.status = MinCostFlowStatus::Optimal;
  result.cost_scale = scale;
  result.flow = std::move(flow);
  result.potential = std::move(potential);
  result.scaled_cost = std::move(cost);
  result.reduced_cost.resize(mcf.num_arcs());
  for (int a = 0; a < mcf.num_arcs(); ++a)
    result.reduced_cost[a] =
        result.scaled_cost[a] + result.potential[mcf.source[a]] - result.potential[mcf.target[a]];
  return result;
}

// Bounds, conservation and complementary slackness of an Optimal result: LP duality's proof.
bool certifies_optimality(const DirectedMcf& mcf, const MinCostFlowResult& r) {
  std::vector<int64_t> net(mcf.num_nodes(), 0);
  for (int a = 0; a < mcf.num_arcs(); ++a) {
    const int64_t f = r.flow[a], rc = r.reduced_cost[a];
    if (f < 0 || f > mcf.capacity[a] || (f < mcf.capacity[a] && rc < 0) || (f > 0 && rc > 0))
      return false;
    net[mcf.source[a]] += f;
    net[mcf.target[a]] -= f;
  }
  return net == mcf.supply;
}

// LEMON's network simplex from scratch on the scaled integer costs `cost` (scaled_costs):
// decides unboundedness.
MinCostFlowResult network_simplex(const DirectedMcf& mcf, double scale, std::vector<int64_t> cost) {
  SimplexOutcome s = lemon_network_simplex(mcf, mcf.source, mcf.target, cost, mcf.supply);
  if (s.status != MinCostFlowStatus::Optimal) {
    MinCostFlowResult result;
    result.status = s.status;
    result.cost_scale = scale;
    return result;
  }
  return optimal_result(mcf, scale, std::move(cost), std::move(s.flow), std::move(s.potential));
}

// LEMON's network simplex given potentials `start` as far as it can take them: it always
// begins from its own artificial basis, so it is run on the costs reduced by `start`, with
// every finite arc they price negative turned around (its flow x becomes capacity − x on the
// reversed arc, the capacity moving from the supply of its source to that of its target).
// What is left to do is routing the imbalance the start leaves, which pays on large networks
// only (kStartedSimplexMinNodes in min_cost_flow.hpp has the figures). Falls back to the cold
// simplex when the reduced costs would leave LEMON's overflow bound (integer_cost_scale with
// 2^60), when the potentials found spread wider than a cold solve's can (2^limit_log2, which
// the caller's use of them assumes), whenever the reduced problem is not optimal, so that
// infeasibility and unboundedness are decided on the original problem, and if the result
// fails its optimality check.
MinCostFlowResult network_simplex_from(const DirectedMcf& mcf, double scale, int limit_log2,
                                       const std::vector<int64_t>& cost,
                                       const std::vector<int64_t>& start) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  // LEMON's own arithmetic needs the bound of integer_cost_scale with 2^60; the caller's
  // consumers of the potentials (refinement's matching) need them no wider than 2^limit_log2.
  const double cost_bound = 0x1p60, spread_bound = std::ldexp(1.0, limit_log2);
  auto cold = [&] { return network_simplex(mcf, scale, cost); };
  std::vector<int> source = mcf.source, target = mcf.target;
  std::vector<int64_t> supply = mcf.supply, reduced_cost(m);
  std::vector<char> turned(m, 0);
  for (int a = 0; a < m; ++a) {
    const int u = mcf.source[a], v = mcf.target[a];
    // start in [−2^62, 0] (centred on its largest) and |cost| ≤ 2^60: no overflow.
    int64_t r = cost[a] + start[u] - start[v];
    if (r < 0 && mcf.capacity[a] != std::numeric_limits<int64_t>::max()) {
      turned[a] = 1;
      std::swap(source[a], target[a]);
      supply[u] -= mcf.capacity[a];
      supply[v] += mcf.capacity[a];
      r = -r;
    }
    if (static_cast<double>(std::abs(r)) * (n + 1) > cost_bound) return cold();
    reduced_cost[a] = r;
  }
  SimplexOutcome s = lemon_network_simplex(mcf, source, target, reduced_cost, supply);
  if (s.status != MinCostFlowStatus::Optimal) return cold();
  std::vector<int64_t> potential(n);
  for (int v = 0; v < n; ++v) potential[v] = s.potential[v] + start[v];
  const auto [low_at, high_at] = std::minmax_element(potential.begin(), potential.end());
  const int64_t low = *low_at, high = *high_at;
  if (static_cast<double>(high) - static_cast<double>(low) > spread_bound) return cold();
  for (int64_t& p : potential) p -= high;
  for (int a = 0; a < m; ++a)
    if (turned[a]) s.flow[a] = mcf.capacity[a] - s.flow[a];
  MinCostFlowResult result =
      optimal_result(mcf, scale, cost, std::move(s.flow), std::move(potential));
  // The translation back is ours, not LEMON's: checked like the shortest paths' result.
  if (!certifies_optimality(mcf, result)) return cold();
  return result;
}

}  // namespace

MinCostFlowResult solve_min_cost_flow(const DirectedMcf& mcf, int limit_log2,
                                      const std::vector<double>& start_potential,
                                      int started_simplex_min_nodes) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  MinCostFlowResult result;
  if (n == 0) {  // LEMON reports an empty network as infeasible
    result.status = MinCostFlowStatus::Optimal;
    return result;
  }
  const double scale = integer_cost_scale(mcf.cost, n, std::min(limit_log2, 60));
  std::vector<int64_t> cost = scaled_costs(mcf, scale);
  if (static_cast<int>(start_potential.size()) != n)
    return network_simplex(mcf, scale, std::move(cost));
  // Started, but the network simplex answers: the start was too far off, or the solver could
  // not decide (see shortest_path_flow.hpp).
  std::vector<int64_t> start(n);
  auto abandoned = [&] {
    MinCostFlowResult fallback =
        n >= started_simplex_min_nodes
            ? network_simplex_from(mcf, scale, std::min(limit_log2, 60), cost, start)
            : network_simplex(mcf, scale, cost);
    fallback.method = MinCostFlowMethod::WarmStartAbandoned;
    return fallback;
  };
  // Potentials matter only up to a common shift: centred on their largest, so that a chain of
  // solves, whose potentials only ever decrease, never drifts out of the solver's bounds.
  const double top = *std::max_element(start_potential.begin(), start_potential.end());
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
  result = optimal_result(mcf, scale, std::move(cost), solver.flow(), solver.potential());
  result.method = MinCostFlowMethod::WarmStart;
  return result;
}

}  // namespace bimdf::detail
