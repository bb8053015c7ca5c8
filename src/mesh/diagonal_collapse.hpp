// Diagonal collapse of inverted quads: the last resort for a quad that smoothing and polishing
// left turned over. Such quads sit where the tessellation forces a fold — mostly at the tips of
// narrow features and where feature curves run closer than a quad edge (the standalone
// remesher's cow, camel, mannequin-devil) — and no placement of the vertices frees them. The
// standard quad-mesh cleanup (as in quad simplification: Tarini et al. 2010, Daniels et al.
// 2008) merges two opposite corners of the quad into one vertex: the quad disappears, its two
// other corners each lose one quad, and the merged vertex has the quads of both. The Euler
// characteristic is kept (one vertex, two edges and one face fewer); valences change only at
// those three vertices.
#pragma once

#include <vector>

#include "bimdf/quant/layout.hpp"
#include "bimdf/quant/tessellate.hpp"

namespace bimdf::detail {

// Collapses, repeatedly (worst first, until none is left that may go), a diagonal of each quad
// whose scaled Jacobian (quad_quality.hpp, against its own normal) is negative: one corner b,
// among those `may_go` allows and off the border, goes into the opposite corner a, which keeps
// its place. A collapse is made only where it keeps the mesh manifold — a and b share no quad
// but this one and no neighbour but its two other corners, each of which keeps two quads — and
// where the worst scaled Jacobian of the quads at a and b, after, is larger than before (the
// inverted quad included). Of the candidates (two diagonals, either end kept) the best after
// is taken. `renumber`: per old vertex its new index, −1 if removed; `merged`: the new indices
// of the vertices that took another in. Returns how many quads were collapsed.
int collapse_inverted_quads(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber,
                            std::vector<int>& merged);

// One collapse, whatever it does to the quads' shapes (for a caller that settles the vertices
// around and judges after): corner `keep` of quad q takes in its opposite corner, if that keeps
// the mesh manifold (as above); else returns false and leaves the mesh as it was. `renumber` as
// above; the merged vertex is renumber[keep]. Throws std::invalid_argument if `keep` is not a
// corner of q.
bool collapse_diagonal(QuadMesh& mesh, int q, int keep, std::vector<int>& renumber);

// The same as collapse_inverted_quads above on a tessellation of `layout`, sparing vertices on its
// feature curves and corners (quad_cleanup.hpp: off_features); `origin` and the charts' quad counts
// follow (the merged vertex keeps the origin of the one it kept).
int collapse_inverted_quads(const quant::Layout& layout, quant::Tessellation& tessellation,
                            std::vector<int>& merged);

}  // namespace bimdf::detail
