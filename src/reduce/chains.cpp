#include "reduce/chains.hpp"

#include <algorithm>

namespace bimdf::detail {
namespace {

// An edge end seen from its node: the edge and which of its two ends it is.
struct Incidence {
  int edge;
  bool is_b;
};

}  // namespace

ChainCollapse collapse_chains(const Problem& p) {
  const int n = p.num_nodes(), m = p.num_edges();
  std::vector<std::vector<Incidence>> at(n);
  for (int e = 0; e < m; ++e) {
    at[p.end_a[e].node].push_back({e, false});
    at[p.end_b[e].node].push_back({e, true});
  }
  auto end_of = [&](Incidence i) { return i.is_b ? p.end_b[i.edge] : p.end_a[i.edge]; };
  auto other = [&](Incidence i) { return Incidence{i.edge, !i.is_b}; };
  std::vector<char> pass(n, 0);
  for (int v = 0; v < n; ++v) {
    const auto& ends = at[v];
    pass[v] = p.demand[v] == 0 && ends.size() == 2 && ends[0].edge != ends[1].edge &&
              end_of(ends[0]).head != end_of(ends[1]).head;
  }

  ChainCollapse c;
  c.reduced.reserve(n, m);  // at most (chains become single edges)
  c.reduced_node.assign(n, -1);
  for (int v = 0; v < n; ++v)
    if (!pass[v]) c.reduced_node[v] = c.reduced.add_node(p.demand[v]);
    else ++c.collapsed_nodes;
  c.reduced_edge.assign(m, -1);
  c.cycle_flow.assign(m, 0);
  std::vector<char> done(m, 0);

  // Follows the chain that leaves through `start` (an end at the first node); returns the end
  // where it stops — at a node that is not pass-through, or back at `start`'s node for a cycle.
  auto walk = [&](Incidence start, std::vector<int>& edges) {
    Incidence cur = start;
    while (true) {
      edges.push_back(cur.edge);
      done[cur.edge] = 1;
      const Incidence arrive = other(cur);
      const int w = end_of(arrive).node;
      if (!pass[w] || w == end_of(start).node) return arrive;
      const auto& ends = at[w];
      cur = (ends[0].edge == arrive.edge) ? ends[1] : ends[0];
    }
  };
  auto chain_cost_and_bounds = [&](const std::vector<int>& edges, int64_t& lo, int64_t& up) {
    lo = -kInfinity;
    up = kInfinity;
    std::vector<Cost> terms;
    for (int e : edges) {
      lo = std::max(lo, p.lower[e]);
      up = std::min(up, p.upper[e]);
      terms.push_back(p.cost[e]);
    }
    return terms.size() == 1 ? terms[0] : Cost::sum(std::move(terms));
  };

  std::vector<int> edges;
  for (int v = 0; v < n; ++v) {
    if (pass[v]) continue;
    for (const Incidence start : at[v]) {
      if (done[start.edge]) continue;
      edges.clear();
      const Incidence stop = walk(start, edges);
      int64_t lo, up;
      Cost cost = chain_cost_and_bounds(edges, lo, up);
      if (lo > up) {
        c.empty_chain_edge = edges.front();
        return c;
      }
      const End a = end_of(start), b = end_of(stop);
      const int id = c.reduced.add_edge(End{c.reduced_node[a.node], a.head},
                                        End{c.reduced_node[b.node], b.head}, lo, up,
                                        std::move(cost));
      for (int e : edges) c.reduced_edge[e] = id;
    }
  }
  // What is left lies on closed cycles of pass-through nodes.
  for (int e = 0; e < m; ++e) {
    if (done[e]) continue;
    edges.clear();
    walk(Incidence{e, false}, edges);
    int64_t lo, up;
    const Cost cost = chain_cost_and_bounds(edges, lo, up);
    if (lo > up) {
      c.empty_chain_edge = edges.front();
      return c;
    }
    const int64_t x = cost.argmin(lo, up);
    for (int f : edges) c.cycle_flow[f] = x;
  }
  return c;
}

std::vector<int64_t> ChainCollapse::lift(std::span<const int64_t> reduced_flow) const {
  std::vector<int64_t> flow = cycle_flow;
  for (size_t e = 0; e < flow.size(); ++e)
    if (reduced_edge[e] >= 0) flow[e] = reduced_flow[reduced_edge[e]];
  return flow;
}

}  // namespace bimdf::detail
