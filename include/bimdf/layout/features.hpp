// Sharp features of a triangle mesh (issue 51, item 2): the curves a quad mesh must keep as
// lines of edges — creases where the surface bends by more than an angle, or edges given in a
// file — and the corners where such curves, and the border, end, meet or turn. The cross field
// is aligned to every feature curve and to the border; the patch layout has them as patch
// borders and their corners as patch corners.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::layout {

struct FeatureOptions {
  // An interior edge is sharp where the normals of its two faces differ by more than this
  // (degrees; QuadWild's default). ≥ 180 finds none.
  double sharp_angle_deg = 35;
  // A vertex on a feature curve or the border is a corner where the curve turns by more than
  // this (degrees): a quad corner there is a right angle, a gentle bend is not one.
  double corner_angle_deg = 45;
  // Short sharp curves are noise (a scan's bumps, a sculpt's creases), not features: sharp
  // edges are eroded this many times from every dangling end, then grown back as many times
  // from the ends that erosion made (QuadWild's `feature_erode_dilate`, same default). A sharp
  // curve with a free end that is at most twice this many edges long disappears; longer curves
  // keep their full length, without the short spurs that branched off them. Also dropped,
  // since erosion cannot shrink them: the edges of triangles whose three edges are all sharp
  // (a lone spike), sets of connected sharp edges away from the border with at most twice
  // this many edges (a small loop), and the flatter side of every lens — a region of at most
  // 16 × this many triangles bounded by curves with fewer than 3 sharp turns (a crease that
  // forks and joins again). 0 keeps every sharp edge.
  int erode_dilate = 4;
};

struct Features {
  std::vector<std::array<int, 2>> sharp_edges;  // interior edges as vertex pairs (smaller first)
  // Where curves (sharp edges and border edges together) end, meet (three or more curve edges)
  // or turn by more than corner_angle_deg; sorted.
  std::vector<int> corners;
  int border_edges = 0;
};

// Sharp edges by dihedral angle (cleaned by erode_dilate), and corners. The mesh must be manifold
// and oriented (layout::prepare_surface).
Features detect_features(const TriangleMesh& mesh, const FeatureOptions& options);

// Features from given sharp edges (vertex pairs, e.g. read from a QuadWild `.feature` file by
// quant::read_feature_edges), all kept, with corners found as detect_features finds them. Pairs
// that are border edges are border edges already and are dropped; a pair that is no edge of the
// mesh throws InputError naming it, with `source` as the file.
Features features_from_edges(const TriangleMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                             const FeatureOptions& options, const std::string& source);

}  // namespace bimdf::layout
