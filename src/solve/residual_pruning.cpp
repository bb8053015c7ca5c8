#include "solve/residual_pruning.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "backend/min_cost_flow.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/double_cover.hpp"

namespace bimdf::detail {

int lp_scale_log2(const BiMcf& residual, std::span<const int> min_throughflow) {
  // 2^(L+1)·(matching nodes)/(LP nodes + 1) ≤ 2^57 leaves the bound's other half for rounding.
  double capacity = 0;
  for (int64_t c : residual.capacity) capacity += static_cast<double>(c);
  const double lp_nodes = 2.0 * residual.num_nodes() + 1;
  // Pruning only removes arcs, so the reduced residual's throughflow limits are at most these.
  double copies = 0;
  const Throughflow tf = refinement_throughflow(residual, min_throughflow);
  for (int v = 0; v < residual.num_nodes(); ++v)
    copies += static_cast<double>(matching_copies_bound(tf.limit[v], tf.part_degree[v]));
  const double matching_nodes = copies + 2 * capacity + 1;
  const int needed =
      static_cast<int>(std::ceil(std::log2(std::max(1.0, matching_nodes / lp_nodes))));
  return std::min(52, 56 - needed);
}

namespace {

// The relaxation double cover of `residual`, its optimum and the optimum's value in scaled
// costs (a 128-bit sum: each scaled cost is below 3·2^60, min_cost_flow.hpp).
struct RelaxationOptimum {
  DoubleCover dc;
  MinCostFlowResult lp;
  __int128 value = 0;
};

RelaxationOptimum relaxation_optimum(const BiMcf& residual,
                                     const std::vector<double>& start_potential, int scale_log2) {
  for (int v = 0; v < residual.num_nodes(); ++v)
    if (residual.demand[v] != 0)
      throw std::invalid_argument("residual pruning needs zero demands (node " + std::to_string(v) +
                                  ")");
  DoubleCover dc = build_double_cover(residual, DoubleCoverKind::Relaxation);
  MinCostFlowResult lp = solve_min_cost_flow(dc.mcf, scale_log2, start_potential);
  if (lp.status != MinCostFlowStatus::Optimal)
    throw std::logic_error(
        "residual pruning: the LP relaxation of a circulation problem with "
        "finite capacities is not optimal");
  __int128 value = 0;
  for (int k = 0; k < dc.mcf.num_arcs(); ++k)
    value += static_cast<__int128>(lp.scaled_cost[k]) * lp.flow[k];
  return {std::move(dc), std::move(lp), value};
}

// d(v) = π(v⁻) − π(v⁺) (double cover nodes v⁺ = 2v, v⁻ = 2v + 1: double_cover.cpp).
int64_t node_dual(const MinCostFlowResult& lp, int v) {
  return lp.potential[2 * v + 1] - lp.potential[2 * v];
}

// The LP's integer circulation when its doubled flow is even everywhere, else empty.
std::vector<int64_t> integral_part(std::span<const int64_t> twice) {
  std::vector<int64_t> y;
  for (int64_t t : twice)
    if (t % 2 != 0) return y;
  for (int64_t t : twice) y.push_back(t / 2);
  return y;
}

}  // namespace

ResidualLp solve_residual_lp(const BiMcf& residual, const std::vector<double>& start_potential,
                             int scale_log2) {
  const RelaxationOptimum optimum = relaxation_optimum(residual, start_potential, scale_log2);
  const MinCostFlowResult& lp = optimum.lp;
  ResidualLp out;
  out.potential = potentials_in_cost_units(lp);
  out.lp_method = lp.method;
  out.cost_scale = lp.cost_scale;
  out.proves_optimal = optimum.value >= 0;
  out.twice_flow = optimum.dc.lift(lp.flow, residual.num_arcs());
  if (!out.proves_optimal) out.integral_circulation = integral_part(out.twice_flow);
  out.node_dual.resize(residual.num_nodes());
  for (int v = 0; v < residual.num_nodes(); ++v) out.node_dual[v] = node_dual(lp, v);
  return out;
}

ResidualPruning prune_residual(const BiMcf& residual, const std::vector<double>& start_potential,
                               std::span<const int> min_throughflow) {
  ResidualPruning out;
  const int n = residual.num_nodes(), m = residual.num_arcs();
  // Named references, not a structured binding: a lambda below uses `lp`, which C++17 (and
  // clang, which builds the fuzzers) does not allow to capture from a binding.
  const RelaxationOptimum optimum =
      relaxation_optimum(residual, start_potential, lp_scale_log2(residual, min_throughflow));
  const DoubleCover& dc = optimum.dc;
  const MinCostFlowResult& lp = optimum.lp;
  const __int128 lp_value = optimum.value;
  out.potential = potentials_in_cost_units(lp);
  out.lp_method = lp.method;

  // 128-bit sums: each reduced cost is below 3·2^60 (min_cost_flow.hpp).
  __int128 margin = 0;
  std::vector<__int128> bound(m, 0);  // Σ over empty copies of r · (copy flow per unit of y)
  for (int k = 0; k < dc.mcf.num_arcs(); ++k) {
    const int a = dc.arc_of[k];
    const bool loop = residual.end_a[a].node == residual.end_b[a].node;
    if (lp.flow[k] == 0 && lp.reduced_cost[k] > 0)
      bound[a] += static_cast<__int128>(lp.reduced_cost[k]) * (loop ? 2 : 1);
  }
  for (int a = 0; a < m; ++a) {
    if (residual.capacity[a] == kInfinity)
      throw std::invalid_argument("residual pruning needs finite capacities (arc " +
                                  std::to_string(a) + ")");
    margin += residual.capacity[a];
  }
  if (lp_value >= 0) {
    out.proves_optimal = true;
    out.fixed_arcs = m;
    out.reduced.demand.clear();
    return out;
  }

  // The relaxation's directed flow is 2y; an even one is an integer circulation.
  const std::vector<int64_t> twice = dc.lift(lp.flow, m);
  out.integral_circulation = integral_part(twice);

  out.cost_scale = lp.cost_scale;
  std::vector<int> node_of(n, -1);
  auto node = [&](End e) {
    if (node_of[e.node] < 0) {
      node_of[e.node] = out.reduced.num_nodes();
      out.reduced.demand.push_back(0);
      out.node_dual.push_back(node_dual(lp, e.node));
      out.residual_node.push_back(e.node);
    }
    return End{node_of[e.node], e.head};
  };
  for (int a = 0; a < m; ++a) {
    if (lp_value + bound[a] >= margin) {
      ++out.fixed_arcs;
      continue;
    }
    out.reduced.end_a.push_back(node(residual.end_a[a]));
    out.reduced.end_b.push_back(node(residual.end_b[a]));
    out.reduced.capacity.push_back(residual.capacity[a]);
    out.reduced.cost.push_back(residual.cost[a]);
    out.arc_of.push_back(a);
    out.twice_flow.push_back(twice[a]);
  }
  return out;
}

std::vector<int64_t> ResidualPruning::lift(std::span<const int64_t> reduced_flow,
                                           int num_residual_arcs) const {
  std::vector<int64_t> y(num_residual_arcs, 0);
  for (size_t k = 0; k < reduced_flow.size(); ++k) y[arc_of[k]] = reduced_flow[k];
  return y;
}

}  // namespace bimdf::detail
