// Doublets: interior vertices of valence 2. Their two quads share two consecutive edges, and
// each has a corner of about 180° there (scaled Jacobian about 0, often just below: bull's one
// inverted quad in the standalone remesher's benchmark). Tessellation makes them where two
// charts both take a layout vertex as a corner on flat ground. The standard cleanup removes the
// vertex and merges its two quads into one, the quad of their four other corners; it keeps the
// Euler characteristic (one vertex, two edges and one face fewer) and changes only the valences
// of the two corners the quads shared.
#pragma once

#include <vector>

#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"

namespace bimdf::detail {

// Removes, repeatedly (a merge can leave a neighbour of valence 2), each doublet whose merged
// quad has a larger scaled Jacobian (quad_quality.hpp) than the worse of its two quads, among
// the vertices `may_go` allows and off the border. The merged quad takes the place (and
// quad_patch) of the first of the two in the mesh's order; the rest keep their order.
// `renumber`: per old vertex its new index, −1 if removed. Returns how many were removed.
int remove_doublets(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber);

// The same on a tessellation of `layout`, sparing vertices on its feature curves and corners
// (there the vertex carries the feature); `origin` and the charts' quad counts follow.
int remove_doublets(const quant::Layout& layout, quant::Tessellation& tessellation);

}  // namespace bimdf::detail
