// The simplification every solve starts with, per connected component: fixed edges into the
// demands (fixed_edges.hpp), outer edges onto a boundary node (outer_edges.hpp) and, optionally,
// chains of pass-through nodes collapsed (chains.hpp). Holds the three reductions so that a
// flow of the simplified problem lifts back to the component in one call.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bimdf/problem.hpp"
#include "reduce/chains.hpp"
#include "reduce/fixed_edges.hpp"
#include "reduce/outer_edges.hpp"

namespace bimdf::detail {

class SimplifiedComponent {
 public:
  SimplifiedComponent(const Problem& component, bool collapse_chains);

  // The problem to solve: no outer edges, no fixed edges, chains collapsed if asked for.
  const Problem& problem() const { return chains_ ? chains_->reduced : outer_.reduced; }
  // An edge (component id) of a chain whose bounds do not intersect, or −1. When ≥ 0 the
  // component is infeasible and problem() must not be solved.
  int empty_chain_edge() const { return empty_chain_edge_; }
  // The problem before chain collapse (fixed and outer edges eliminated), and the projection of
  // its flows onto problem(): every edge of a chain carries the chain's flow. The approximation
  // may run on the unchained problem (ApproximateOptions::unchained), whose double cover
  // approximates a little better, while refinement always runs on the smaller chained one.
  const Problem& unchained_problem() const { return outer_.reduced; }
  std::vector<int64_t> project_unchained(const std::vector<int64_t>& flow) const;
  // Double-cover potentials (v⁺ = 2v, v⁻ = 2v + 1) of the unchained problem's nodes → those of
  // problem()'s nodes, which are the unchained nodes that are not pass-through.
  std::vector<double> project_unchained_potential(const std::vector<double>& potential) const;
  // The component's id of a node of problem() (of unchained_problem() when `unchained`), or −1
  // for the boundary node that carries the outer edges (outer_edges.hpp).
  int component_node(int node, bool unchained = false) const;
  // A flow of problem() → a flow of the component.
  std::vector<int64_t> lift(std::vector<int64_t> flow) const;

 private:
  FixedEdgeElimination fixed_;
  OuterEdgeElimination outer_;
  std::optional<ChainCollapse> chains_;
  int component_nodes_ = 0;
  int empty_chain_edge_ = -1;
};

}  // namespace bimdf::detail
