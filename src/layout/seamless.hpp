// A seamless parametrization aligned to a cross field (issue 51, item 4): the map whose iso-lines
// the motorcycle graph is traced along, so that separatrices that are one line of the layout
// stay one line instead of drifting past each other as streamlines of a non-integrable field do.
//
// Method. A cross field is rarely a gradient (it has curl), so its streamlines do not close up
// into a grid; the parametrization is the closest field that does (Bommes, Zimmer, Kobbelt 2009,
// "Mixed-integer quadrangulation", without the integer part). It is solved cut-free: the unknowns
// are one 2D vector per mesh edge — the edge's image in the parameter plane, in the cross frame
// of one of its faces; the other face sees it rotated by the field's matching across the edge (a
// multiple of a quarter turn). Each face asks that its edges' images close (their sum is zero)
// and that the linear map they define match the cross frame (∇u, ∇v = the cross's two
// directions): a sparse least-squares problem, closure weighted 10⁶ above fit. Rotations by
// quarter turns between faces make the map seamless: around a regular vertex the images close
// into a chart, around a singular vertex into a cone of (4 − quarter index) quarter turns, and
// the iso-lines through a point continue as iso-lines across every edge. Edges on a feature
// curve or the border have the component across the curve pulled towards zero (a weighted
// term, SeamlessOptions::curve_weight), so curves are nearly iso-lines: a hard zero folds the
// map where dihedral-angle curves zigzag across the field.
//
// What comes out, per face, is the map's two iso-line directions in 3D (∂x/∂u, along which v is
// constant, and ∂x/∂v): inside a face they are constant, so a trace that goes straight along
// one and takes the matching one in the next face follows an iso-line exactly. Faces whose map
// is folded (det ≤ 0, which least squares does not rule out near close pairs of singularities)
// are counted; tracing treats them like any other face.
#pragma once

#include <array>
#include <vector>

#include "bimdf/layout/cross_field.hpp"
#include "layout/face_frames.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

struct SeamlessMap {
  // Per face: ∂x/∂u and ∂x/∂v, tangent vectors in the face's plane (not unit: 1 / the map's
  // stretch). ways[f][0] ≈ the field's direction in f, ways[f][1] a quarter turn
  // counter-clockwise from it.
  std::vector<std::array<detail::Vec3, 2>> iso_direction;
  // Per face: ∇u and ∇v, tangent vectors in the face's plane; a 3D vector x in the face maps
  // to (∇u·x, ∇v·x) in the parameter plane.
  std::vector<std::array<detail::Vec3, 2>> gradient;
  int folded_faces = 0;        // det ≤ 0
  double max_closure = 0;      // the largest |Σ edge images| of a face over its longest edge
  double mean_distortion = 0;  // area-weighted mean of ‖J − I‖ (J in cross frames)
};

struct SeamlessOptions {
  // Rounds of local stiffening after the first solve, and the shear (‖J‖²/2det, 1 for a
  // similarity) above which a face is stiffened.
  int stiffening_rounds = 5;
  double stiffen_above = 2;
  // How strongly curve edges are pulled onto iso-lines, against the fit (1 = the same weight
  // per unit of relative error). Measured on 17 shared models: 3 and 30 gave more singular
  // vertices or lower quality than 10 on most; a hard constraint folded 12 of 23 maps.
  double curve_weight = 10;
  // Per edge (empty: none): quarter turns added to the matching the field gives across it,
  // oriented as field_indices takes them (cancel_close_pairs, singularity_pairs.hpp): the map's
  // cones are then those of field_indices(mesh, field, matching_offset).
  std::vector<int> matching_offset;
};

// `curve_edge` per edge of `top` (features and border): (nearly) iso-lines there. The field's faces
// on curves must be aligned to them (compute_cross_field fixes them so).
SeamlessMap seamless_parametrization(const SurfaceTopology& top, const FaceFrames& frames,
                                     const CrossField& field, const std::vector<bool>& curve_edge,
                                     const SeamlessOptions& options = {});

}  // namespace bimdf::layout
