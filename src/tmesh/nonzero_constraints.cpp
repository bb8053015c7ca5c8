// Algorithm 2 (paper §4.2.3): greedy min-one constraints that imply every non-zero path.
//
// The non-zero implication graph G1 has a node per path, arc and side, and an edge v → w when
// a non-zero v forces a non-zero w (v's arcs are a subset of w's, or v and w are opposite sides
// of a patch, whose lengths are equal). A depth-first search from a side then finds every path
// that a min-one bound on that side would satisfy. Nodes a search visits are deleted: either
// their paths are now covered, or nothing reachable from them is an uncovered path — so no
// later search needs them, and the whole pass touches each edge once.
#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "bimdf/tmesh/quantize.hpp"

namespace bimdf::tmesh {
namespace {

// G1 with nodes numbered paths first, then arcs, then sides (4 per patch).
struct ImplicationGraph {
  int paths = 0, arcs = 0;
  std::vector<std::vector<int>> out;
  int arc_node(int a) const { return paths + a; }
  int side_node(int patch, int side) const { return paths + arcs + 4 * patch + side; }
};

bool is_subset(const std::vector<int>& small, const std::vector<int>& large) {
  return std::includes(large.begin(), large.end(), small.begin(), small.end());
}

ImplicationGraph build_implication_graph(const TMesh& tmesh) {
  ImplicationGraph g;
  g.paths = static_cast<int>(tmesh.nonzero_paths.size());
  g.arcs = tmesh.num_arcs();
  g.out.resize(g.paths + g.arcs + 4 * tmesh.num_patches());
  std::vector<std::vector<int>> path_arcs(g.paths);
  std::vector<std::vector<int>> paths_with_arc(g.arcs);
  for (int m = 0; m < g.paths; ++m) {
    path_arcs[m] = arcs_along(tmesh.nonzero_paths[m]);
    for (int a : path_arcs[m]) {
      paths_with_arc[a].push_back(m);
      g.out[g.arc_node(a)].push_back(m);
    }
  }
  // Path ⊂ path: candidates share the smaller path's first arc. Equal arc sets imply each
  // other both ways, which the search handles like any cycle.
  for (int m = 0; m < g.paths; ++m) {
    if (path_arcs[m].empty()) continue;
    for (int w : paths_with_arc[path_arcs[m].front()])
      if (w != m && is_subset(path_arcs[m], path_arcs[w])) g.out[m].push_back(w);
  }
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k = 0; k < 4; ++k) {
      const int s = g.side_node(p, k);
      g.out[s].push_back(g.side_node(p, (k + 2) % 4));
      const std::vector<int> arcs = arcs_along(tmesh.patch_sides[p][k]);
      for (int a : arcs) g.out[g.arc_node(a)].push_back(s);
      for (int w : paths_with_arc[arcs.front()])
        if (is_subset(arcs, path_arcs[w])) g.out[s].push_back(w);
    }
  return g;
}

}  // namespace

MinOneConstraints greedy_min_one_constraints(const TMesh& tmesh,
                                             const TMeshIncidence& /*incidence*/,
                                             std::vector<int>* cover) {
  MinOneConstraints result;
  if (cover) cover->assign(tmesh.nonzero_paths.size(), -1);
  if (tmesh.nonzero_paths.empty()) return result;
  const ImplicationGraph g = build_implication_graph(tmesh);
  std::vector<char> deleted(g.out.size(), 0);
  int uncovered = g.paths;
  // Try-Cover: visit everything reachable from `start` that is not deleted, delete it, and say
  // whether an uncovered path was among it.
  std::vector<int> stack;
  int element = 0;  // the bound a search would add: sides first, then arcs (see `cover`)
  const auto try_cover = [&](int start) {
    if (deleted[start]) return false;
    bool covered_any = false;
    deleted[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (v < g.paths) {
        covered_any = true, --uncovered;
        if (cover) (*cover)[v] = element;
      }
      for (int w : g.out[v])
        if (!deleted[w]) deleted[w] = 1, stack.push_back(w);
    }
    return covered_any;
  };
  // Sides by decreasing target length: a min-one bound costs least where the side would not
  // be 0 anyway.
  std::vector<SideRef> sides;
  std::vector<double> side_target;
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k = 0; k < 4; ++k) {
      double length = 0;
      for (int h : tmesh.patch_sides[p][k]) length += tmesh.arc_target[TMesh::arc_of(h)];
      sides.push_back({p, k});
      side_target.push_back(length);
    }
  std::vector<int> order(sides.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return side_target[a] > side_target[b]; });
  for (int i : order) {
    if (uncovered == 0) return result;
    element = static_cast<int>(result.sides.size());
    if (try_cover(g.side_node(sides[i][0], sides[i][1]))) result.sides.push_back(sides[i]);
  }
  // Paths without a whole side: one of their arcs, longest target first.
  std::vector<int> arcs(g.arcs);
  std::iota(arcs.begin(), arcs.end(), 0);
  std::stable_sort(arcs.begin(), arcs.end(),
                   [&](int a, int b) { return tmesh.arc_target[a] > tmesh.arc_target[b]; });
  for (int a : arcs) {
    if (uncovered == 0) break;
    element = static_cast<int>(result.sides.size() + result.arcs.size());
    if (try_cover(g.arc_node(a))) result.arcs.push_back(a);
  }
  if (cover)  // arc bounds by arc id below: renumber theirs
    for (int& e : *cover)
      if (e >= static_cast<int>(result.sides.size())) e = -2 - result.arcs[e - result.sides.size()];
  std::sort(result.arcs.begin(), result.arcs.end());
  if (cover)
    for (int& e : *cover)
      if (e <= -2)
        e = static_cast<int>(result.sides.size() +
                             (std::lower_bound(result.arcs.begin(), result.arcs.end(), -2 - e) -
                              result.arcs.begin()));
  return result;
}

}  // namespace bimdf::tmesh
