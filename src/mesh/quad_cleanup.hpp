// What the topological cleanups of a finished quad mesh share (doublets.hpp,
// diagonal_collapse.hpp): which vertices may disappear without taking a feature or the border
// with them, and the renumbering once vertices and quads are gone.
#pragma once

#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"
#include "mesh/quad_adjacency.hpp"

namespace bimdf::detail {

// Per quad mesh vertex of a tessellation of `layout`: 1 if it is off the layout's feature
// curves and corners (a vertex on one carries the feature and must stay), else 0.
std::vector<char> off_features(const quant::Layout& layout, const quant::Tessellation& t);

// Clears `may_go` for the vertices on the mesh's border (an edge of one quad marks them).
void keep_border(const QuadMesh& mesh, std::vector<char>& may_go);

// Drops the flagged vertices and quads, keeping the order of the rest (quad_patch follows).
// `renumber`: per old vertex its new index, −1 if dropped.
void drop_gone(QuadMesh& mesh, const std::vector<char>& vertex_gone,
               const std::vector<char>& quad_gone, std::vector<int>& renumber);

// After drop_gone on t.mesh: the origins follow `renumber` and the charts' quad counts are
// recounted from quad_patch.
void follow_renumbering(quant::Tessellation& t, const std::vector<int>& renumber);

}  // namespace bimdf::detail
