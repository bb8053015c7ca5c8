// Patch layouts (T-meshes) on a triangle mesh: charts, their sides and subsides, read from
// QuadWild's step-2 output (../shared/reference/quadwild_modeling.md §1; paper §4.4).
//
// A *chart* is a disk of triangles with k ≥ 3 corners on its boundary; a *side* is the boundary
// between two consecutive corners; a *subside* is a maximal piece of a side that borders a
// single neighbour chart (or the mesh border) and has no corner of either chart in its
// interior, so sides split at T-junctions. Each subside is shared by at most two charts and
// gets one positive integer in a quantization: its number of quad edges.
//
// Orientation: every chart's boundary is walked with the chart on the left (the faces'
// counter-clockwise order); sides are numbered in that order from the first corner met. A
// subside's vertex chain runs in the walking direction of `charts[0]`; `charts[1]` (the
// neighbour, −1 on the mesh border) walks it reversed.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::quant {

struct Subside {
  std::array<int, 2> charts{-1, -1};  // charts[1] = −1 on the mesh border
  std::array<int, 2> sides{-1, -1};   // the side index within each chart
  std::vector<int> vertices;          // mesh vertex chain, in charts[0]'s walking direction
  double length = 0;                  // sum of the mesh edge lengths

  bool on_border() const { return charts[1] < 0; }
  int mesh_edges() const { return static_cast<int>(vertices.size()) - 1; }
};

struct Side {
  std::vector<int> subsides;   // in walking order
  std::vector<bool> reversed;  // whether the chart walks subsides[i] against its vertex chain
  double length = 0;           // sum of its subsides' lengths
};

struct Chart {
  std::vector<int> faces;
  std::vector<int> corners;  // vertex ids in walking order; corners[j] starts sides[j]
  std::vector<Side> sides;
  std::vector<int> subsides;  // every subside of the chart, side by side in walking order

  int valence() const { return static_cast<int>(sides.size()); }
  bool empty() const { return faces.empty(); }
};

struct Layout {
  TriangleMesh mesh;  // coherently oriented (faces flipped where the input was not)
  std::vector<int> face_chart;
  std::vector<Chart> charts;  // by patch id; ids without faces give empty charts
  std::vector<Subside> subsides;
  std::vector<std::array<int, 2>> feature_edges;  // vertex pairs (from NAME.feature)
  std::vector<int> feature_corners;               // vertex ids (from NAME.c_feature)
  int flipped_faces = 0;                          // faces re-oriented to make the mesh coherent
  // What the reader tolerated but the user should know (e.g. a corner inside its chart).
  std::vector<std::string> warnings;
  double average_edge_length = 0;  // QuadWild's: the mean of every face's three edge lengths
};

// Builds charts, sides and subsides. `corners[c]`: the corner vertices of chart c (their order
// is irrelevant; the boundary walk finds them; corners off the boundary are ignored with a
// warning, as QuadWild does). Re-orients faces coherently if needed. Throws InputError (with
// `source` as the file) for a non-manifold or non-orientable mesh, a chart that is not a disk,
// a valence outside 3–6, or a shared
// boundary that the two charts split differently — naming the chart, vertex or edge.
Layout build_layout(TriangleMesh mesh, std::vector<int> face_chart,
                    const std::vector<std::vector<int>>& corners, const std::string& source);

// Reads QuadWild's step-2 output: `obj_path` and, beside it with the same stem, `.patch` and
// `.corners` (required), `.feature` and `.c_feature` (optional). Errors name the file and line.
Layout read_quadwild_layout(const std::string& obj_path);

// Reads QuadWild's NAME.feature (a count, then `face,edge` pairs: edge e of a face runs from its
// vertex e to vertex e+1 mod 3) as the vertex pairs of `mesh`'s faces. Errors name file and line.
std::vector<std::array<int, 2>> read_feature_edges(const std::string& path,
                                                   const TriangleMesh& mesh);
// Reads QuadWild's NAME.c_feature (a count, then vertex ids below `num_vertices`).
std::vector<int> read_feature_corners(const std::string& path, int num_vertices);

}  // namespace bimdf::quant
