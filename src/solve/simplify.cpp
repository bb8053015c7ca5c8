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

std::vector<int64_t> SimplifiedComponent::project_unchained(
    const std::vector<int64_t>& flow) const {
  if (!chains_) return flow;
  std::vector<int64_t> projected(chains_->reduced.num_edges(), 0);
  for (size_t e = 0; e < flow.size(); ++e)
    if (chains_->reduced_edge[e] >= 0) projected[chains_->reduced_edge[e]] = flow[e];
  return projected;
}

}  // namespace bimdf::detail
