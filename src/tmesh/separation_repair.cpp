// Separation repair (tmesh/separation_repair.hpp).
#include "tmesh/separation_repair.hpp"

#include <algorithm>
#include <utility>

namespace bimdf::tmesh {
namespace {

// Per T-mesh vertex: whether a non-zero path starts there.
std::vector<char> seeds(const TMesh& tm) {
  std::vector<char> seed(tm.num_vertices(), 0);
  for (const auto& path : tm.nonzero_paths) seed[tm.half_arc_tail(path.front())] = 1;
  return seed;
}

// Per T-mesh vertex: whether it lies on a curve — an end of a feature arc or a border arc.
std::vector<char> on_curves(const TMesh& tm, const TMeshIncidence& incidence) {
  std::vector<char> on(tm.num_vertices(), 0);
  for (int a = 0; a < tm.num_arcs(); ++a) {
    const bool feature = a < static_cast<int>(tm.arc_feature.size()) && tm.arc_feature[a];
    if (feature || incidence.is_border(2 * a) || incidence.is_border(2 * a + 1))
      on[tm.arc_ends[a][0]] = on[tm.arc_ends[a][1]] = 1;
  }
  return on;
}

// Adds `x` to `list` (one kind of bound) unless already there; returns whether added.
template <typename T>
bool add_once(std::vector<T>& list, const T& x) {
  if (std::find(list.begin(), list.end(), x) != list.end()) return false;
  list.push_back(x);
  return true;
}
bool bound_arc(int a, MinOneConstraints& bounds) { return add_once(bounds.arcs, a); }
bool bound_arc_two(int a, MinOneConstraints& bounds) { return add_once(bounds.arcs_two, a); }
bool bound_side(SideRef side, MinOneConstraints& bounds) { return add_once(bounds.sides, side); }

}  // namespace

bool add_separation_bounds(const TMesh& tm, const TMeshIncidence& incidence,
                           const std::vector<int64_t>& length, const CollapsedMesh& collapsed,
                           MinOneConstraints& bounds) {
  const std::vector<char> seed = seeds(tm);
  // Nodes: T-mesh vertices, then one per patch and side pair. Edges carry their element:
  // arc a ≥ 0, or −1 − (2·patch + pair).
  const int nv = tm.num_vertices();
  std::vector<std::vector<std::pair<int, int>>> adjacent(nv + 2 * tm.num_patches());
  for (int a = 0; a < tm.num_arcs(); ++a)
    if (length[a] == 0) {
      const auto [u, w] = tm.arc_ends[a];
      adjacent[u].push_back({w, a});
      adjacent[w].push_back({u, a});
    }
  for (int p = 0; p < tm.num_patches(); ++p)
    for (int pair = 0; pair < 2; ++pair) {
      if (side_length(tm, p, pair, length) != 0) continue;
      const int node = nv + 2 * p + pair;
      for (int k : {pair + 1, (pair + 3) % 4})
        for (int h : tm.patch_sides[p][k])
          for (int v : {tm.half_arc_tail(h), tm.half_arc_head(h)}) {
            adjacent[v].push_back({node, -1 - (2 * p + pair)});
            adjacent[node].push_back({v, -1 - (2 * p + pair)});
          }
    }
  const auto target = [&](int element) {
    if (element >= 0) return tm.arc_target[element];
    const int p = (-1 - element) / 2, pair = (-1 - element) % 2;
    double sum = 0;
    for (int k : {pair, pair + 2})
      for (int h : tm.patch_sides[p][k]) sum += tm.arc_target[TMesh::arc_of(h)];
    return sum / 2;
  };
  bool added = false;
  std::vector<std::pair<int, int>> came_from(adjacent.size());  // (node, element)
  // Bounds the element with the longest target on a path of merging elements from `from` to
  // `to` (none when they merged some other way: not ours to fix).
  const auto bound_path = [&](int from, int to) {
    std::fill(came_from.begin(), came_from.end(), std::pair<int, int>{-1, 0});
    std::vector<int> queue{from};
    came_from[from] = {from, 0};
    for (size_t i = 0; i < queue.size() && came_from[to].first < 0; ++i)
      for (const auto& [w, element] : adjacent[queue[i]])
        if (came_from[w].first < 0) came_from[w] = {queue[i], element}, queue.push_back(w);
    if (came_from[to].first < 0) return;
    int best = 0;
    double best_target = -1;
    for (int v = to; v != from; v = came_from[v].first)
      if (const int e = came_from[v].second; target(e) > best_target)
        best = e, best_target = target(e);
    added |= best >= 0 ? bound_arc(best, bounds)
                       : bound_side(SideRef{(-1 - best) / 2, (-1 - best) % 2}, bounds);
  };
  const std::vector<char> on_curve = on_curves(tm, incidence);
  for (const CollapsedVertex& o : collapsed.origin) {
    std::vector<int> merged;
    int off_curve_seed = -1, curve_vertex = -1;
    for (int v : o.tmesh_vertices) {
      if (seed[v]) merged.push_back(v);
      if (seed[v] && !on_curve[v] && off_curve_seed < 0) off_curve_seed = v;
      if (on_curve[v] && curve_vertex < 0) curve_vertex = v;
    }
    if (merged.size() >= 2)
      bound_path(merged[0], merged[1]);
    else if (off_curve_seed >= 0 && curve_vertex >= 0)
      bound_path(off_curve_seed, curve_vertex);
  }
  return added;
}

bool add_collapse_failure_bounds(const TMesh& tm, const std::vector<int64_t>& length,
                                 const std::vector<int>& patches, MinOneConstraints& bounds) {
  int best_arc = -1;
  SideRef best_side{-1, -1};
  double best_target = -1;
  for (int p : patches) {
    if (p < 0 || p >= tm.num_patches()) continue;
    for (int pair = 0; pair < 2; ++pair) {
      const SideRef side{p, pair};
      if (side_length(tm, p, pair, length) != 0 ||
          std::find(bounds.sides.begin(), bounds.sides.end(), side) != bounds.sides.end())
        continue;
      double target = 0;
      for (int h : tm.patch_sides[p][pair]) target += tm.arc_target[TMesh::arc_of(h)];
      if (target > best_target) best_target = target, best_side = side, best_arc = -1;
    }
    for (const auto& sides : tm.patch_sides[p])
      for (int h : sides) {
        const int a = TMesh::arc_of(h);
        if (length[a] != 0 ||
            std::find(bounds.arcs.begin(), bounds.arcs.end(), a) != bounds.arcs.end())
          continue;
        if (tm.arc_target[a] > best_target)
          best_target = tm.arc_target[a], best_arc = a, best_side = {-1, -1};
      }
  }
  if (best_arc >= 0) return bound_arc(best_arc, bounds);
  if (best_side[0] >= 0) return bound_side(best_side, bounds);
  return false;
}

bool add_valence_bounds(const TMesh& tm, const std::vector<int64_t>& length,
                        const CollapsedMesh& collapsed, MinOneConstraints& bounds) {
  const std::vector<char> seed = seeds(tm);
  std::vector<int> corners(tm.num_vertices(), 0);
  for (int p = 0; p < tm.num_patches(); ++p)
    for (int k = 0; k < 4; ++k) ++corners[tm.half_arc_tail(tm.patch_sides[p][k].front())];
  std::vector<int> quads_around(collapsed.origin.size(), 0);
  for (const auto& quad : collapsed.mesh.quads)
    for (int v : quad) ++quads_around[v];
  bool added = false;
  for (size_t o = 0; o < collapsed.origin.size(); ++o)
    for (int s : collapsed.origin[o].tmesh_vertices) {
      if (!seed[s] || corners[s] == quads_around[o]) continue;
      for (int a = 0; a < tm.num_arcs(); ++a)
        if (length[a] == 0 && (tm.arc_ends[a][0] == s || tm.arc_ends[a][1] == s))
          added |= bound_arc(a, bounds);
      for (int p = 0; p < tm.num_patches(); ++p)
        for (int k = 0; k < 4; ++k)
          if (tm.half_arc_tail(tm.patch_sides[p][k].front()) == s)
            for (int pair = 0; pair < 2; ++pair)
              if (side_length(tm, p, pair, length) == 0)
                added |= bound_side(SideRef{p, pair}, bounds);
    }
  return added;
}

bool add_border_loop_bounds(const TMesh& tm, const TMeshIncidence& incidence,
                            const std::vector<int64_t>& length, MinOneConstraints& bounds) {
  // Border half-arcs by tail; a vertex where the border pinches has several, any order will do.
  std::vector<std::vector<int>> leaving(tm.num_vertices());
  for (int h = 0; h < tm.num_half_arcs(); ++h)
    if (incidence.is_border(h)) leaving[tm.half_arc_tail(h)].push_back(h);
  std::vector<char> walked(tm.num_half_arcs(), 0);
  bool added = false;
  for (int start = 0; start < tm.num_half_arcs(); ++start) {
    if (!incidence.is_border(start) || walked[start]) continue;
    std::vector<int> loop;
    for (int h = start; h >= 0 && !walked[h];) {
      walked[h] = 1;
      loop.push_back(TMesh::arc_of(h));
      int next = -1;
      for (int g : leaving[tm.half_arc_head(h)])
        if (!walked[g]) next = g;
      h = next;
    }
    int64_t total = 0;
    for (int a : loop) total += length[a];
    if (total >= 3) continue;
    for (int a : loop)
      if (length[a] == 0) added |= bound_arc(a, bounds);
    if (loop.size() == 2) {
      const int longer = tm.arc_target[loop[0]] >= tm.arc_target[loop[1]] ? loop[0] : loop[1];
      added |= bound_arc_two(longer, bounds);
    }
  }
  return added;
}

bool add_quad_split_bounds(const TMesh& tm, const std::vector<int64_t>& length,
                           const CollapsedMesh& collapsed, const std::vector<int>& to_split,
                           MinOneConstraints& bounds) {
  bool added = false;
  for (int f : to_split) {
    const auto& q = collapsed.mesh.quads[f];
    // The arcs of length 1 that make one of the quad's edges: both ends lie on them.
    int best = -1;
    for (int k = 0; k < 4; ++k) {
      const std::vector<int>& from = collapsed.origin[q[k]].arcs;
      const std::vector<int>& to = collapsed.origin[q[(k + 1) % 4]].arcs;
      for (int a : from) {
        if (length[a] != 1 || std::find(to.begin(), to.end(), a) == to.end()) continue;
        if (std::find(bounds.arcs_two.begin(), bounds.arcs_two.end(), a) != bounds.arcs_two.end())
          continue;
        if (best < 0 || tm.arc_target[a] > tm.arc_target[best]) best = a;
      }
    }
    if (best >= 0) added |= bound_arc_two(best, bounds);
  }
  return added;
}

}  // namespace bimdf::tmesh
