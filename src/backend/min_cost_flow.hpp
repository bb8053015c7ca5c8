// Minimum-cost flow on a directed network (graph/directed_mcf.hpp): from scratch by LEMON's
// network simplex, or, given the potentials of a similar problem solved before, by our
// shortest-path solver started from them (backend/shortest_path_flow.hpp), which gives way to
// the network simplex when the start is too far off — run then on the costs reduced by the
// start, every arc they price negative saturated, so that it only routes the imbalance the
// start leaves. This header is LEMON-free so that C++20 code can include it (DESIGN §6).
//
// Integer cost scaling — the one place where bimdf turns double costs into the integers a
// combinatorial solver needs (DESIGN §2): every per-unit cost c becomes llround(c·S) with
// S = 2^k the largest power of two (k ≤ 62) for which max|c|·S ≤ 2^60 / (nodes + 1). The
// bound keeps LEMON's node potentials and its artificial big-M costs ((max cost + 1)·nodes)
// below 2^61, so no int64 arithmetic inside the solver can overflow, while the relative
// resolution of the largest cost is as fine as that safety allows. Costs that differ by less
// than 1/S therefore look equal to the solver: results built on this flow must be re-evaluated
// in double (the reported objective always is).
#pragma once

#include <cstdint>
#include <vector>

#include "graph/directed_mcf.hpp"

namespace bimdf::detail {

enum class MinCostFlowStatus { Optimal, Infeasible, Unbounded };

// How a min-cost flow was solved (statistics): from scratch by the network simplex (no start
// given), from the given potentials by shortest paths, or by the network simplex from them
// (too far off for the shortest paths, past their work limit, or undecided by them).
enum class MinCostFlowMethod { NetworkSimplex, WarmStart, WarmStartAbandoned };

// Counts of MinCostFlowMethod over a solve's min-cost flows.
struct MinCostFlowTally {
  int64_t cold = 0, warm = 0, warm_abandoned = 0;
  // `warm` counts every solve given a start, `warm_abandoned` those the network simplex did.
  void add(MinCostFlowMethod method) {
    cold += method == MinCostFlowMethod::NetworkSimplex;
    warm += method != MinCostFlowMethod::NetworkSimplex;
    warm_abandoned += method == MinCostFlowMethod::WarmStartAbandoned;
  }
  void add(const MinCostFlowTally& t) {
    cold += t.cold;
    warm += t.warm;
    warm_abandoned += t.warm_abandoned;
  }
};

struct MinCostFlowResult {
  MinCostFlowStatus status = MinCostFlowStatus::Infeasible;
  std::vector<int64_t> flow;  // per arc, when Optimal
  double cost_scale = 1;      // the S used
  MinCostFlowMethod method = MinCostFlowMethod::NetworkSimplex;
  // The integer problem actually solved, and its optimal dual (when Optimal), per arc:
  // scaled_cost = llround(c·S); reduced_cost = scaled_cost + π(source) − π(target) for the
  // solver's node potentials π. Optimality (complementary slackness): flow 0 where reduced_cost >
  // 0, flow = capacity where reduced_cost < 0. |reduced_cost| < 3·2^60, see the scale above.
  std::vector<int64_t> scaled_cost;
  std::vector<int64_t> reduced_cost;
  std::vector<int64_t> potential;  // π per node, when Optimal
};

// A start the shortest paths cannot take still starts the network simplex on networks of at
// least this many nodes, below which it is started cold. Measured on the same LPs in one
// process (refinement's first LP, started from the cover's potentials): on the shared
// instances, up to 25k nodes, the simplex from the start took 0.85–1.6× the cold one's time
// (bull__flow_0 62 against 73 ms, bull__flow_1 81 against 59 ms, ChineseDragon 29 against
// 24 ms); on generated instances it gains more the larger they are (18k nodes 105 against
// 120 ms, 44k nodes 337 against 553 ms, 440k nodes 36 against 69–78 s; docs/benchmarks.md).
inline constexpr int kStartedSimplexMinNodes = 32768;

// Solves `mcf` exactly (for the scaled integer costs). Deterministic. `limit_log2` < 60 gives
// coarser integer costs (the bound above with 2^limit_log2), for callers that hand the costs
// and potentials on to a solver with less headroom (refinement's perfect matching).
// `start_potential` (per node, in units of cost; empty: none) warm-starts it as described
// above; `started_simplex_min_nodes` is the size from which a start the shortest paths give up
// still starts the network simplex (tests lower it).
MinCostFlowResult solve_min_cost_flow(const DirectedMcf& mcf, int limit_log2 = 60,
                                      const std::vector<double>& start_potential = {},
                                      int started_simplex_min_nodes = kStartedSimplexMinNodes);

// The optimal potentials of `r` in units of cost (π / S): what a later, similar problem may
// start from.
std::vector<double> potentials_in_cost_units(const MinCostFlowResult& r);

// The scale S described above, for the given costs and node count; `limit_log2` is 60 for the
// min-cost flow and smaller for solvers that multiply their duals.
double integer_cost_scale(const std::vector<double>& costs, int num_nodes, int limit_log2 = 60);

}  // namespace bimdf::detail
