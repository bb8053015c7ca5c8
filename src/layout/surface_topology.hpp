// Half-edge navigation on a manifold, coherently oriented triangle mesh (what prepare_surface
// returns): rings around vertices in counter-clockwise order, border loops, connected
// components. Every layout stage walks the surface through this one structure.
//
// Half-edge h = 3f + i runs from faces[f][i] to faces[f][(i+1) % 3] (quant::Connectivity's
// numbering); its face is h / 3, next(h) and prev(h) are the face's other two half-edges.
#pragma once

#include <array>
#include <vector>

#include "bimdf/mesh.hpp"
#include "quant/triangle_connectivity.hpp"

namespace bimdf::layout {

class SurfaceTopology {
 public:
  // The mesh must be manifold and coherently oriented (prepare_surface's output); throws
  // InputError otherwise, as quant::connect does, with `source` as the file.
  explicit SurfaceTopology(const TriangleMesh& mesh, const std::string& source = "<mesh>");

  static int next(int h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static int prev(int h) { return h - h % 3 + (h % 3 + 2) % 3; }
  static int face(int h) { return h / 3; }
  int opposite(int h) const { return conn_.opposite[h]; }  // −1 on the border
  int edge(int h) const { return conn_.edge[h]; }
  int from(int h) const { return quant::from_vertex(*mesh_, h); }
  int to(int h) const { return quant::to_vertex(*mesh_, h); }
  int num_edges() const { return conn_.num_edges; }
  int num_half_edges() const { return static_cast<int>(conn_.opposite.size()); }
  // One half-edge of edge e; the other is its opposite (−1 on the border).
  int edge_half_edge(int e) const { return edge_half_edge_[e]; }
  bool on_border(int v) const { return border_vertex_[v]; }

  // The half-edges leaving v in counter-clockwise order; at a border vertex the first is a
  // border half-edge (no face clockwise of it), so the faces run from one border edge to the
  // other. Empty for a vertex no face uses.
  std::vector<int> outgoing(int v) const;
  // The half-edge after h around h's origin, counter-clockwise (−1 past the border).
  int rotate_ccw(int h) const { return opposite(prev(h)); }
  // The angle of h's face at h's origin (between h and its face's previous edge), radians.
  double corner_angle(int h) const;
  // The mean length of the undirected edges (0 without edges): the unit of the layout stages'
  // distances (alignment length, approach radius, short traces).
  double mean_edge_length() const;

  // Border loops as half-edges in walking order (each has no opposite; the mesh's faces lie to
  // the left).
  const std::vector<std::vector<int>>& border_loops() const { return border_loops_; }
  const std::vector<int>& face_component() const { return face_component_; }
  int num_components() const { return num_components_; }

  const TriangleMesh& mesh() const { return *mesh_; }

 private:
  const TriangleMesh* mesh_;
  quant::Connectivity conn_;
  std::vector<int> edge_half_edge_;
  std::vector<int> vertex_out_;  // the first half-edge of outgoing(v), −1 if unused
  std::vector<bool> border_vertex_;
  std::vector<std::vector<int>> border_loops_;
  std::vector<int> face_component_;
  int num_components_ = 0;
};

}  // namespace bimdf::layout
