// Procedural triangle meshes for the layout stages' tests (src/layout): closed and open, of
// known topology, with and without sharp edges.
#pragma once

#include "bimdf/mesh.hpp"

namespace bimdf::test {

// The icosahedron subdivided `levels` times, projected onto the unit sphere (χ = 2).
TriangleMesh icosphere(int levels);
// A torus of revolution around z, radii R > r, n segments around the axis and m around the
// tube (χ = 0).
TriangleMesh torus(double R, double r, int n, int m);
// The cube [−1, 1]³, each face an n×n grid of squares cut into two triangles (χ = 2; its 12
// edges are 90° creases).
TriangleMesh cube(int n);
// An open cylinder around z, radius 1, height h, n segments around and m along (two border
// circles, χ = 0).
TriangleMesh cylinder(double h, int n, int m);
// The square [0, w] × [0, w] in z = 0 as an n×n grid (one border loop, χ = 1); `diagonal`
// flips the cut of every other square.
TriangleMesh square(double w, int n);
// a followed by b, b's vertex ids shifted, b's vertices moved by `offset`.
TriangleMesh combine(const TriangleMesh& a, const TriangleMesh& b, double offset);

}  // namespace bimdf::test
