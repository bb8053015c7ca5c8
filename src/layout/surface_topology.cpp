// Rings, border loops and components of a manifold oriented triangle mesh
// (surface_topology.hpp).
#include "layout/surface_topology.hpp"

#include <cmath>
#include <numeric>

#include "bimdf/error.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::layout {

SurfaceTopology::SurfaceTopology(const TriangleMesh& mesh, const std::string& source)
    : mesh_(&mesh) {
  std::vector<std::pair<int, int>> same_direction;
  conn_ = quant::connect(mesh, source, &same_direction);
  if (!same_direction.empty())
    throw InputError(source, "",
                     "faces " + std::to_string(same_direction[0].first / 3) + " and " +
                         std::to_string(same_direction[0].second / 3) +
                         " are oriented differently (prepare the surface first)");
  const int H = num_half_edges(), V = mesh.num_vertices(), F = mesh.num_faces();
  edge_half_edge_.assign(conn_.num_edges, -1);
  for (int h = 0; h < H; ++h)
    if (edge_half_edge_[conn_.edge[h]] < 0) edge_half_edge_[conn_.edge[h]] = h;

  // The first outgoing half-edge of each vertex: a border one where there is one.
  vertex_out_.assign(V, -1);
  border_vertex_.assign(V, false);
  for (int h = 0; h < H; ++h) {
    const int v = from(h);
    if (conn_.opposite[h] < 0) {
      vertex_out_[v] = h;
      border_vertex_[v] = true;
      border_vertex_[to(h)] = true;
    } else if (vertex_out_[v] < 0) {
      vertex_out_[v] = h;
    }
  }

  // Border loops: from a border half-edge's head, the next border half-edge leaves it.
  std::vector<bool> walked(H, false);
  for (int h = 0; h < H; ++h) {
    if (conn_.opposite[h] >= 0 || walked[h]) continue;
    std::vector<int> loop;
    for (int g = h; !walked[g]; g = vertex_out_[to(g)]) {
      walked[g] = true;
      loop.push_back(g);
    }
    border_loops_.push_back(std::move(loop));
  }

  // Components by a flood over faces.
  face_component_.assign(F, -1);
  std::vector<int> stack;
  for (int f0 = 0; f0 < F; ++f0) {
    if (face_component_[f0] >= 0) continue;
    face_component_[f0] = num_components_;
    stack.push_back(f0);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const int g = conn_.opposite[3 * f + i];
        if (g >= 0 && face_component_[g / 3] < 0) {
          face_component_[g / 3] = num_components_;
          stack.push_back(g / 3);
        }
      }
    }
    ++num_components_;
  }
}

std::vector<int> SurfaceTopology::outgoing(int v) const {
  std::vector<int> ring;
  const int start = vertex_out_[v];
  if (start < 0) return ring;
  for (int h = start; h >= 0;) {
    ring.push_back(h);
    h = rotate_ccw(h);
    if (h == start) break;
  }
  return ring;
}

double SurfaceTopology::mean_edge_length() const {
  const auto& p = mesh_->vertices;
  double sum = 0;
  for (int e = 0; e < num_edges(); ++e) {
    const int h = edge_half_edge(e);
    sum += detail::norm(detail::sub(p[to(h)], p[from(h)]));
  }
  return num_edges() > 0 ? sum / num_edges() : 0;
}

double SurfaceTopology::corner_angle(int h) const {
  const auto& p = mesh_->vertices;
  const detail::Vec3 a = detail::sub(p[to(h)], p[from(h)]);
  const detail::Vec3 b = detail::sub(p[from(prev(h))], p[from(h)]);
  return std::atan2(detail::norm(detail::cross(a, b)), detail::dot(a, b));
}

}  // namespace bimdf::layout
