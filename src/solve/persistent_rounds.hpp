// Refinement rounds that keep one perfect matching from round to round (paper §3.7–3.9; issue
// 25's "matching that persists"). Each round looks for the cheapest circulation of the
// residual around the current flow x — unit pieces up to deviation 2 each way, throughflow
// limits per node — through a perfect matching (bmatching.hpp, matching_gadgets.hpp). Solved
// afresh every round, the blossom algorithm pairs the same far-apart odd cycles again and
// labels most of the graph, although the round before changed x on a few edges only. Here the
// residual has a fixed shape: four unit slots per edge (forward and backward, deviation 1 and
// 2; a slot the bounds rule out is disabled, never removed; equal-cost pieces stay apart), the
// throughflow limits of the first round, and the first round's integer cost scale. Only the
// weights of the slots of the edges the last round changed differ in the next round, so the
// matching, its duals and its blossoms carry over: those slots are updated and their vertices
// reopened (BlossomMatching::update_edge), and the next run grows trees from them alone. The
// first round's matching starts from the residual's LP relaxation, as a classic round does
// (residual_pruning.hpp); later rounds solve no LP. Every run ends with the solver's optimality
// certificate on the whole residual, so a round that finds no improving circulation proves x
// optimal exactly as a classic round does (Theorem 3.8). Experimental (`--matching
// persistent`): measured slower than fresh rounds on every instance so far, because dissolving
// the blossoms that hold a change costs as much dual change as a fresh round and the fixed
// shape is ~2.7× a pruned round's matching (docs/benchmarks.md, "A matching that persists
// across rounds").
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "backend/min_cost_flow.hpp"
#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct PersistentRound {
  bool proves_optimal = false;     // the LP optimum is 0 (first round only): x is optimal
  std::vector<int64_t> next_flow;  // x plus the round's cheapest circulation (else)
  bool resumed = false;            // the matching started from the previous round's
  bool lp_solved = false;          // (first round) and how it was solved:
  MinCostFlowMethod lp_method = MinCostFlowMethod::NetworkSimplex;
  std::vector<double> lp_potential;  // the LP's potentials, when solved
  int64_t free_vertices = 0;         // trees the matching grew
  int64_t matching_nodes = 0, matching_edges = 0;
  int max_throughflow = 0;
  double time_lp_s = 0, time_build_s = 0, time_matching_s = 0;
};

class PersistentRounds {
 public:
  // Requires a problem without outer edges; keeps a reference to it. `hub_throughflow` as in
  // RefineOptions (refine.hpp): false gives every node K = 2.
  PersistentRounds(const Problem& problem, bool hub_throughflow);
  ~PersistentRounds();
  PersistentRounds(const PersistentRounds&) = delete;
  PersistentRounds& operator=(const PersistentRounds&) = delete;

  // One round around the feasible flow `flow`. The first call solves the LP (warm-started from
  // `start_potential`, per double-cover node; may be empty) and builds the matching; later
  // calls update the slots of the edges where `flow` differs from the previous call's and
  // resume. Throws std::invalid_argument when a weight leaves the blossom solver's overflow
  // bound, std::length_error for a matching beyond int indices, std::logic_error on a broken
  // invariant (a bug): the caller then solves the round the classic way.
  PersistentRound round(std::span<const int64_t> flow, const std::vector<double>& start_potential);

 private:
  struct State;
  const Problem& problem_;
  bool hub_throughflow_;
  std::unique_ptr<State> state_;
};

}  // namespace bimdf::detail
