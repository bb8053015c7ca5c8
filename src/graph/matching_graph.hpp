// An undirected graph with edge weights, for maximum-weight perfect matching. Plain arrays and
// free of other bimdf headers: the C++17 backend includes it (DESIGN §6). It lives in src/graph/,
// below both the reductions that build it and the backends that solve it (DESIGN §4).
#pragma once

#include <vector>

namespace bimdf::detail {

struct MatchingGraph {
  int num_nodes = 0;
  std::vector<int> end_a;  // per edge; no loops
  std::vector<int> end_b;
  std::vector<double> weight;

  int num_edges() const { return static_cast<int>(end_a.size()); }
};

}  // namespace bimdf::detail
