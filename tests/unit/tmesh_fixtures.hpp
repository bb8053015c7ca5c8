// Test meshes for the quad T-mesh tests (issue 21): regular grids, tori, the cube and its
// Catmull–Clark subdivisions, linear subdivision, seeded random meshes and a mesh with a
// deliberate thin strip. Every function is deterministic (the random ones depend on their
// seed only) and returns consistently oriented (counter-clockwise seen from outside),
// manifold, all-quad meshes; `quad_patch` is left empty.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::test {

// A polygon mesh (faces of any size ≥ 3, counter-clockwise): the input of Catmull–Clark.
struct PolyMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> faces;
};

PolyMesh to_poly(const QuadMesh& mesh);

// An open w × h grid of unit quads in the plane z = 0: vertex y·(w+1) + x at (x, y, 0),
// quad y·w + x = (v(x,y), v(x+1,y), v(x+1,y+1), v(x,y+1)). No irregular vertex; its four
// corners have border valence 2 and emit no trace, so the motorcycle graph is empty and the
// whole grid is one patch.
QuadMesh grid_mesh(int w, int h);

// A closed w × h grid on a torus (radii 3 and 1): vertex y·w + x, quad y·w + x joins (x, y) to
// (x+1, y+1) with x wrapping mod w; the row above y = h − 1 is row 0 shifted by `shift`
// columns, so shift ≠ 0 makes the grid lines helical. Every vertex has valence 4. Adjacent
// quads' normals differ by about 360/w or 360/h degrees: use w, h ≥ 12 and |shift| ≤ w/2 for
// no sharp edge at the default 35° (a strong shear sharpens the inner equator: 15 × 11 with
// shift 7 has sharp rows there).
QuadMesh torus_mesh(int w, int h, int shift = 0);

// The cube [−1, 1]³: 8 vertices, 6 quads.
QuadMesh cube_mesh();

// One Catmull–Clark step (any polygon mesh, border allowed: border edge points are midpoints,
// border vertices move along the border, border corners of one face stay). The result is all
// quads: for each face f and each corner i of it, the quad (vertex point, edge point of the
// edge leaving it, face point of f, edge point of the edge entering it), in face order.
// Vertices: the input's vertex points first (same ids), then edge points, then face points.
QuadMesh catmull_clark(const PolyMesh& mesh);
QuadMesh catmull_clark(const QuadMesh& mesh);

// The cube after `levels` ≥ 1 Catmull–Clark steps: 6·4^levels quads, exactly 8 irregular
// vertices (valence 3, the cube's corners, ids 0..7), every other vertex of valence 4.
// Dihedral angles: 40.7°–43.3° at level 1 (every edge sharp at the default 35°: pass
// sharp_angle_deg ≥ 45 for the 6-patch layout), at most 26.5° at level 2, 13.9° at 3, 7.1° at 4.
QuadMesh subdivided_cube(int levels);

// Each quad split into k × k quads (bilinear positions); shared edges get the same new
// vertices. The input's vertices keep their ids; k = 1 returns a copy.
QuadMesh linear_subdivision(const QuadMesh& mesh, int k);

// A random small quad mesh, deterministic in `seed`. Three in four are planar (z = 0): a
// 2..5 × 2..5 grid of cells, perhaps without one corner cell (a reflex border corner), with
// random cells split into two triangles along a random diagonal and random pairs of cells
// merged into hexagons; then one Catmull–Clark step (irregular vertices: triangle centres 3,
// hexagon centres 6, split and merged vertices…). The others are built on an n-gon, n = 3..6:
// a closed prism after one Catmull–Clark step (every edge sharp at the default 35°) or two
// (smooth), an open tube of 1..3 rings after one step (border valence 3 everywhere, no seed
// unless features: annuli that tracing must cut; only `with_tubes`, else a smoothed prism
// again), or a cup (one cap) after two. Finally k × k
// linear subdivision, k ∈ {1, 2, 3} (at most 2 after two steps). At most ~1300 quads.
// `description` (if given) receives a short summary for test messages.
QuadMesh random_quad_mesh(uint64_t seed, std::string* description = nullptr,
                          bool with_tubes = false);

// A planar, open "staircase" with a deliberate thin strip: the 10 × 8 grid of unit cells
// without the lower-left 3 × 3 block and the upper-right 3 × 4 block. Its two reflex border
// corners, A = (3, 3) and B = (7, 4) (border valence 4, so seeds), lie one row apart: A's
// trace to the right along y = 3 and B's trace to the left along y = 4 bound, with A's upward
// and B's downward traces, a patch 4 quads long and 1 quad wide (x in 3..7, y in 3..4).
// Vertex (x, y) is at (x, y, 0); thin_strip_vertex gives its id.
QuadMesh thin_strip_mesh();
int thin_strip_vertex(int x, int y);

// The w × h grid (as grid_mesh) folded along the line x = fold_x (0 < fold_x < w) by
// `angle_deg`: the part x ≥ fold_x is rotated about that line, so the edges on it have that
// dihedral angle and every other edge none.
QuadMesh folded_grid(int w, int h, int fold_x, double angle_deg);

}  // namespace bimdf::test
