#include "bimdf/flow.hpp"

namespace bimdf {

double objective(const Problem& problem, std::span<const int64_t> flow) {
  double total = 0.0;
  for (int e = 0; e < problem.num_edges(); ++e) total += problem.cost[e](flow[e]);
  return total;
}

FlowCheck check_flow(const Problem& problem, std::span<const int64_t> flow) {
  FlowCheck check;
  if (flow.size() != static_cast<size_t>(problem.num_edges())) {
    check.size_ok = false;
    return check;
  }
  // |flow| < 2^63 and fewer than 2^31 edges with at most two ends each keep every node sum
  // below 2^95: 128-bit accumulation is exact.
  std::vector<__int128> net(problem.num_nodes(), 0);
  for (int e = 0; e < problem.num_edges(); ++e) {
    const int64_t x = flow[e];
    if (x < problem.lower[e] || x > problem.upper[e]) check.bound_violations.push_back({e, x});
    const End a = problem.end_a[e], b = problem.end_b[e];
    net[a.node] += static_cast<__int128>(a.sign()) * x;
    if (b.node != kNoNode) net[b.node] += static_cast<__int128>(b.sign()) * x;
  }
  for (int v = 0; v < problem.num_nodes(); ++v)
    if (net[v] != problem.demand[v])
      check.conservation_violations.push_back({v, net[v], problem.demand[v]});
  check.objective = objective(problem, flow);
  return check;
}

}  // namespace bimdf
