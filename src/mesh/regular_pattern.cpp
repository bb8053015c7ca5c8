// Regular patterns (quant/pattern.hpp): a grid for quads, k corner grids around one singularity
// otherwise. The corner grids are glued by identifying their vertices with a union–find, which
// also handles strip counts of zero, where grids degenerate to paths and the singularity lands
// on a side or a corner.
#include "mesh/regular_pattern.hpp"

#include <cstdint>
#include <map>
#include <numeric>
#include <utility>

#include "bimdf/quant/pattern.hpp"

namespace bimdf::quant {

std::vector<int> regular_strip_counts(const std::vector<int>& sides) {
  const int k = static_cast<int>(sides.size());
  if (k < 3 || k > 6) return {};
  const auto l = [&](int j) { return sides[((j % k) + k) % k]; };
  if (k == 4) {
    if (l(0) != l(2) || l(1) != l(3)) return {};
    return {l(1), l(0)};
  }
  std::vector<int> e(k);
  for (int j = 0; j < k; ++j) {
    // Twice e_j as an alternating sum of side lengths: for odd k around the whole cycle, for
    // k = 6 over the triangle of alternate sides that e_j belongs to.
    int64_t twice = 0;
    if (k == 6) {
      twice = int64_t{l(j - 1)} + l(j + 1) - l(j + 3);
    } else {
      for (int m = 0; m < k; ++m) twice += (m % 2 == 0 ? 1 : -1) * int64_t{l(j + 1 + 2 * m)};
    }
    if (twice < 0 || twice % 2 != 0) return {};
    e[j] = static_cast<int>(twice / 2);
  }
  int zero_runs = 0;
  for (int j = 0; j < k; ++j) {
    if (e[j] == 0 && e[(j + k - 1) % k] != 0) ++zero_runs;
    if (l(j) != e[(j + k - 1) % k] + e[(j + 1) % k]) return {};
  }
  if (zero_runs > 1) return {};
  return e;
}

namespace detail {
namespace {

class UnionFind {
 public:
  int add() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) { parent_[find(a)] = find(b); }
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  std::vector<int> parent_;
};

// Grids whose vertices are nodes of a union–find; nodes 0…n−1 stand for the ring positions.
class GridGluing {
 public:
  explicit GridGluing(int ring_size) {
    for (int i = 0; i < ring_size; ++i) nodes_.add();
  }

  // A grid of w × h cells; returns its index. Node (u, v), 0 ≤ u ≤ w, 0 ≤ v ≤ h.
  int add_grid(int w, int h) {
    grids_.push_back({w, h, nodes_.size()});
    for (int i = 0; i < (w + 1) * (h + 1); ++i) nodes_.add();
    return static_cast<int>(grids_.size()) - 1;
  }
  int node(int grid, int u, int v) const {
    const Grid& g = grids_[grid];
    return g.first_node + v * (g.w + 1) + u;
  }
  void glue(int a, int b) { nodes_.unite(a, b); }

  // Emits the cells as quads (u, v) → (u+1, v) → (u+1, v+1) → (u, v+1), naming every class
  // by its ring vertex or a new interior id. False if a class holds two ring positions or a
  // quad repeats a vertex.
  bool emit(const std::vector<int>& ring, QuadSoup& soup) {
    const int n = static_cast<int>(ring.size());
    std::map<int, int> class_vertex;
    for (int i = 0; i < n; ++i)
      if (!class_vertex.emplace(nodes_.find(i), ring[i]).second) return false;
    QuadSoup out = soup;
    const auto vertex_of = [&](int node) {
      auto [it, inserted] = class_vertex.emplace(nodes_.find(node), out.next_vertex);
      if (inserted) ++out.next_vertex;
      return it->second;
    };
    for (int gi = 0; gi < static_cast<int>(grids_.size()); ++gi) {
      const Grid& g = grids_[gi];
      for (int v = 0; v < g.h; ++v)
        for (int u = 0; u < g.w; ++u) {
          const std::array<int, 4> q{vertex_of(node(gi, u, v)), vertex_of(node(gi, u + 1, v)),
                                     vertex_of(node(gi, u + 1, v + 1)),
                                     vertex_of(node(gi, u, v + 1))};
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
              if (q[a] == q[b]) return false;
          out.quads.push_back(q);
        }
    }
    soup = std::move(out);
    return true;
  }

 private:
  struct Grid {
    int w, h, first_node;
  };
  UnionFind nodes_;
  std::vector<Grid> grids_;
};

}  // namespace

std::vector<int> PatchPolygon::side_lengths() const {
  const int k = static_cast<int>(corners.size());
  std::vector<int> l(k);
  for (int j = 0; j < k; ++j) {
    const int next = j + 1 < k ? corners[j + 1] : corners[0] + size();
    l[j] = next - corners[j];
  }
  return l;
}

bool add_regular_pattern(const PatchPolygon& polygon, QuadSoup& soup) {
  const std::vector<int> l = polygon.side_lengths();
  const std::vector<int> e = regular_strip_counts(l);
  if (e.empty()) return false;
  const int n = polygon.size();
  const int k = static_cast<int>(l.size());
  const auto ring_node = [&](int position) { return ((position % n) + n) % n; };
  GridGluing gluing(n);
  if (k == 4) {
    // u along side 0, v along side 1; the ring walks (0,0) → (a,0) → (a,b) → (0,b).
    const int a = l[0], b = l[1];
    const int g = gluing.add_grid(a, b);
    const std::vector<int>& c = polygon.corners;
    for (int u = 0; u <= a; ++u) {
      gluing.glue(gluing.node(g, u, 0), ring_node(c[0] + u));
      gluing.glue(gluing.node(g, a - u, b), ring_node(c[2] + u));
    }
    for (int v = 0; v <= b; ++v) {
      gluing.glue(gluing.node(g, a, v), ring_node(c[1] + v));
      gluing.glue(gluing.node(g, 0, b - v), ring_node(c[3] + v));
    }
    return gluing.emit(polygon.ring, soup);
  }
  // Grid j sits at corner j: u runs along side j (e_{j−1} cells), v back along side j−1
  // (e_j cells), so (u, v) is a counter-clockwise frame. Its edge u = e_{j−1} is the spoke
  // from side j to the singularity, shared with grid j+1's edge v = e_{j+1}.
  std::vector<int> grid(k);
  for (int j = 0; j < k; ++j) grid[j] = gluing.add_grid(e[(j + k - 1) % k], e[j]);
  for (int j = 0; j < k; ++j) {
    const int w = e[(j + k - 1) % k], h = e[j];
    const int corner = polygon.corners[j];
    for (int u = 0; u <= w; ++u) gluing.glue(gluing.node(grid[j], u, 0), ring_node(corner + u));
    for (int v = 0; v <= h; ++v) gluing.glue(gluing.node(grid[j], 0, v), ring_node(corner - v));
    const int next = (j + 1) % k;
    for (int t = 0; t <= h; ++t)
      gluing.glue(gluing.node(grid[j], w, t), gluing.node(grid[next], t, e[next]));
  }
  return gluing.emit(polygon.ring, soup);
}

bool is_disk_with_boundary(const std::vector<std::array<int, 4>>& quads, int num_vertices,
                           const std::vector<int>& ring) {
  if (quads.empty()) return false;
  std::map<std::pair<int, int>, int> directed;  // edge → quad
  std::vector<char> used(num_vertices, 0);
  for (int f = 0; f < static_cast<int>(quads.size()); ++f) {
    const std::array<int, 4>& q = quads[f];
    for (int a = 0; a < 4; ++a) {
      if (q[a] < 0 || q[a] >= num_vertices) return false;
      used[q[a]] = 1;
      for (int b = a + 1; b < 4; ++b)
        if (q[a] == q[b]) return false;
      if (!directed.emplace(std::make_pair(q[a], q[(a + 1) % 4]), f).second) return false;
    }
  }
  for (char u : used)
    if (!u) return false;
  // Boundary edges (no reverse twin) must be exactly the ring's edges.
  std::map<std::pair<int, int>, int> ring_edges;
  for (size_t i = 0; i < ring.size(); ++i)
    ring_edges.emplace(std::make_pair(ring[i], ring[(i + 1) % ring.size()]), 0);
  int undirected = 0, boundary = 0;
  for (const auto& [edge, f] : directed) {
    const bool twin = directed.count({edge.second, edge.first}) > 0;
    if (twin) {
      if (edge.first < edge.second) ++undirected;
      continue;
    }
    if (!ring_edges.count(edge)) return false;
    ++boundary;
    ++undirected;
  }
  if (boundary != static_cast<int>(ring.size())) return false;
  // Connected through edges.
  std::vector<int> component(quads.size(), -1), stack{0};
  component[0] = 0;
  int reached = 1;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int a = 0; a < 4; ++a) {
      const auto it = directed.find({quads[f][(a + 1) % 4], quads[f][a]});
      if (it != directed.end() && component[it->second] < 0) {
        component[it->second] = 0;
        ++reached;
        stack.push_back(it->second);
      }
    }
  }
  if (reached != static_cast<int>(quads.size())) return false;
  return num_vertices - undirected + static_cast<int>(quads.size()) == 1;
}

}  // namespace detail
}  // namespace bimdf::quant
