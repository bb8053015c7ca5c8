#include "solve/special_structure.hpp"

#include <cstdint>
#include <queue>

#include "backend/min_cost_flow.hpp"
#include "backend/perfect_matching.hpp"
#include "bimdf/flow.hpp"

namespace bimdf::detail {
namespace {

// The slope of a cost that is linear everywhere (zero, linear, or a sum of such), or nullopt.
std::optional<double> linear_slope(const Cost& cost) {
  switch (cost.kind()) {
    case CostKind::Zero:
      return 0.0;
    case CostKind::Linear:
      return cost.slope();
    case CostKind::Sum: {
      double slope = 0;
      for (const Cost& term : cost.terms()) {
        const std::optional<double> s = linear_slope(term);
        if (!s) return std::nullopt;
        slope += *s;
      }
      return slope;
    }
    default:
      return std::nullopt;
  }
}

// Node signs s(v) = ±1 under which every edge has one end with s·σ = +1 and one with −1, or
// nullopt when there are none (an odd cycle of the sign graph, a loop or an outer edge).
std::optional<std::vector<int>> orientation(const Problem& p) {
  std::vector<std::vector<int>> edges_at(p.num_nodes());
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.end_b[e].node == kNoNode || p.end_a[e].node == p.end_b[e].node) return std::nullopt;
    edges_at[p.end_a[e].node].push_back(e);
    edges_at[p.end_b[e].node].push_back(e);
  }
  std::vector<int> sign(p.num_nodes(), 0);
  std::queue<int> queue;
  for (int root = 0; root < p.num_nodes(); ++root) {
    if (sign[root] != 0) continue;
    sign[root] = 1;
    queue.push(root);
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop();
      for (int e : edges_at[v]) {
        const End& here = p.end_a[e].node == v ? p.end_a[e] : p.end_b[e];
        const End& there = p.end_a[e].node == v ? p.end_b[e] : p.end_a[e];
        // s(there)·σ(there) = −s(v)·σ(here).
        const int wanted = -sign[v] * here.sign() * there.sign();
        if (sign[there.node] == 0) {
          sign[there.node] = wanted;
          queue.push(there.node);
        } else if (sign[there.node] != wanted) {
          return std::nullopt;
        }
      }
    }
  }
  return sign;
}

std::optional<std::vector<int64_t>> solve_as_directed_flow(const Problem& p) {
  std::vector<double> slope(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    const std::optional<double> s = linear_slope(p.cost[e]);
    if (!s || p.lower[e] == -kInfinity) return std::nullopt;
    slope[e] = *s;
  }
  const std::optional<std::vector<int>> sign = orientation(p);
  if (!sign) return std::nullopt;
  // x = lower + y with 0 ≤ y ≤ upper − lower; node v's row times s(v) reads
  // inflow(y) − outflow(y) = s(v)·b(v) − Σ s(v)·σ·lower, and LEMON's supply is its negation.
  DirectedMcf mcf;
  mcf.supply.resize(p.num_nodes());
  for (int v = 0; v < p.num_nodes(); ++v) mcf.supply[v] = -(*sign)[v] * p.demand[v];
  for (int e = 0; e < p.num_edges(); ++e) {
    const End& a = p.end_a[e];
    const End& b = p.end_b[e];
    const bool a_is_tail = (*sign)[a.node] * a.sign() < 0;
    mcf.source.push_back(a_is_tail ? a.node : b.node);
    mcf.target.push_back(a_is_tail ? b.node : a.node);
    mcf.capacity.push_back(p.upper[e] == kInfinity ? INT64_MAX : p.upper[e] - p.lower[e]);
    mcf.cost.push_back(slope[e]);
    // The lower bound's flow leaves the source and enters the target.
    mcf.supply[mcf.source.back()] -= p.lower[e];
    mcf.supply[mcf.target.back()] += p.lower[e];
  }
  // LEMON reads unbalanced supplies as inequalities; they are infeasible here.
  int64_t total_supply = 0;
  for (int64_t s : mcf.supply) total_supply += s;
  if (total_supply != 0) return std::nullopt;
  const MinCostFlowResult r = solve_min_cost_flow(mcf);
  if (r.status != MinCostFlowStatus::Optimal) return std::nullopt;
  std::vector<int64_t> flow(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) flow[e] = p.lower[e] + r.flow[e];
  return flow;
}

std::optional<std::vector<int64_t>> solve_as_perfect_matching(const Problem& p) {
  if (p.num_edges() == 0) return std::nullopt;
  const bool heads = p.end_a[0].head;
  for (int v = 0; v < p.num_nodes(); ++v)
    if (p.demand[v] != (heads ? 1 : -1)) return std::nullopt;
  MatchingGraph graph;
  graph.num_nodes = p.num_nodes();
  for (int e = 0; e < p.num_edges(); ++e) {
    const End& a = p.end_a[e];
    const End& b = p.end_b[e];
    if (b.node == kNoNode || a.node == b.node || a.head != heads || b.head != heads ||
        p.lower[e] != 0 || p.upper[e] != 1)
      return std::nullopt;
    graph.end_a.push_back(a.node);
    graph.end_b.push_back(b.node);
    graph.weight.push_back(p.cost[e](0) - p.cost[e](1));
  }
  const std::optional<std::vector<char>> matched = max_weight_perfect_matching(graph);
  if (!matched) return std::nullopt;
  return std::vector<int64_t>(matched->begin(), matched->end());
}

}  // namespace

std::optional<SpecialStructureSolution> solve_special_structure(const Problem& problem) {
  std::optional<SpecialStructureSolution> solved;
  if (auto flow = solve_as_perfect_matching(problem))
    solved = SpecialStructureSolution{"perfect matching", std::move(*flow)};
  else if (auto directed = solve_as_directed_flow(problem))
    solved = SpecialStructureSolution{"directed min-cost flow", std::move(*directed)};
  // The reductions are short, but a flow that breaks a bound or a node's balance must never
  // leave here: the general path then solves the component.
  if (solved && !check_flow(problem, solved->flow).feasible()) return std::nullopt;
  return solved;
}

}  // namespace bimdf::detail
