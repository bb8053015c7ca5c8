// Which quads meet at each vertex of a quad mesh: the adjacency smoothing, metrics, chart
// placement and the cleanups all start from.
#pragma once

#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::detail {

// Per vertex, the quads with a corner there, in the mesh's order.
inline std::vector<std::vector<int>> quads_at_vertices(const QuadMesh& mesh) {
  std::vector<std::vector<int>> quads_at(mesh.num_vertices());
  for (int q = 0; q < mesh.num_quads(); ++q)
    for (int v : mesh.quads[q]) quads_at[v].push_back(q);
  return quads_at;
}

}  // namespace bimdf::detail
