// Close singularity pairs cancelled in the parametrization (singularity_pairs.hpp).
#include "layout/singularity_pairs.hpp"

#include <algorithm>
#include <functional>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "mesh/vec3.hpp"

namespace bimdf::layout {
namespace {

double distance(const TriangleMesh& m, int a, int b) {
  return detail::norm(detail::sub(m.vertices[a], m.vertices[b]));
}

// The half-edges of the shortest path from a to b over interior edges and interior vertices
// within `reach` of a, in order from a; empty if there is none.
std::vector<int> shortest_path(const SurfaceTopology& top, int a, int b, double reach) {
  const TriangleMesh& m = top.mesh();
  std::unordered_map<int, double> dist{{a, 0.0}};
  std::unordered_map<int, int> arrived_by;  // vertex → the half-edge it was reached by
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  queue.push({0.0, a});
  while (!queue.empty()) {
    const auto [du, u] = queue.top();
    queue.pop();
    if (du > dist[u]) continue;
    if (u == b) break;
    for (int h : top.outgoing(u)) {
      const int w = top.to(h);
      if (top.opposite(h) < 0 || top.on_border(w) || distance(m, a, w) > reach) continue;
      const double d = du + distance(m, u, w);
      const auto it = dist.find(w);
      if (it != dist.end() && it->second <= d) continue;
      dist[w] = d;
      arrived_by[w] = h;
      queue.push({d, w});
    }
  }
  if (!arrived_by.count(b)) return {};
  std::vector<int> path;
  for (int v = b; v != a; v = top.from(arrived_by.at(v))) path.push_back(arrived_by.at(v));
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

CancelledPairs cancel_close_pairs(const SurfaceTopology& top, const FieldIndices& indices,
                                  const std::vector<bool>& keep, double radius) {
  const TriangleMesh& m = top.mesh();
  CancelledPairs out;
  out.matching_offset.assign(top.num_edges(), 0);
  if (!(radius > 0)) return out;
  std::vector<std::tuple<double, int, int>> candidates;  // distance, +1 vertex, −1 vertex
  const auto& s = indices.singularities;
  for (const FieldSingularity& p : s) {
    if (p.quarter_index != 1 || p.on_border || keep[p.vertex]) continue;
    for (const FieldSingularity& n : s) {
      if (n.quarter_index != -1 || n.on_border || keep[n.vertex]) continue;
      const double d = distance(m, p.vertex, n.vertex);
      if (d <= radius) candidates.push_back({d, p.vertex, n.vertex});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> taken(m.num_vertices(), false);
  for (const auto& [d, plus, minus] : candidates) {
    if (taken[plus] || taken[minus]) continue;
    const std::vector<int> path = shortest_path(top, plus, minus, 2 * radius);
    if (path.empty()) continue;
    // field_indices counts a quarter added to an edge's jump +1 at the head of the edge's
    // first half-edge and −1 at its tail: a quarter along each step (in the step's direction)
    // takes one from `plus` (+1 → 0), passes it on through every vertex between, and gives it
    // to `minus` (−1 → 0).
    for (int h : path) {
      const int e = top.edge(h);
      out.matching_offset[e] += top.edge_half_edge(e) == h ? 1 : -1;
    }
    taken[plus] = taken[minus] = true;
    out.pairs.push_back({plus, minus});
  }
  return out;
}

}  // namespace bimdf::layout
