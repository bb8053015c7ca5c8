// Descriptive statistics of a problem, as `bimdf info` prints them: sizes, edge kinds, bounds,
// cost kinds and connected components, plus the parity argument that proves some components
// infeasible without solving anything.
#pragma once

#include <array>
#include <cstdint>

#include "bimdf/problem.hpp"

namespace bimdf {

struct ProblemSummary {
  int nodes = 0;
  int edges = 0;
  int nodes_with_demand = 0;  // b[v] != 0
  double total_demand = 0;    // Σ b[v] (a double: the exact sum may exceed int64)
  std::array<int, kNumEdgeKinds> edge_kinds{};  // indexed by EdgeKind
  // Top-level cost kind of each edge, and every term of every (nested) sum counted by its kind.
  std::array<int, kNumCostKinds> cost_kinds{};
  std::array<int, kNumCostKinds> cost_terms{};
  int fixed_edges = 0;     // lower == upper
  int finite_upper = 0;    // upper < inf
  int positive_lower = 0;  // lower > 0
  int negative_lower = 0;  // lower < 0 (including -inf)
  int components = 0;
  int largest_component_nodes = 0;
  int largest_component_edges = 0;
  // Components whose conservation equations cannot all hold for parity reasons: without outer
  // edges, every edge contributes an even amount (0 or ±2x) to the component's total, so an odd
  // total demand is infeasible; with head-tail edges only, the total must be 0.
  int parity_infeasible_components = 0;
};

ProblemSummary summarize(const Problem& problem);

}  // namespace bimdf
