// Solving Bi-MDF problems (problem.hpp).
//
// ApproximateSolver implements the paper's fast approximation (§3.5–3.6, §3.10): it returns a
// verified feasible integer flow, usually within a few percent of the optimum, or a proof that
// none exists. Per connected component it
//   1. moves fixed edges (lower = upper) into the demands, eliminates outer edges (§3.2.1) and
//      collapses chains of pass-through nodes (§3.10);
//   2. guesses each edge's flow as its cost's integer minimizer within bounds, then moves the
//      guess to the rounded optimum of the LP relaxation (which already balances the network);
//   3. repairs the guess's parity so that the residual demand b − σ·g is even (§3.6.2);
//   4. linearizes the costs around the guess with capacity-2 pieces up to `max_deviation` and
//      tail pieces that keep the whole feasible region (§3.5, §3.6.3);
//   5. solves the (asymmetric) double cover as a directed min-cost flow with LEMON's network
//      simplex and lifts the result back to an integer flow (§3.6).
// The double cover is a restriction of the integer problem, so it can be infeasible although
// the problem is not (../shared/reference/libsatsuma.md §0). The solver then falls back — the
// other split of odd capacities, round-to-even parity, the symmetric cover — and if all of
// them fail it solves the LP relaxation: when that is infeasible, so is the problem. Every
// "infeasible" answer comes with its proof: an odd total demand over a set of nodes that only
// even amounts can change, a chain whose bounds do not intersect, or an infeasible relaxation.
// The rare case where the relaxation is feasible but no cover is (an integer-infeasible problem
// or a hard feasible one) needs the exact solver and is reported as an error, never as
// "infeasible".
//
// Both solvers work in LEMON's style: construct on a validated problem (the solver keeps a
// reference), set options, run(), then query.
//
//   bimdf::ApproximateSolver solver(problem);
//   solver.max_deviation(5);
//   if (solver.run() == bimdf::SolveStatus::Feasible) use(solver.solution().flow);
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"

namespace bimdf {

// How the guess is made parity-even (paper §3.6.2).
enum class ParityRepairMode {
  SpanningTreeTJoin,  // the paper's minimum-spanning-forest T-join (default)
  RoundToEven,        // every movable guess to its cheaper even neighbour, then the T-join
};

// Which double cover the approximation starts with (paper §3.6.2); the others are fallbacks.
enum class DoubleCoverMode {
  Asymmetric,  // odd capacities split ⌊c/2⌋ + ⌈c/2⌉ between the two copies (default)
  Symmetric,   // odd capacities rounded down to even, half on each copy
};

// Which maximum-weight perfect matching solver the exact refinement uses.
enum class MatchingBackend {
  Blossom,  // bimdf's own, warm-started from each round's LP relaxation (default)
  Lemon,    // LEMON's MaxWeightedPerfectMatching from scratch: slower, kept as a cross-check
  // Experimental: one blossom matching kept across all rounds and re-optimized where the last
  // round changed the flow, no LP after the first round (solve/persistent_rounds.hpp). Exact,
  // but slower than Blossom on every instance measured so far (docs/benchmarks.md).
  Persistent,
};

// One progress report of Solver::run() (see Solver::progress).
struct SolveProgress {
  enum class Event {
    Approximated,     // a component's approximation is done: a feasible flow to refine
    RefinementRound,  // one refinement round of a component is done
  };
  Event event = Event::Approximated;
  // The component reported on: 0 .. components − 1 in the order they are solved, largest
  // first (a connected problem has one component, 0).
  int component = 0;
  int components = 1;
  // Refinement rounds this component has done so far (0 for Approximated).
  int64_t round = 0;
  // The component's objective after the event: the cost of its edges' current flow, as it
  // would count in Solution::objective.
  double objective = 0;
  // RefinementRound: whether the round lowered the objective. A round that does not ends the
  // component's refinement: its flow is then proven optimal (paper Thm 3.8). A component that
  // its dedicated algorithm solves outright (a directed min-cost flow or a perfect matching,
  // see Solver) reports its optimum as Approximated, then one such round.
  bool improved = false;
  double elapsed_s = 0;  // wall-clock seconds since run() started
};

// Thrown by run() when a stage fails in a way that is neither a solution nor a proof of
// infeasibility (see the header comment). The message names the component and what failed.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The exact solver (paper §3.7–3.9): the approximation above, then iterative refinement — each
// round a minimum-cost circulation of throughflow at most 2 around the current flow (more at
// nodes with many arcs, which only widens the search), found as a maximum-weight perfect
// matching (our blossom solver) on the arcs that the round's LP relaxation cannot exclude — until a
// round no longer lowers the objective, which proves optimality (paper Thm 3.8). Two kinds of
// component skip both and go to the algorithm they deserve (the statistic "approximation_path",
// shown by `bimdf solve -v`, names them): one whose nodes can be signed so that every edge has a
// head and a tail after negating the negative nodes' rows (a 2-colourable sign graph, no loops;
// outer edges are arcs to and from the outside) is a directed min-cost flow — network simplex, on
// windows of unit arcs around curved costs' minima; one whose edges all join two nodes with two
// heads (or all with two tails), bounds [0, 1], every demand 1 (or −1), is a perfect matching —
// LEMON's blossom algorithm (src/solve/special_structure.hpp). Components are solved independently,
// on `threads` workers; the flow does not depend on the thread count. When a limit stops refinement
// first, a lower bound from the LP relaxation of the whole problem says how far from optimal the
// flow can be.
//
//   bimdf::Solver solver(problem);
//   solver.threads(2).time_limit(10.0);
//   if (solver.run() == bimdf::SolveStatus::Optimal) use(solver.solution().flow);
class Solver {
 public:
  // `problem` must pass validate() and outlive the solver.
  explicit Solver(const Problem& problem);

  // Options of the approximation that starts the refinement (see ApproximateSolver).
  Solver& max_deviation(int u);
  Solver& parity_repair(ParityRepairMode mode);
  Solver& double_cover(DoubleCoverMode mode);
  Solver& collapse_chains(bool enable);
  // Run the approximation on the problem before chains are collapsed, and project its flow
  // onto the chains: that double cover approximates a little better (median gap on the shared
  // instances 3.0% instead of 3.7%) but its LP guess costs about 1.7× as much. Default false.
  Solver& approximate_unchained(bool enable);
  // Refinement rounds per component before giving up on proving optimality (status Feasible
  // with the best flow so far). Default: unlimited (refinement always terminates).
  Solver& max_rounds(int64_t rounds);
  // Wall-clock seconds for the whole solve; when exceeded, refinement stops and the best flows
  // are returned with status Feasible. Default: unlimited.
  Solver& time_limit(double seconds);
  // Worker threads for independent components (≥ 1). Default 1.
  Solver& threads(int count);
  // Report a lower bound ("lower_bound", "relative_gap"): the optimum itself for components
  // proven optimal, the LP relaxation's bound for the others. Default true.
  Solver& lower_bound(bool enable);
  // The perfect matching solver of the refinement rounds. Default MatchingBackend::Blossom.
  Solver& matching(MatchingBackend backend);
  // Called after each component's approximation and after each of its refinement rounds —
  // large problems take minutes (a 10^6-edge one ~40 rounds), so that a program can show how
  // far the solve is. Components proven infeasible report nothing. Calls never overlap; with
  // threads > 1 they may come from worker threads, and the calling worker waits until the
  // callback returns (time that counts against time_limit). An exception thrown by the
  // callback cancels the solve: no further call is made, the components being solved stop at
  // their next report, and run() throws that exception — a program can stop a long solve so.
  // Default: none.
  Solver& progress(std::function<void(const SolveProgress&)> callback);

  // Returns Optimal, Feasible (a limit was hit) or Infeasible. Throws like ApproximateSolver.
  SolveStatus run();

  // After run(): as ApproximateSolver's, plus "approximate_objective", "refinement_rounds",
  // "refinement_rounds_max", "matchings_solved", "time_refine_build_s", "time_pruning_s",
  // "time_matching_s", "lower_bound", "relative_gap" and matching sizes.
  const Solution& solution() const { return solution_; }

 private:
  const Problem& problem_;
  int max_deviation_ = 5;
  ParityRepairMode parity_ = ParityRepairMode::SpanningTreeTJoin;
  DoubleCoverMode cover_ = DoubleCoverMode::Asymmetric;
  bool collapse_chains_ = true;
  bool approximate_unchained_ = false;
  int64_t max_rounds_ = -1;
  double time_limit_s_ = -1;
  int threads_ = 1;
  bool lower_bound_ = true;
  MatchingBackend matching_ = MatchingBackend::Blossom;
  std::function<void(const SolveProgress&)> progress_;
  Solution solution_;
};

class ApproximateSolver {
 public:
  // `problem` must pass validate() and outlive the solver.
  explicit ApproximateSolver(const Problem& problem);

  // U, the largest deviation from the guess that the linearized costs model exactly at even
  // sample points (paper §3.6.3). Default 5; must be ≥ 0. Larger U: more arcs, rarely better.
  ApproximateSolver& max_deviation(int u);
  // Default SpanningTreeTJoin.
  ApproximateSolver& parity_repair(ParityRepairMode mode);
  // Default Asymmetric.
  ApproximateSolver& double_cover(DoubleCoverMode mode);
  // Collapse chains of pass-through nodes before solving (§3.10). Default true.
  ApproximateSolver& collapse_chains(bool enable);
  // Run the approximation on the problem before chains are collapsed, and project its flow
  // onto the chains: that double cover approximates a little better (median gap on the shared
  // instances 3.0% instead of 3.7%) but its LP guess costs about 1.7× as much. Default false.
  ApproximateSolver& approximate_unchained(bool enable);

  // Solves; returns Feasible or Infeasible (also available as solution().status). Throws
  // SolverError as described above and std::overflow_error for values beyond 64-bit sums.
  SolveStatus run();

  // After run(): status, objective (recomputed in double; NaN when infeasible), the flow (one
  // value per edge; empty when infeasible) and statistics: "time_*_s" per stage, sizes before
  // and after simplification, "approximation_path" (which parity/cover combination produced
  // each component's flow), "fallbacks", and "infeasible_reason" when infeasible.
  const Solution& solution() const { return solution_; }

 private:
  const Problem& problem_;
  int max_deviation_ = 5;
  ParityRepairMode parity_ = ParityRepairMode::SpanningTreeTJoin;
  DoubleCoverMode cover_ = DoubleCoverMode::Asymmetric;
  bool collapse_chains_ = true;
  bool approximate_unchained_ = false;
  Solution solution_;
};

}  // namespace bimdf
