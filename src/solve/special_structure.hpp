// Components that a dedicated algorithm solves outright (issue 25): written as Bi-MDF, some
// problems need neither the double cover nor refinement.
//   * Orientable with linear costs: the nodes can be signed s(v) = ±1 so that every edge has
//     one end with s·σ = +1 and one with s·σ = −1 (the sign graph is 2-colourable; no loops).
//     Multiplying each node's conservation row by s(v) turns every edge into a directed arc
//     (tail where s·σ = −1), so the component is one directed minimum-cost flow (bounds
//     shifted to [0, upper − lower]), solved by the network simplex. A directed min-cost flow
//     written as Bi-MDF is such a component, whichever nodes' rows it writes negated.
//   * Perfect matching: every edge joins two different nodes with two heads (or every edge
//     with two tails), bounds [0, 1], and every demand is 1 (or −1): a flow is a perfect
//     matching, its cost Σ c(0) plus Σ over matched edges of c(1) − c(0), solved by LEMON's
//     maximum-weight perfect matching on the negated increments.
// Both results are optimal for the integer-scaled costs that the backends solve
// (backend/min_cost_flow.hpp), as refinement's are. Where a dedicated solver finds no solution
// (infeasible, unbounded), the caller takes the general path, which proves it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct SpecialStructureSolution {
  std::string path;           // "directed min-cost flow" or "perfect matching"
  std::vector<int64_t> flow;  // per edge of the problem
};

// The optimal flow of `problem` (no outer edges) by the dedicated algorithm of its structure,
// or nullopt when it has none above or that algorithm found no optimum.
std::optional<SpecialStructureSolution> solve_special_structure(const Problem& problem);

}  // namespace bimdf::detail
