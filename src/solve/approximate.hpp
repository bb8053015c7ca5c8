// The approximation pipeline for one connected component (see bimdf/solve.hpp for the steps and
// guarantees). Internal: the public ApproximateSolver splits components, runs this on each and
// merges the results.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"
#include "reduce/double_cover.hpp"
#include "reduce/parity.hpp"

namespace bimdf::detail {

struct ApproximateOptions {
  int max_deviation = 5;
  ParityMode parity = ParityMode::SpanningTreeTJoin;
  DoubleCoverKind cover = DoubleCoverKind::Asymmetric;
  bool collapse_chains = true;
};

// Why a component has no flow; ids are the component's own.
struct InfeasibilityProof {
  enum class Kind { None, OddParity, EmptyChain, Relaxation, PhaseOne } kind = Kind::None;
  int node = -1;          // OddParity: a node of the odd set (−1: the outer edges' boundary)
  int edge = -1;          // EmptyChain: an edge of the chain
};

struct ComponentOutcome {
  SolveStatus status = SolveStatus::Infeasible;  // Feasible or Infeasible
  std::vector<int64_t> flow;                     // the component's edges, when Feasible
  InfeasibilityProof proof;
  std::string path;       // e.g. "tjoin+asymmetric"
  int attempts = 0;       // double covers tried
  int nodes_solved = 0;   // after simplification
  int edges_solved = 0;
  int64_t mcf_arcs = 0;   // directed arcs of the last cover solved
  double time_simplify_s = 0, time_parity_s = 0, time_linearize_s = 0, time_mcf_s = 0;
};

// Throws SolverError (bimdf/solve.hpp) only on internal failures.
ComponentOutcome approximate_component(const Problem& component,
                                       const ApproximateOptions& options);

std::string parity_mode_name(ParityMode mode);
std::string cover_kind_name(DoubleCoverKind kind);

}  // namespace bimdf::detail
