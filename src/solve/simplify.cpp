#include "solve/simplify.hpp"

namespace bimdf::detail {

SimplifiedComponent::SimplifiedComponent(const Problem& component, bool collapse)
    : fixed_(eliminate_fixed_edges(component)), outer_(eliminate_outer_edges(fixed_.reduced)) {
  if (!collapse) return;
  chains_ = collapse_chains(outer_.reduced);
  if (chains_->empty_chain_edge >= 0)
    empty_chain_edge_ = fixed_.original_edge[chains_->empty_chain_edge];
}

std::vector<int64_t> SimplifiedComponent::lift(std::vector<int64_t> flow) const {
  if (chains_) flow = chains_->lift(flow);
  return fixed_.lift(outer_.lift(flow));
}

int SimplifiedComponent::component_node(int v) const {
  if (chains_) {
    const auto& map = chains_->reduced_node;
    for (int w = 0; w < static_cast<int>(map.size()); ++w)
      if (map[w] == v) {
        v = w;
        break;
      }
  }
  return v == outer_.boundary_node ? -1 : v;
}

}  // namespace bimdf::detail
