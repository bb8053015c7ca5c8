#include "solve/special_structure.hpp"

#include <algorithm>
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

// Node signs s(v) = ±1 under which every two-ended edge has one end with s·σ = +1 and one with
// −1, or nullopt when there are none (an odd cycle of the sign graph, or a loop). Outer edges
// constrain nothing: their one end may be either.
std::optional<std::vector<int>> orientation(const Problem& p) {
  std::vector<std::vector<int>> edges_at(p.num_nodes());
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.end_b[e].node == kNoNode) continue;
    if (p.end_a[e].node == p.end_b[e].node) return std::nullopt;
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

// A curved cost is modelled exactly on a window of flow values around its minimizer, by one
// unit arc per value, and below and above the window by one arc each whose per-unit cost is
// the cost's step at the window's edge — by convexity never above the cost there. A window
// starts kHalfWindow values to either side, grows where the optimum lands outside it, and
// stops growing at kMaxWindow values (then the general path takes over).
constexpr int64_t kHalfWindow = 4;
constexpr int64_t kMaxWindow = 4096;
constexpr int kMaxWidenings = 16;

struct Window {
  int64_t from = 0, to = 0;  // flow values where the arcs give the cost exactly
};

// The directed network of `p` under the node signs `sign`, with each curved edge's cost
// modelled on its window (linear edges: one arc over the whole bound range, `windows` unused).
// Arcs of edge e are listed in arcs_of[e], as (arc, +1) where their flow adds to the edge's
// and (arc, −1) where it subtracts.
DirectedMcf directed_network(const Problem& p, const std::vector<int>& sign,
                             const std::vector<std::optional<double>>& slope,
                             const std::vector<Window>& windows,
                             std::vector<std::vector<std::pair<int, int>>>& arcs_of) {
  // x = base + (forward arcs' flow) − (backward arc's flow); node v's row times s(v) reads
  // inflow − outflow = s(v)·b(v), and LEMON's supply is its negation. Outer edges join an
  // extra node, the outside, whose supply balances the others'.
  DirectedMcf mcf;
  const int outside = p.num_nodes();
  mcf.supply.resize(p.num_nodes() + 1);
  for (int v = 0; v < p.num_nodes(); ++v) mcf.supply[v] = -sign[v] * p.demand[v];
  arcs_of.assign(p.num_edges(), {});
  bool any_outer = false;
  for (int e = 0; e < p.num_edges(); ++e) {
    const End& a = p.end_a[e];
    const End& b = p.end_b[e];
    const bool a_is_tail = sign[a.node] * a.sign() < 0;
    const int other = b.node == kNoNode ? outside : b.node;
    any_outer = any_outer || b.node == kNoNode;
    const int source = a_is_tail ? a.node : other, target = a_is_tail ? other : a.node;
    const auto arc = [&](bool forward, int64_t capacity, double cost) {
      arcs_of[e].push_back({mcf.num_arcs(), forward ? 1 : -1});
      mcf.source.push_back(forward ? source : target);
      mcf.target.push_back(forward ? target : source);
      mcf.capacity.push_back(capacity);
      mcf.cost.push_back(cost);
    };
    const Cost& c = p.cost[e];
    const int64_t base = slope[e] ? p.lower[e] : windows[e].from;
    // The base flow leaves the source and enters the target.
    mcf.supply[source] -= base;
    mcf.supply[target] += base;
    if (slope[e]) {
      arc(true, p.upper[e] == kInfinity ? INT64_MAX : p.upper[e] - p.lower[e], *slope[e]);
      continue;
    }
    const Window& w = windows[e];
    for (int64_t x = w.from; x < w.to; ++x) arc(true, 1, c(x + 1) - c(x));
    if (w.to < p.upper[e])
      arc(true, p.upper[e] == kInfinity ? INT64_MAX : p.upper[e] - w.to, c(w.to + 1) - c(w.to));
    if (w.from > p.lower[e])
      arc(false, p.lower[e] == -kInfinity ? INT64_MAX : w.from - p.lower[e],
          c(w.from - 1) - c(w.from));
  }
  if (any_outer) {
    mcf.supply[outside] = 0;
    for (int v = 0; v < p.num_nodes(); ++v) mcf.supply[outside] -= mcf.supply[v];
  }
  return mcf;
}

std::optional<std::vector<int64_t>> solve_as_directed_flow(const Problem& p) {
  const std::optional<std::vector<int>> sign = orientation(p);
  if (!sign) return std::nullopt;
  std::vector<std::optional<double>> slope(p.num_edges());
  std::vector<Window> windows(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    slope[e] = linear_slope(p.cost[e]);
    if (slope[e] && p.lower[e] == -kInfinity) return std::nullopt;
    if (slope[e]) continue;
    const int64_t centre = p.cost[e].argmin(p.lower[e], p.upper[e]);
    windows[e] = {std::max(p.lower[e], centre - kHalfWindow),
                  std::min(p.upper[e], centre + kHalfWindow)};
  }
  std::vector<std::vector<std::pair<int, int>>> arcs_of;
  for (int widening = 0; widening < kMaxWidenings; ++widening) {
    const DirectedMcf mcf = directed_network(p, *sign, slope, windows, arcs_of);
    // LEMON reads unbalanced supplies as inequalities; they are infeasible here.
    int64_t total_supply = 0;
    for (int64_t s : mcf.supply) total_supply += s;
    if (total_supply != 0) return std::nullopt;
    const MinCostFlowResult r = solve_min_cost_flow(mcf);
    if (r.status != MinCostFlowStatus::Optimal) return std::nullopt;
    std::vector<int64_t> flow(p.num_edges());
    bool exact = true;
    for (int e = 0; e < p.num_edges(); ++e) {
      flow[e] = slope[e] ? p.lower[e] : windows[e].from;
      for (const auto& [arc, direction] : arcs_of[e]) flow[e] += direction * r.flow[arc];
      if (slope[e]) continue;
      // The arcs' cost is below the true one everywhere and equal on [from − 1, to + 1]: an
      // optimum there for every edge is the problem's optimum.
      Window& w = windows[e];
      if (flow[e] >= w.from - 1 && flow[e] <= w.to + 1) continue;
      exact = false;
      w = {std::max(p.lower[e], std::min(w.from, flow[e] - kHalfWindow)),
           std::min(p.upper[e], std::max(w.to, flow[e] + kHalfWindow))};
      if (w.to - w.from > kMaxWindow) return std::nullopt;
    }
    if (exact) return flow;
  }
  return std::nullopt;
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
