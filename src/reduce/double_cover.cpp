#include "reduce/double_cover.hpp"

#include <stdexcept>
#include <string>

namespace bimdf::detail {

DoubleCover build_double_cover(const BiMcf& in, DoubleCoverKind kind) {
  DoubleCover dc;
  dc.kind = kind;
  const bool halved = kind != DoubleCoverKind::Relaxation;
  const int n = in.num_nodes();
  auto plus = [](int v) { return 2 * v; };
  auto minus = [](int v) { return 2 * v + 1; };
  dc.mcf.supply.resize(2 * n);
  for (int v = 0; v < n; ++v) {
    int64_t b = in.demand[v];
    if (halved) {
      if (b & 1)
        throw std::invalid_argument("double cover: odd demand " + std::to_string(b) +
                                    " at node " + std::to_string(v));
      b /= 2;
    }
    dc.mcf.supply[plus(v)] = -b;
    dc.mcf.supply[minus(v)] = b;
  }
  auto add = [&](int from, int to, int64_t cap, double cost, int arc) {
    dc.mcf.source.push_back(from);
    dc.mcf.target.push_back(to);
    dc.mcf.capacity.push_back(cap);
    dc.mcf.cost.push_back(cost);
    dc.arc_of.push_back(arc);
  };
  for (int i = 0; i < in.num_arcs(); ++i) {
    const End a = in.end_a[i], b = in.end_b[i];
    const int64_t c = in.capacity[i];
    const int a0_from = a.head ? minus(a.node) : plus(a.node);
    const int a0_to = b.head ? plus(b.node) : minus(b.node);
    if (a.node == b.node) {
      // In the relaxation the directed flow is 2y, and a loop's single arc carries all of it.
      add(a0_from, a0_to, halved || c == kInfinity ? c : 2 * c, in.cost[i], i);
      continue;
    }
    int64_t c0 = c, c1 = c;
    if (c != kInfinity) switch (kind) {
        case DoubleCoverKind::Asymmetric: c0 = c / 2, c1 = c - c / 2; break;
        case DoubleCoverKind::AsymmetricSwapped: c0 = c - c / 2, c1 = c / 2; break;
        case DoubleCoverKind::Symmetric: c0 = c1 = c / 2; break;
        case DoubleCoverKind::Relaxation: break;
      }
    add(a0_from, a0_to, c0, in.cost[i], i);
    add(b.head ? minus(b.node) : plus(b.node), a.head ? plus(a.node) : minus(a.node), c1,
        in.cost[i], i);
  }
  return dc;
}

std::vector<int64_t> DoubleCover::lift(std::span<const int64_t> directed_flow,
                                       int num_bimcf_arcs) const {
  std::vector<int64_t> y(num_bimcf_arcs, 0);
  for (size_t k = 0; k < directed_flow.size(); ++k) y[arc_of[k]] += directed_flow[k];
  return y;
}

}  // namespace bimdf::detail
