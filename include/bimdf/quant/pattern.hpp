// All-quad patterns for a k-sided patch with prescribed side subdivisions: the combinatorial
// step of turning a quantized chart into quads (../shared/reference/quadwild_modeling.md §4.1;
// paper §4.4 relies on the existence of such patterns for every even perimeter).
//
// Given side lengths l_0…l_{k−1} (k = 3…6, every l_j ≥ 1, Σ l_j even and ≥ 4), a pattern is a
// quad mesh of the k-gon whose boundary has exactly l_j edges on side j. Regular side vectors
// get the regular pattern (note §3.3): for k = 4 with l_0 = l_2, l_1 = l_3 a grid; for other k
// one valence-k vertex joined to the sides, i.e. k corner grids of e_j × e_{j−1} quads where
// e_j ≥ 0 counts the strips parallel to side j and l_j = e_{j−1} + e_{j+1}. (An e_j of 0 puts
// the singularity on the boundary.) Every other side vector is cut, by a chain of interior
// edges between two boundary vertices, into two sub-patches that are regular — or are cut
// again — choosing the cut that creates the fewest singularities and whose length best fits
// the distance it spans; the cuts play the role of the padding and edge-flow parameters of
// Takayama et al.'s patterns (SGP 2014). Should no cut sequence work, a fan — quads around one
// new centre vertex, each on two boundary edges, or around a corner — covers the patch, so no
// chart is ever left without quads. (No side vector with sides up to 9 needs the fan.)
#pragma once

#include <array>
#include <string>
#include <vector>

namespace bimdf::quant {

enum class PatternKind {
  Regular,  // the regular pattern of the side vector (grid, or one valence-k singularity)
  Cut,      // regular sub-patches joined along cut chains
  Fan       // the last resort: quads fanned around a centre vertex or a corner
};

std::string to_string(PatternKind kind);

// A quad pattern on its pattern_polygon. Vertices 0…P−1 (P = Σ l_j) are the boundary in
// counter-clockwise order: vertex Σ_{i<j} l_i is corner j and side j runs from corner j to
// corner j+1. Interior vertices follow. Quads are counter-clockwise, like the boundary.
struct QuadPattern {
  std::vector<int> sides;                        // l_j
  std::vector<std::array<int, 4>> quads;         // vertex ids
  std::vector<std::array<double, 2>> positions;  // in `polygon`
  PatternKind kind = PatternKind::Regular;
  int cuts = 0;                                // cut chains used (PatternKind::Cut)
  std::vector<std::array<double, 2>> polygon;  // pattern_polygon(sides): corner j

  int num_vertices() const { return static_cast<int>(positions.size()); }
  int perimeter() const;
};

// The convex polygon patterns are drawn in: corner j, counter-clockwise, corner 0 at the top.
// Its sides have the lengths l_j (so quads come out near-square): it is the polygon with those
// sides inscribed in a circle. When the longest side is not clearly shorter than the others
// together (2 l_max > 0.9 Σ l), the lengths are first blended towards their mean until it is.
std::vector<std::array<double, 2>> pattern_polygon(const std::vector<int>& sides);

// The pattern for `sides` (see above). Boundary vertices sit on pattern_polygon(sides), evenly
// spaced along each side; interior vertices at the average of their neighbours (Tutte's
// embedding, which keeps faces convex on the convex polygon). Among the candidate patterns the
// first whose quads are all convex (no corner turning clockwise) is taken; if none is, the
// first fan, convex or not (a valid disk of quads all the same). Throws std::invalid_argument if k
// is outside 3…6, a side is < 1, or the perimeter is odd or < 4.
QuadPattern make_quad_pattern(const std::vector<int>& sides);

// The regular pattern's strip counts e_j (l_j = e_{j−1} + e_{j+1}; for k = 4, e_0 = l_1 and
// e_1 = l_0 are the grid's two dimensions), or an empty vector when `sides` is not regular:
// some e_j would be negative or fractional, or the zero e_j would not form one cyclic run
// (the pattern would pinch at its singularity).
std::vector<int> regular_strip_counts(const std::vector<int>& sides);

}  // namespace bimdf::quant
