#include "solve/refine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "backend/perfect_matching.hpp"
#include "bimdf/flow.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/linearize.hpp"
#include "reduce/matching_gadgets.hpp"
#include "reduce/residual_pruning.hpp"

namespace bimdf::detail {
namespace {

constexpr int kThroughflow = 2;  // M = U = 2, paper §3.9

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

RefineResult refine(const Problem& p, std::vector<int64_t> flow, const RefineOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RefineResult r;
  r.flow = std::move(flow);
  r.objective = objective(p, r.flow);
  LinearizeOptions unit_pieces;
  unit_pieces.max_deviation = kThroughflow;
  unit_pieces.step = 1;
  unit_pieces.tails = false;
  // Strict improvement beyond rounding noise; otherwise x is optimal (Thm 3.8).
  auto improves = [&](double next_objective) {
    return next_objective < r.objective - 1e-12 * std::max(1.0, std::fabs(r.objective));
  };
  while (true) {
    if (r.rounds >= options.max_rounds || seconds_since(start) > options.time_limit_s) return r;
    auto t = std::chrono::steady_clock::now();
    const Linearization lin = linearize(p, r.flow, unit_pieces);
    r.time_build_s += seconds_since(t);
    t = std::chrono::steady_clock::now();
    const ResidualPruning pruned = prune_residual(lin.mcf);
    r.time_pruning_s += seconds_since(t);
    ++r.rounds;
    if (pruned.proves_optimal) {
      r.converged = true;
      return r;
    }
    if (!pruned.integral_circulation.empty()) {
      std::vector<int64_t> next = lin.lift(pruned.integral_circulation);
      const double next_objective = objective(p, next);
      if (improves(next_objective)) {
        r.flow = std::move(next);
        r.objective = next_objective;
        continue;
      }
    }
    t = std::chrono::steady_clock::now();
    const BMatchingReduction bm = reduce_to_bmatching(pruned.reduced, kThroughflow);
    const MatchingReduction mm = reduce_to_perfect_matching(bm.bmatching);
    r.matching_nodes = std::max<int64_t>(r.matching_nodes, mm.graph.num_nodes);
    r.matching_edges = std::max<int64_t>(r.matching_edges, mm.graph.num_edges());
    r.time_build_s += seconds_since(t);
    t = std::chrono::steady_clock::now();
    const std::optional<std::vector<char>> matched = max_weight_perfect_matching(mm.graph);
    r.time_matching_s += seconds_since(t);
    ++r.matchings;
    if (!matched)
      throw std::logic_error("refinement: the residual matching has no perfect matching");
    t = std::chrono::steady_clock::now();
    const std::vector<int> values = mm.lift(*matched, bm.bmatching.num_edges());
    const std::vector<int64_t> reduced_flow = bm.lift(values, pruned.reduced.num_arcs());
    std::vector<int64_t> next = lin.lift(pruned.lift(reduced_flow, lin.mcf.num_arcs()));
    const double next_objective = objective(p, next);
    r.time_build_s += seconds_since(t);
    if (!improves(next_objective)) {
      r.converged = true;
      return r;
    }
    r.flow = std::move(next);
    r.objective = next_objective;
  }
}

}  // namespace bimdf::detail
