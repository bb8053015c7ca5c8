// Edge connectivity of a triangle mesh by half-edges, and coherent re-orientation: what the
// layout reader (layout_extraction.cpp) and the triangle-mesh layout stages (src/layout/)
// both need before they can walk a surface.
//
// Half-edge h = 3f + i runs from faces[f][i] to faces[f][(i+1) % 3]; its face is h / 3.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::quant {

inline int from_vertex(const TriangleMesh& m, int h) { return m.faces[h / 3][h % 3]; }
inline int to_vertex(const TriangleMesh& m, int h) { return m.faces[h / 3][(h % 3 + 1) % 3]; }

struct Connectivity {
  std::vector<int> opposite;  // per half-edge, −1 on the mesh border
  std::vector<int> edge;      // per half-edge, its undirected edge id
  int num_edges = 0;
};

// Pairs half-edges by their undirected edge. Throws InputError (file `source`) naming the two
// vertices of an edge with more than two faces (non-manifold). `same_direction`, if given,
// collects pairs whose half-edges run the same way (orientation conflicts).
Connectivity connect(const TriangleMesh& m, const std::string& source,
                     std::vector<std::pair<int, int>>* same_direction);

// Flips faces so that every interior edge is walked in opposite directions by its two faces;
// the face with the smallest id keeps its orientation in each connected piece. Returns how many
// faces were flipped; throws InputError naming two faces if the mesh is not orientable.
int orient_coherently(TriangleMesh& m, const Connectivity& c, const std::string& source);

}  // namespace bimdf::quant
