// Half-edge pairing and coherent orientation of triangle meshes (triangle_connectivity.hpp).
#include "quant/triangle_connectivity.hpp"

#include <algorithm>
#include <cstdint>
#include <queue>

#include "bimdf/error.hpp"

namespace bimdf::quant {

Connectivity connect(const TriangleMesh& m, const std::string& source,
                     std::vector<std::pair<int, int>>* same_direction) {
  const int H = 3 * m.num_faces();
  std::vector<std::pair<uint64_t, int>> keyed(H);
  for (int h = 0; h < H; ++h) {
    const uint64_t a = from_vertex(m, h), b = to_vertex(m, h);
    keyed[h] = {std::min(a, b) << 32 | std::max(a, b), h};
  }
  std::sort(keyed.begin(), keyed.end());
  Connectivity c;
  c.opposite.assign(H, -1);
  c.edge.assign(H, -1);
  for (int i = 0; i < H;) {
    int j = i;
    while (j < H && keyed[j].first == keyed[i].first) ++j;
    if (j - i > 2) {
      const int h = keyed[i].second;
      throw InputError(source, "",
                       "the mesh edge between vertices " + std::to_string(from_vertex(m, h)) +
                           " and " + std::to_string(to_vertex(m, h)) + " has " +
                           std::to_string(j - i) + " faces, expected at most 2 (non-manifold)");
    }
    for (int k = i; k < j; ++k) c.edge[keyed[k].second] = c.num_edges;
    if (j - i == 2) {
      const int h = keyed[i].second, g = keyed[i + 1].second;
      c.opposite[h] = g;
      c.opposite[g] = h;
      if (same_direction && from_vertex(m, h) == from_vertex(m, g))
        same_direction->push_back({h, g});
    }
    ++c.num_edges;
    i = j;
  }
  return c;
}

int orient_coherently(TriangleMesh& m, const Connectivity& c, const std::string& source) {
  const int F = m.num_faces();
  std::vector<int8_t> flip(F, -1);
  int flipped = 0;
  for (int root = 0; root < F; ++root) {
    if (flip[root] >= 0) continue;
    flip[root] = 0;
    std::queue<int> queue;
    queue.push(root);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (int i = 0; i < 3; ++i) {
        const int h = 3 * f + i, g = c.opposite[h];
        if (g < 0) continue;
        const int same = from_vertex(m, h) == from_vertex(m, g);
        const int8_t want = static_cast<int8_t>(same ^ flip[f]);
        if (flip[g / 3] < 0) {
          flip[g / 3] = want;
          queue.push(g / 3);
        } else if (flip[g / 3] != want) {
          throw InputError(source, "",
                           "the mesh is not orientable (faces " + std::to_string(f) + " and " +
                               std::to_string(g / 3) + " cannot agree on an orientation)");
        }
      }
    }
  }
  for (int f = 0; f < F; ++f)
    if (flip[f] == 1) {
      std::swap(m.faces[f][1], m.faces[f][2]);
      ++flipped;
    }
  return flipped;
}

}  // namespace bimdf::quant
