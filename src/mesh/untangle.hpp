// The untangling step of smoothing: the position of one vertex, within a disk of its tangent
// plane, that maximizes the smallest corner area of its quads (Freitag and Plassmann's local
// untangling, "Local optimization-based simplicial mesh untangling and improvement", 2000,
// carried over to quads). Every corner's signed area, measured against a fixed normal per quad,
// is linear in the vertex's position, so the best position is the optimum of a small linear
// program in (x, y, t): maximize t subject to area_i(x, y) ≥ t. Unlike a search among sampled
// positions it finds the exact optimum, and so the untangled position whenever one exists.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::detail {

// An orthonormal frame (t1, t2) of the plane of the quads `quads` at a vertex (their summed
// Newell normal), or nothing when that normal vanishes.
std::optional<std::array<std::array<double, 3>, 2>> tangent_frame(const QuadMesh& mesh,
                                                                  const std::vector<int>& quads);

// The mean distance from `at` to the vertices `neighbours`: the scale of a vertex's moves.
double mean_distance(const QuadMesh& mesh, const std::vector<int>& neighbours,
                     const std::array<double, 3>& at);

// Among the points p = at + x·t1 + y·t2 with x² + y² ≤ radius² (t1, t2 orthonormal), the one
// at which the smallest signed corner area of the quads `quads` of `mesh` (all containing
// vertex `v`; quad f's corners signed by `normals[f]`, each divided by the product of its
// two edge lengths at the current position so that corners weigh like scaled Jacobians) is
// largest. Only corners whose area depends on v count. nullopt when no quad has such a corner.
// The disk is approximated by a regular 16-gon.
std::optional<std::array<double, 3>> max_min_corner_position(
    const QuadMesh& mesh, int v, const std::vector<int>& quads,
    const std::vector<std::array<double, 3>>& normals, const std::array<double, 3>& t1,
    const std::array<double, 3>& t2, double radius);

// The untangling energy of a quad: the sum over its corners of the corner's condition number
// (|e1|² + |e2|²) / (2·det), where det = (e1 × e2)·normal is replaced by the regularization
// h(det) = (det + √(det² + 4δ²)) / 2 with δ = `delta`·|e1|·|e2| (Escobar et al., "Simultaneous
// untangling and smoothing of tetrahedral meshes", 2003). h is positive everywhere, so the
// energy is finite for inverted corners too and falls as they straighten: minimizing it
// untangles, and for valid quads (det ≫ δ) it is the usual shape energy (2 for a square
// corner). Scale-invariant; a corner with a zero-length edge has infinite energy.
// Newton's method with a backtracking line search for a local minimum of `energy` over the
// points at + x·t1 + y·t2, starting at (0, 0): derivatives by central differences with step
// 10⁻⁴·`length`, steps at most `length`/2 (a gradient step where the Hessian is not positive
// definite), at most `iterations` steps. `energy` may return +∞ for forbidden points. Returns
// the best point found (`at` when no step lowered the energy).
std::array<double, 3> descend_in_tangent_plane(
    const std::function<double(const std::array<double, 3>&)>& energy,
    const std::array<double, 3>& at, const std::array<double, 3>& t1,
    const std::array<double, 3>& t2, double length, int iterations);

double untangling_energy(const QuadMesh& mesh, const std::array<int, 4>& quad,
                         const std::array<double, 3>& normal, double delta);

}  // namespace bimdf::detail
