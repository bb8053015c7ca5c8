// A point on a triangle mesh's surface, named by the mesh element it lies on: what traced
// separatrices are made of (tracing.hpp) and what the mesh is cut along (mesh_cutting.hpp).
#pragma once

#include <array>

#include "bimdf/mesh.hpp"
#include "layout/surface_topology.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::layout {

struct SurfacePoint {
  enum class Kind { Vertex, Edge, Face };
  Kind kind = Kind::Vertex;
  // Vertex: the vertex id. Edge: the undirected edge id of SurfaceTopology (the point lies
  // strictly inside the edge). Face: the face id (the point lies strictly inside the face).
  int id = -1;
  // Edge: where on the edge, 0 at from(edge_half_edge(id)) and 1 at its to(); strictly
  // between 0 and 1.
  double t = 0;
  // Face: barycentric coordinates with respect to faces[id][0], [1], [2]; each > 0, sum 1.
  std::array<double, 3> bary{};

  static SurfacePoint at_vertex(int v) { return {Kind::Vertex, v, 0, {}}; }
  static SurfacePoint on_edge(int e, double t) { return {Kind::Edge, e, t, {}}; }
  static SurfacePoint in_face(int f, std::array<double, 3> b) { return {Kind::Face, f, 0, b}; }
};

// The point's position in space.
inline detail::Vec3 position(const SurfaceTopology& top, const SurfacePoint& p) {
  const TriangleMesh& m = top.mesh();
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      return m.vertices[p.id];
    case SurfacePoint::Kind::Edge: {
      const int h = top.edge_half_edge(p.id);
      const detail::Vec3 &a = m.vertices[top.from(h)], &b = m.vertices[top.to(h)];
      return detail::along(a, p.t, detail::sub(b, a));
    }
    case SurfacePoint::Kind::Face: {
      detail::Vec3 x{0, 0, 0};
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) x[c] += p.bary[k] * m.vertices[m.faces[p.id][k]][c];
      return x;
    }
  }
  return {0, 0, 0};
}

}  // namespace bimdf::layout
