#include "solve/simplify.hpp"

#include <algorithm>
#include <utility>

namespace bimdf::detail {

SimplifiedComponent::SimplifiedComponent(const Problem& component, bool collapse)
    : fixed_(eliminate_fixed_edges(component)),
      // Only the lift needs fixed_ from here on, not its reduced problem: moved on.
      outer_(eliminate_outer_edges(std::move(fixed_.reduced))),
      component_nodes_(component.num_nodes()) {
  if (!collapse) return;
  chains_ = collapse_chains(outer_.reduced);
  if (chains_->empty_chain_edge >= 0)
    empty_chain_edge_ = fixed_.original_edge[chains_->empty_chain_edge];
}

std::vector<int64_t> SimplifiedComponent::lift(std::vector<int64_t> flow) const {
  if (chains_) flow = chains_->lift(flow);
  return fixed_.lift(outer_.lift(flow));
}

int SimplifiedComponent::component_node(int node, bool unchained) const {
  // Fixed- and outer-edge elimination keep the component's node ids (and add the boundary).
  if (chains_ && !unchained) {
    const auto& of = chains_->reduced_node;
    node = static_cast<int>(std::find(of.begin(), of.end(), node) - of.begin());
  }
  return node < component_nodes_ ? node : -1;
}

std::vector<int64_t> SimplifiedComponent::project_unchained(
    const std::vector<int64_t>& flow) const {
  if (!chains_) return flow;
  std::vector<int64_t> projected(chains_->reduced.num_edges(), 0);
  for (size_t e = 0; e < flow.size(); ++e)
    if (chains_->reduced_edge[e] >= 0) projected[chains_->reduced_edge[e]] = flow[e];
  return projected;
}

std::vector<double> SimplifiedComponent::project_unchained_potential(
    const std::vector<double>& potential) const {
  if (!chains_ || potential.empty()) return potential;
  std::vector<double> projected(2 * static_cast<size_t>(chains_->reduced.num_nodes()), 0.0);
  for (size_t v = 0; v < chains_->reduced_node.size(); ++v) {
    const int w = chains_->reduced_node[v];
    if (w < 0) continue;
    projected[2 * w] = potential[2 * v];
    projected[2 * w + 1] = potential[2 * v + 1];
  }
  return projected;
}

}  // namespace bimdf::detail
