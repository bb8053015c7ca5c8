// A smooth cross field (4-RoSy) on a triangle mesh, aligned to feature curves and the border
// and, where the surface is clearly curved one way more than the other, to its principal
// curvature directions (issue 51, item 3) — and the field's singularities.
//
// Representation. One cross per face, constant over the face, stored as one of its four unit
// tangent directions. Crosses are compared across an edge by unfolding the two faces into one
// plane (discrete Levi-Civita transport); the field's singularities then sit at vertices.
//
// Method (Knöppel, Crane, Pinkall, Schröder 2013, "Globally optimal direction fields", in its
// face-based form). A cross of angle θ is the complex number u = e^{4iθ}, so its four directions
// are one value and the smoothness energy Σ_e w_e |u_g − r_e u_f|² (r_e the transport across
// edge e, w_e the edge's dual weight) is a Hermitian quadratic form. Faces on a feature curve or
// the border are fixed to the curve's direction. The rest minimizes smoothness plus
// (1/L²)·Σ_f A_f c_f |u_f − q_f|²: one sparse symmetric solve. q_f is the principal-curvature
// cross of the shape operator (Cohen-Steiner & Morvan's edge-based one) after it has diffused
// over a few edge lengths, so that the mesh's small bumps do not steer the field; c_f ∈ [0, 1]
// grows with how much more the surface bends one way than the other there. A piece with
// neither a fixed face nor curvature to follow gets the smoothest field: the eigenvector of the
// smallest eigenvalue, by inverse iteration. Defaults were chosen on the 23 shared models
// (docs/standalone_remesher.md): the fields' interior singularities are within 1.16× of the
// singular vertices of QuadWild's final meshes on every one.
//
// Singularities. Going once around a vertex, the field turns relative to the transport by
// Σ δ_e (δ_e: the jump across edge e, reduced to (−π/4, π/4]) while transport itself turns by
// the angle defect K (2π − Σ corner angles inside, π − Σ angles on the border, where the
// border's direction closes the loop). The vertex's index is (Σ δ + K) / 2π, a multiple of 1/4:
// +1/4 is a valence-3 singularity, −1/4 a valence-5 one. The indices of all vertices sum to the
// Euler characteristic (Poincaré–Hopf with border; field_indices checks it).
#pragma once

#include <array>
#include <vector>

#include "bimdf/layout/features.hpp"
#include "bimdf/mesh.hpp"

namespace bimdf::layout {

struct CrossFieldOptions {
  // The alignment length L, as a multiple of the mesh's average edge length: curvature pulls
  // with weight c_f/L², c_f = min(1, |κ1 − κ2|·L). Larger: smoother fields, curvature followed
  // only where it is strong. > 0.
  double alignment_length = 1;
  // Follow principal curvature directions at all (features and the border are always
  // followed).
  bool align_to_curvature = true;
  // The scale at which curvature is measured, as a multiple of the average edge length: the
  // shape operator diffuses over about this distance before its directions are read, so bumps
  // smaller than it do not steer the field. 0: the one-ring operator.
  double curvature_scale = 6;
  // Rounds of pulling the field towards unit length (cross_field.cpp), with strength 1/ℓ² per
  // unit area, ℓ = unit_pull average edge lengths: its singularities spread apart instead of
  // crowding where the linear solve lets it vanish. 0 rounds: the linear solve alone.
  int unit_rounds = 10;
  double unit_pull = 3;
};

struct CrossField {
  // Per face: one of the cross's four directions, a unit vector in the face's plane.
  std::vector<std::array<double, 3>> direction;
  // Per face: fixed to a feature curve or the border.
  std::vector<bool> fixed;
  // Per face: how strongly curvature pulled it (c_f above, 0 where not aligned to curvature).
  std::vector<double> curvature_weight;
  // Pieces (connected components) that had nothing to align to and got the smoothest field.
  int smoothest_components = 0;
};

// Computes the field. The mesh must be manifold and oriented (prepare_surface).
CrossField compute_cross_field(const TriangleMesh& mesh, const Features& features,
                               const CrossFieldOptions& options);

struct FieldSingularity {
  int vertex = -1;
  int quarter_index = 0;  // the index × 4: +1 valence 3, −1 valence 5, +2 valence 2, …
  bool on_border = false;
};

struct FieldIndices {
  std::vector<int> quarter_index;  // per vertex, the index × 4 (0 at regular vertices)
  // Vertices of non-zero index. On the border the index is measured against the border's own
  // direction, so a right-angled border corner has +1 (a quad corner) and a straight border 0.
  std::vector<FieldSingularity> singularities;
  int quarter_index_sum = 0;  // = 4 × the Euler characteristic, always (the index theorem)
  // The largest distance of a vertex's Σ δ + K from a multiple of π/2, in radians: rounding
  // noise only (a larger value means the field is not a cross field on this mesh).
  double max_rounding = 0;
};

// Index of every vertex under `field` (see the header comment). `matching_offset` (per edge of
// the mesh's SurfaceTopology, or empty): quarter turns added to the field's jump across each
// edge, in the orientation of the edge's first half-edge — each counts +1 quarter of index at
// that half-edge's head and −1 at its tail (layout/singularity_pairs.hpp moves singularities
// so).
FieldIndices field_indices(const TriangleMesh& mesh, const CrossField& field,
                           const std::vector<int>& matching_offset = {});

// QuadWild's `.rosy` text: the face count, `4`, then one direction per face (`x y z`).
std::string to_rosy(const CrossField& field);

}  // namespace bimdf::layout
