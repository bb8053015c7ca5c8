// ApproximateSolver (bimdf/solve.hpp): splits the problem into connected components, runs the
// approximation pipeline (approximate.hpp) on each, merges the flows and verifies the result.
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include "bimdf/flow.hpp"
#include "bimdf/solve.hpp"
#include "reduce/components.hpp"
#include "solve/approximate.hpp"

namespace bimdf {
namespace {

std::string describe_proof(const detail::InfeasibilityProof& proof,
                           const std::vector<int>& part_edge_to_original,
                           const std::vector<int>& part_node_to_original) {
  using Kind = detail::InfeasibilityProof::Kind;
  switch (proof.kind) {
    case Kind::OddParity: {
      const std::string where =
          proof.node < 0 ? std::string("the set of nodes with outer edges")
                         : "node " + std::to_string(part_node_to_original[proof.node]);
      return "parity: " + where +
             " belongs to a set of nodes whose total demand must be changed by an odd amount, "
             "but every edge that can carry a different flow changes it by an even amount";
    }
    case Kind::EmptyChain:
      return "chain: edge " + std::to_string(part_edge_to_original[proof.edge]) +
             " lies on a chain of nodes with demand 0 that forces equal flow on all its edges, "
             "and the bounds of those edges do not intersect";
    case Kind::Relaxation:
      return "relaxation: the LP relaxation of the component containing node " +
             std::to_string(part_node_to_original[0]) +
             " is infeasible: its demands cannot be met within the bounds even fractionally";
    case Kind::PhaseOne:
      return "phase 1: the component containing node " +
             std::to_string(part_node_to_original[0]) + " has no flow: exact phase-1 refinement could not remove the artificial flow "
             "needed to meet its demands within the bounds";
    case Kind::None:
      break;
  }
  return "unknown";
}

}  // namespace

ApproximateSolver::ApproximateSolver(const Problem& problem) : problem_(problem) {}

ApproximateSolver& ApproximateSolver::max_deviation(int u) {
  if (u < 0) throw std::invalid_argument("max_deviation must be >= 0");
  max_deviation_ = u;
  return *this;
}
ApproximateSolver& ApproximateSolver::parity_repair(ParityRepairMode mode) {
  parity_ = mode;
  return *this;
}
ApproximateSolver& ApproximateSolver::double_cover(DoubleCoverMode mode) {
  cover_ = mode;
  return *this;
}
ApproximateSolver& ApproximateSolver::collapse_chains(bool enable) {
  collapse_chains_ = enable;
  return *this;
}

SolveStatus ApproximateSolver::run() {
  const auto start = std::chrono::steady_clock::now();
  solution_ = Solution{};
  auto& stats = solution_.stats;

  detail::ApproximateOptions opt;
  opt.max_deviation = max_deviation_;
  opt.parity = parity_ == ParityRepairMode::SpanningTreeTJoin
                   ? detail::ParityMode::SpanningTreeTJoin
                   : detail::ParityMode::RoundToEven;
  opt.cover = cover_ == DoubleCoverMode::Asymmetric ? detail::DoubleCoverKind::Asymmetric
                                                    : detail::DoubleCoverKind::Symmetric;
  opt.collapse_chains = collapse_chains_;

  const detail::ComponentSplit split = detail::split_components(problem_);
  const int parts = static_cast<int>(split.parts.size());
  std::vector<std::vector<int>> edge_original(parts), node_original(parts);
  for (int e = 0; e < problem_.num_edges(); ++e)
    edge_original[split.part_of_edge[e]].push_back(e);
  for (int v = 0; v < problem_.num_nodes(); ++v)
    node_original[split.part_of_node[v]].push_back(v);

  std::vector<std::vector<int64_t>> flows(parts);
  std::map<std::string, int> paths;
  int64_t attempts = 0, nodes_solved = 0, edges_solved = 0;
  double t_simplify = 0, t_parity = 0, t_linearize = 0, t_mcf = 0;
  for (int k = 0; k < parts; ++k) {
    detail::ComponentOutcome c;
    try {
      c = detail::approximate_component(split.parts[k], opt);
    } catch (const SolverError& e) {
      throw SolverError("component containing node " + std::to_string(node_original[k][0]) +
                        ": " + e.what());
    }
    attempts += c.attempts;
    nodes_solved += c.nodes_solved;
    edges_solved += c.edges_solved;
    t_simplify += c.time_simplify_s;
    t_parity += c.time_parity_s;
    t_linearize += c.time_linearize_s;
    t_mcf += c.time_mcf_s;
    if (c.status == SolveStatus::Infeasible) {
      solution_.status = SolveStatus::Infeasible;
      solution_.objective = std::numeric_limits<double>::quiet_NaN();
      stats["infeasible_reason"] =
          describe_proof(c.proof, edge_original[k], node_original[k]);
      break;
    }
    ++paths[c.path];
    flows[k] = std::move(c.flow);
  }

  stats["components"] = int64_t{parts};
  stats["nodes_solved"] = nodes_solved;
  stats["edges_solved"] = edges_solved;
  stats["double_covers_solved"] = attempts;
  stats["time_simplify_s"] = t_simplify;
  stats["time_parity_s"] = t_parity;
  stats["time_linearize_s"] = t_linearize;
  stats["time_min_cost_flow_s"] = t_mcf;
  std::string path_text;
  int64_t fallbacks = 0;
  for (const auto& [path, count] : paths) {
    path_text += (path_text.empty() ? "" : ", ") + path + " (" + std::to_string(count) +
                 (count == 1 ? " component)" : " components)");
    const std::string primary =
        detail::parity_mode_name(opt.parity) + "+" + detail::cover_kind_name(opt.cover);
    if (path != primary) fallbacks += count;
  }
  stats["approximation_path"] = path_text;
  stats["fallbacks"] = fallbacks;

  if (solution_.status != SolveStatus::Infeasible) {
    solution_.flow = split.lift(flows);
    const FlowCheck check = check_flow(problem_, solution_.flow);
    if (!check.feasible())
      throw SolverError("internal error: the approximate flow violates " +
                        std::to_string(check.bound_violations.size()) + " bounds and " +
                        std::to_string(check.conservation_violations.size()) +
                        " conservation constraints");
    solution_.status = SolveStatus::Feasible;
    solution_.objective = check.objective;
  }
  stats["time_total_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution_.status;
}

}  // namespace bimdf
