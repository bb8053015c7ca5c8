#include "reduce/parity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace bimdf::detail {
namespace {

// The cheaper of g−1 and g+1 within bounds, as a direction (±1) and its extra cost; direction
// 0 when the edge cannot move. Ties go towards the cost's anchor, then downwards, so that the
// result is deterministic.
struct Move {
  int direction = 0;
  double cost = std::numeric_limits<double>::infinity();
};

Move cheapest_move(const Problem& p, int e, int64_t g) {
  Move best;
  const double here = p.cost[e](g);
  for (int d : {-1, 1}) {
    const int64_t x = g + d;
    if (x < p.lower[e] || x > p.upper[e]) continue;
    const double c = p.cost[e](x) - here;
    const bool better =
        c < best.cost ||
        (c == best.cost && std::fabs(x - p.cost[e].anchor()) <
                               std::fabs(g + best.direction - p.cost[e].anchor()));
    if (best.direction == 0 || better) best = {d, c};
  }
  return best;
}

bool movable(const Problem& p, int e) {
  return p.end_a[e].node != p.end_b[e].node && p.lower[e] < p.upper[e];
}

void apply(int e, const Move& move, ParityRepair& r) {
  r.guess[e] += move.direction;
  r.adjustment_cost += move.cost;
  ++r.adjusted_edges;
}

}  // namespace

ParityRepair repair_parity(const Problem& p, std::vector<int64_t> guess, ParityMode mode) {
  const int n = p.num_nodes(), m = p.num_edges();
  ParityRepair r;
  r.guess = std::move(guess);

  if (mode == ParityMode::RoundToEven)
    for (int e = 0; e < m; ++e)
      if (movable(p, e) && (r.guess[e] & 1)) apply(e, cheapest_move(p, e, r.guess[e]), r);

  // Residual parity from low bits only: (b − σ·g) mod 2 = (b + g_a + g_b) mod 2 per node.
  std::vector<char> odd(n);
  for (int v = 0; v < n; ++v) odd[v] = p.demand[v] & 1;
  for (int e = 0; e < m; ++e)
    if (p.end_a[e].node != p.end_b[e].node) {
      odd[p.end_a[e].node] ^= r.guess[e] & 1;
      odd[p.end_b[e].node] ^= r.guess[e] & 1;
    }
  if (std::find(odd.begin(), odd.end(), 1) == odd.end()) return r;

  // Kruskal: movable edges by adjustment cost, ties by id (deterministic).
  std::vector<Move> move(m);
  std::vector<int> order;
  for (int e = 0; e < m; ++e)
    if (movable(p, e)) {
      move[e] = cheapest_move(p, e, r.guess[e]);
      order.push_back(e);
    }
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return move[x].cost < move[y].cost; });
  std::vector<int> root(n);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  std::vector<std::vector<int>> tree(n);  // incident forest edges
  for (int e : order) {
    const int a = find(p.end_a[e].node), b = find(p.end_b[e].node);
    if (a == b) continue;
    root[std::max(a, b)] = std::min(a, b);
    tree[p.end_a[e].node].push_back(e);
    tree[p.end_b[e].node].push_back(e);
  }

  // Depth-first order per tree; then leaves first: a node that is still odd takes the edge to
  // its parent, which flips the parent. Only the tree's root can remain odd.
  std::vector<int> parent_edge(n, -1), dfs_order;
  std::vector<char> seen(n, 0);
  std::vector<int> stack;
  for (int s = 0; s < n; ++s) {
    if (seen[s]) continue;
    const size_t first = dfs_order.size();
    stack.push_back(s);
    seen[s] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      dfs_order.push_back(v);
      for (int e : tree[v]) {
        const int w = p.end_a[e].node == v ? p.end_b[e].node : p.end_a[e].node;
        if (seen[w]) continue;
        seen[w] = 1;
        parent_edge[w] = e;
        stack.push_back(w);
      }
    }
    for (size_t i = dfs_order.size(); i-- > first + 1;) {
      const int v = dfs_order[i];
      if (!odd[v]) continue;
      const int e = parent_edge[v];
      const int parent = p.end_a[e].node == v ? p.end_b[e].node : p.end_a[e].node;
      apply(e, move[e], r);
      odd[v] = 0;
      odd[parent] ^= 1;
    }
    if (odd[s] && r.odd_node < 0) r.odd_node = s;
  }
  return r;
}

}  // namespace bimdf::detail
