// Quality of a quad mesh: topology (manifoldness, Euler characteristic, singularities, base
// complex), element shape (scaled Jacobian) and, against a reference surface, distance and
// orientation — the numbers by which remeshing results are compared.
//
// Conventions. A vertex is *singular* when its valence differs from the regular one: 4 inside,
// 3 on the boundary (boundary vertices of valence 2 — a single quad's corner — count as
// singular too, as the corners of an open patch do in every base complex). The *scaled
// Jacobian* of a quad is the minimum over its four corners of sin of the corner angle, signed
// by the quad's own (Newell) normal: 1 for a rectangle, 0 for a degenerate corner, negative
// for a concave or folded one. A quad is *degenerate* when that value is exactly 0 (zero area,
// or a corner of exactly 180°), two of its corners are closer than 10⁻⁶ of its longest edge, or
// its four corners lie on one line (Newell normal below 10⁻⁹ of the sum of its squared edges;
// its angles are then rounding noise); otherwise it is *inverted* when the value is negative.
// The *base complex*
// is the partition of the faces by the boundary and the separatrices — the edge chains traced
// straight (through valence-4 vertices) from every singular vertex until they reach the
// boundary or another singular vertex.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf {

struct QuadMeshMetrics {
  int faces = 0, vertices = 0, edges = 0;
  int euler_characteristic = 0;  // V − E + F
  int boundary_edges = 0;
  int border_loops = 0;           // connected pieces of the boundary edges
  int non_manifold_edges = 0;     // edges with more than two quads, or two with equal direction
  int non_manifold_vertices = 0;  // vertices whose quads form more than one fan
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }

  std::map<int, int> interior_singularities;  // valence → count (valence ≠ 4)
  std::map<int, int> boundary_singularities;  // valence → count (valence ≠ 3)
  int singular_vertices() const;

  double scaled_jacobian_min = 0, scaled_jacobian_mean = 0, scaled_jacobian_p5 = 0;
  int inverted = 0;            // non-degenerate faces with a negative scaled Jacobian
  int degenerate =
      0;  // faces with a scaled Jacobian of exactly 0, corners ~coincident or ~collinear
  int base_complex_faces = 0;  // patches of the base complex

  // Against a reference surface (−1 / 0 when none was given).
  double hausdorff = -1;           // max distance from the quad mesh to the reference
  double hausdorff_relative = -1;  // hausdorff / the reference's bounding-box diagonal
  // Faces whose normal opposes the reference's: the sum of its unit normals at the closest
  // points of the face's corners.
  int flipped = 0;
};

// Measures `mesh`; with `reference`, also the one-sided Hausdorff distance from the quad mesh
// (sampled at vertices, edge midpoints and face centres) to the reference triangles, and the
// faces that face away from the reference.
QuadMeshMetrics measure_quad_mesh(const QuadMesh& mesh, const TriangleMesh* reference = nullptr);

// Per quad of `mesh`, the base-complex patch it lies in (0 … base_complex_faces − 1, numbered
// in the order of their first quads): the pieces left when every separatrix is cut — traced
// from each singular vertex straight through regular interior vertices until it reaches a
// singular or border vertex — together with the border and non-manifold edges. The patches
// measure_quad_mesh counts.
std::vector<int> base_complex_patches(const QuadMesh& mesh);

// What keeps a quad mesh measured as `quads` from having the topology of the triangle mesh
// `surface` it remeshes, in words ("" when nothing does): not manifold, another Euler
// characteristic, another number of border loops. A remesher checks this before it hands a
// mesh out: a quantization may glue two patches back to back (a "pillow" of two quads on the
// same four vertices) where the layout did not foresee it.
std::string topology_difference(const QuadMeshMetrics& quads, const TriangleMesh& surface);

}  // namespace bimdf
