// What SurfaceSmoother (smoothing.hpp) knows that does not depend on vertex positions: the
// curves vertices slide along, the charts they move on, the mesh's adjacency and the
// closest-point trees (built on first use). Built once, shared by every run.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "bimdf/quant/tessellate.hpp"
#include "mesh/closest_point.hpp"
#include "mesh/smoothing.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::quant {

// What smoothing needs that depends only on the layout and the tessellation's connectivity,
// not on vertex positions: built once, shared by every run.
struct SurfaceSmoother::Setup {
  Setup(const Layout& layout, Tessellation& t, const std::vector<std::vector<int>>* vertex_charts);

  const Layout& layout;
  Tessellation& t;
  // Feature and border polylines (one per subside, then the joints), per vertex: the curve it
  // slides along (−1: none) and the charts it may move on (empty: fixed or on a curve).
  std::vector<std::vector<int>> curve_polylines;
  std::vector<std::vector<int>> charts;
  std::vector<int> curve;
  std::vector<std::vector<std::array<int, 3>>> corners;  // (next, opposite, previous)
  std::vector<std::vector<int>> neighbours;
  std::vector<std::vector<int>> vertex_quads;
  std::vector<std::unique_ptr<bimdf::detail::TriangleTree>> trees;  // per chart, built on first use
  std::unique_ptr<bimdf::detail::TriangleTree> surface;  // all of layout.mesh, built on first use
  // Per triangle corner of layout.mesh: the area-weighted normal of the triangles of the same
  // chart at that vertex, built on first use (see surface_normal).
  std::vector<std::array<bimdf::detail::Vec3, 3>> corner_normals;
};

// Per corner of each triangle of `mesh`: the sum of the (area-weighted) normals of the
// triangles of the same chart at that corner's vertex. Charts meet at features and borders,
// where the normal must not be blended across the crease.
std::vector<std::array<bimdf::detail::Vec3, 3>> chart_corner_normals(
    const TriangleMesh& mesh, const std::vector<int>& face_chart);

}  // namespace bimdf::quant
