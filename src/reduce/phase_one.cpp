#include "reduce/phase_one.hpp"

#include <stdexcept>

#include "reduce/checked.hpp"

namespace bimdf::detail {

PhaseOne build_phase_one(const Problem& p, std::span<const int64_t> guess) {
  PhaseOne r;
  r.num_original_edges = p.num_edges();
  r.problem.demand = p.demand;
  std::vector<__int128> residual(p.demand.begin(), p.demand.end());
  for (int e = 0; e < p.num_edges(); ++e) {
    r.problem.add_edge(p.end_a[e], p.end_b[e], p.lower[e], p.upper[e], Cost::zero());
    residual[p.end_a[e].node] -= static_cast<__int128>(p.end_a[e].sign()) * guess[e];
    residual[p.end_b[e].node] -= static_cast<__int128>(p.end_b[e].sign()) * guess[e];
  }
  r.start.assign(guess.begin(), guess.end());
  for (int v = 0; v < p.num_nodes(); ++v) {
    const int64_t res = narrow_checked(residual[v], "the residual of node " + std::to_string(v));
    if (res == 0) continue;
    if (res & 1) throw std::invalid_argument("phase one needs even residuals");
    const End end{v, res > 0};
    r.problem.add_edge(end, end, 0, kInfinity, Cost::linear(1.0));
    r.start.push_back((res > 0 ? res : -res) / 2);
  }
  return r;
}

int64_t PhaseOne::artificial_flow(std::span<const int64_t> flow) const {
  int64_t total = 0;
  for (size_t e = num_original_edges; e < flow.size(); ++e) total += flow[e];
  return total;
}

std::vector<int64_t> PhaseOne::lift(std::span<const int64_t> flow) const {
  return {flow.begin(), flow.begin() + num_original_edges};
}

}  // namespace bimdf::detail
