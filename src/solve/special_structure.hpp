// Components that a dedicated algorithm solves outright (issue 25): written as Bi-MDF, some
// problems need neither the double cover nor refinement.
//   * Orientable: the nodes can be signed s(v) = ±1 so that every edge has one end with
//     s·σ = +1 and one with s·σ = −1 (the sign graph is 2-colourable; no loops). Multiplying
//     each node's conservation row by s(v) turns every edge into a directed arc (tail where
//     s·σ = −1), so the component is one directed minimum-cost flow, solved by the network
//     simplex: a linear cost is one arc (bounds shifted to [0, upper − lower]; its lower bound
//     must be finite); a curved (convex) one is modelled exactly on a window of flow values
//     around its minimizer by one unit arc per value, and beyond the window by an arc each
//     way whose per-unit cost is the cost's step at the window's edge, which by convexity
//     never exceeds the cost there. Where the optimum puts an edge outside its window ± 1,
//     that window grows and the network is solved again (at most 16 times, windows of at most
//     4,096 values); inside every window the modelled cost is the true one and below it
//     elsewhere, so that optimum is the problem's. A directed min-cost flow written as Bi-MDF
//     is such a component, whichever nodes' rows it writes negated.
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

// The optimal flow of `problem` by the dedicated algorithm of its structure, or nullopt when it
// has none above or that algorithm found no optimum. Outer edges are arcs to and from the
// outside of a directed flow (a perfect matching has none).
std::optional<SpecialStructureSolution> solve_special_structure(const Problem& problem);

}  // namespace bimdf::detail
