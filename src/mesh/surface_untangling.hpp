// Untangling a region of quads on a surface by moving all its free vertices at once: the last
// resort of tangled_regions.hpp, where smoothing, which moves one vertex at a time, stops
// because every single move turns another quad over. The region descends on the regularized
// distortion energy of Garanzha et al. ("Foldover-free maps in 50 lines of code", 2021),
// measured per quad twice: in the tangent plane of the surface under it, and in the plane of
// the quad's own (Newell) normal, refreshed before each minimization — a twisted quad can
// turn counter-clockwise about the one and not the other, and metrics.hpp counts the second.
// Per corner and plane, with J the 2×2 matrix of the corner's two edges (in that plane, over
// the target edge length) and D = det J,
//   f(J) = ((|J|² + D² + 1) / 2) / χ(D, ε),   χ(D, ε) = (D + √(ε² + D²)) / 2,
// the mean of the shape term |J|²/(2χ) and the area term (D² + 1)/(2χ), both 1 at a square
// corner of the target size. χ > 0 for every ε > 0, so the energy is finite and smooth on
// tangled quads too; as ε falls, minimizers lose their inverted corners (f grows without bound
// as χ → 0 where D ≤ 0). ε follows the paper's rule: after each minimization, with E the
// energy and D⁻ the smallest determinant, σ = max(1 − E/E_before, 1/10), μ = (1 − σ)·χ(D⁻, ε)
// and ε ← 2√(μ(μ − D⁻)) while D⁻ < μ, else ε ← ε/10 (the paper lets it drop to 0; a tenth
// keeps the energy finite for the next descent). Each minimization is L-BFGS with a
// backtracking line search; every step is projected back onto the surface, so the descent is
// a projected one (a plane region, whose projection is the identity, descends exactly).
// Tutte's embedding, the region's other placement, is one-to-one only inside a convex
// boundary in one plane; this needs neither.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "mesh/vec3.hpp"

namespace bimdf::detail {

struct QuadsOnSurface {
  std::vector<Vec3> points;                       // updated in place
  std::vector<std::array<int, 4>> quads;          // corners counter-clockwise about their normal
  std::vector<Vec3> normals;                      // per quad, the surface's unit normal under it
  std::vector<char> movable;                      // per point; the others stay where they are
  std::function<Vec3(int, const Vec3&)> project;  // (point, position) back onto the surface;
                                                  // none: the points stay where they move
};

struct SurfaceUntangling {
  // The smallest determinant, over the target length squared, among the corners (in either
  // plane) that a movable point changes.
  double min_det_before = 0;
  double min_det_after = 0;
  int rounds = 0;  // minimizations run (one per ε)
  bool untangled() const { return min_det_after > 0; }
};

// Moves the movable points of `quads` to untangle them; `edge_length` is the length their
// edges should have (it scales the energy's area term, not what counts as untangled). Stops
// once every corner's determinant is positive and a minimization no longer lowers the energy
// by 0.1%, or after `max_rounds` minimizations.
SurfaceUntangling untangle_quads_on_surface(QuadsOnSurface& quads, double edge_length,
                                            int max_rounds = 30);

}  // namespace bimdf::detail
