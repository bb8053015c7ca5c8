// Splitting a problem into its connected components (paper §3.10, first paragraph). Components
// share no node, so their flows are independent: each can be solved on its own (and in
// parallel), and the flows lift back by placing each part's values at its edges' original ids.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct ComponentSplit {
  // One problem per component, numbered in order of their smallest node id; inside a part,
  // nodes and edges keep their relative order. Names are not copied.
  std::vector<Problem> parts;
  std::vector<int> part_of_edge;   // original edge → its part
  std::vector<int> edge_in_part;   // original edge → its id inside the part
  std::vector<int> part_of_node;   // original node → its part
  std::vector<int> node_in_part;   // original node → its id inside the part

  // The original problem's flow from one flow per part.
  std::vector<int64_t> lift(const std::vector<std::vector<int64_t>>& part_flows) const;
};

ComponentSplit split_components(const Problem& problem);

}  // namespace bimdf::detail
