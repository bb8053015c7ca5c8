// Parity repair (paper §3.6.2): adjusting an integer guess g so that the residual demand
// b − σ·g is even at every node, as the double cover requires. Only the parity of the residual
// matters, and it changes at both ends of a non-loop edge whenever that edge's guess moves by
// ±1 (a loop changes its node by ±2). The nodes T with odd residual must therefore be paired
// up by a T-join: a set J of movable edges in which exactly the nodes of T have odd degree.
//
//   SpanningTreeTJoin  the paper's Algorithm 1: a minimum spanning forest under the adjustment
//                      cost min(c(g±1)) − c(g), then the unique T-join inside each tree, found
//                      leaf-first by depth-first order.
//   RoundToEven        first moves every odd guess to the cheaper even neighbour (which needs
//                      no T-join for edges that can move), then repairs what remains (odd
//                      demands) with the spanning-tree T-join.
//
// Movable edges are the non-loop edges with lower < upper; moves stay within bounds. If some
// tree of movable edges has an odd number of T-nodes, no flow exists at all: every flow differs
// from g only on movable edges, each of which changes the residual sum of that tree's nodes by
// an even amount, and edges leaving the tree are fixed. This proof is reported via `odd_node`.
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

enum class ParityMode { SpanningTreeTJoin, RoundToEven };

struct ParityRepair {
  std::vector<int64_t> guess;  // the adjusted guess, within bounds
  int adjusted_edges = 0;      // edges whose guess moved
  double adjustment_cost = 0;  // Σ c(adjusted) − c(initial)
  int odd_node = -1;           // ≥ 0: a node of a tree with odd residual sum (infeasible)
};

// Requires a problem without outer edges and a guess within bounds.
ParityRepair repair_parity(const Problem& problem, std::vector<int64_t> guess, ParityMode mode);

}  // namespace bimdf::detail
