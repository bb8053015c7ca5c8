// Verifying a flow against a problem: integrality is given by the int64 type, so what remains is
// bounds, conservation at every node, and the objective. The check uses 128-bit sums, so it is
// exact for every input and cannot overflow. Every solver result passes through it before it is
// returned (DESIGN §5).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf {

struct BoundViolation {
  int edge;
  int64_t flow;
};

struct ConservationViolation {
  int node;
  __int128 net_flow;  // Σ σ·x over the node's ends
  int64_t demand;
};

struct FlowCheck {
  bool size_ok = true;  // flow has exactly one value per edge
  std::vector<BoundViolation> bound_violations;
  std::vector<ConservationViolation> conservation_violations;
  double objective = 0;  // Σ cost[e](x[e]); +inf if a cost is undefined at its flow

  bool feasible() const {
    return size_ok && bound_violations.empty() && conservation_violations.empty();
  }
};

// Checks `flow` (one value per edge, in edge order). The objective is computed only when the
// size matches; bound and conservation violations are listed in id order.
FlowCheck check_flow(const Problem& problem, std::span<const int64_t> flow);

// Σ cost[e](flow[e]) in edge order. Requires flow.size() == problem.num_edges().
double objective(const Problem& problem, std::span<const int64_t> flow);

}  // namespace bimdf
