// The approximation pipeline on one simplified component (simplify.hpp): guess, parity repair,
// linearization, double covers with fallbacks, and the exact phase-1 last resort (see
// bimdf/solve.hpp for the guarantees). Internal: component.hpp drives it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "backend/min_cost_flow.hpp"
#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"
#include "reduce/double_cover.hpp"
#include "reduce/parity.hpp"

namespace bimdf::detail {

struct ApproximateOptions {
  int max_deviation = 5;
  ParityMode parity = ParityMode::SpanningTreeTJoin;
  DoubleCoverKind cover = DoubleCoverKind::Asymmetric;
  // Approximate the problem before chain collapse (component.cpp): see bimdf/solve.hpp.
  bool unchained = false;
};

// Why a component has no flow; ids are the component's own.
struct InfeasibilityProof {
  enum class Kind { None, OddParity, EmptyChain, Relaxation, PhaseOne } kind = Kind::None;
  int node = -1;  // OddParity: a node of the odd set (−1: the outer edges' boundary)
  int edge = -1;  // EmptyChain: an edge of the chain
};

struct ApproximateOutcome {
  SolveStatus status = SolveStatus::Infeasible;  // Feasible or Infeasible
  std::vector<int64_t> flow;                     // of the problem given, when Feasible
  InfeasibilityProof proof;                      // ids of the problem given
  std::string path;                              // e.g. "tjoin+asymmetric"
  int attempts = 0;                              // double covers tried
  int64_t mcf_arcs = 0;                          // directed arcs of the last cover solved
  // The last cover's optimal potentials per double-cover node (v⁺ = 2v, v⁻ = 2v + 1), in units
  // of cost: refinement's first LP starts from them. Empty on the last-resort paths.
  std::vector<double> potential;
  MinCostFlowTally min_cost_flows;  // how the LP guess and the covers were solved
  double time_lp_guess_s = 0, time_parity_s = 0, time_linearize_s = 0, time_mcf_s = 0;
};

// `problem` must be simplified (no outer or fixed edges). Throws SolverError (bimdf/solve.hpp)
// only on internal failures.
ApproximateOutcome approximate(const Problem& problem, const ApproximateOptions& options);

std::string parity_mode_name(ParityMode mode);
std::string cover_kind_name(DoubleCoverKind kind);

}  // namespace bimdf::detail
