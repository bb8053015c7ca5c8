#include "reduce/outer_edges.hpp"

#include <utility>

namespace bimdf::detail {

OuterEdgeElimination eliminate_outer_edges(Problem problem) {
  OuterEdgeElimination r;
  r.reduced = std::move(problem);
  Problem& p = r.reduced;
  r.num_original_edges = p.num_edges();
  bool any_outer = false;
  for (int e = 0; e < p.num_edges() && !any_outer; ++e) any_outer = p.is_outer(e);
  if (!any_outer) return r;

  // Parity of the total demand from the low bits alone: no overflow possible.
  int64_t parity = 0;
  for (int64_t b : p.demand) parity ^= (b & 1);
  r.boundary_node = p.add_node(parity);
  for (int e = 0; e < r.num_original_edges; ++e)
    if (p.is_outer(e)) p.end_b[e] = End{r.boundary_node, /*head=*/true};
  p.add_edge(End{r.boundary_node, false}, End{r.boundary_node, false}, -kInfinity, kInfinity,
             Cost::zero());
  return r;
}

std::vector<int64_t> OuterEdgeElimination::lift(std::span<const int64_t> reduced_flow) const {
  return {reduced_flow.begin(), reduced_flow.begin() + num_original_edges};
}

}  // namespace bimdf::detail
