// The collapse and tessellation of collapse_and_tessellate (tmesh/collapse.hpp), internal to
// src/tmesh: its state (points, their classes' positions, patch grids) shared by the numbering
// and checks (collapse.cpp) and the placement of points (collapse_placement.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "bimdf/quant/pattern.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "core/union_find.hpp"
#include "tmesh/zip_placement.hpp"

namespace bimdf::tmesh::detail {

using Vec3 = std::array<double, 3>;
using Vec2 = std::array<double, 2>;

// More points than this would not fit the int vertex ids of QuadMesh comfortably.
constexpr int64_t kMaxPoints = int64_t{1} << 28;

using UnionFind = bimdf::detail::SmallestRootUnionFind;

template <size_t N>
std::array<double, N> lerp(const std::array<double, N>& a, const std::array<double, N>& b,
                           double t) {
  std::array<double, N> r;
  for (size_t d = 0; d < N; ++d) r[d] = a[d] + t * (b[d] - a[d]);
  return r;
}

// Coons patch at grid index (i, j) of a W × H grid from its four boundary curves, each given
// at every grid index: bottom[i] (j = 0), top[i] (j = H), left[j] (i = 0), right[j] (i = W).
// Where two curves disagree at a corner (zero arcs there), the corner is their mean.
template <size_t N>
std::array<double, N> coons(const std::vector<std::array<double, N>>& bottom,
                            const std::vector<std::array<double, N>>& top,
                            const std::vector<std::array<double, N>>& left,
                            const std::vector<std::array<double, N>>& right, int i, int j) {
  const int W = static_cast<int>(bottom.size()) - 1, H = static_cast<int>(left.size()) - 1;
  const double s = double(i) / W, t = double(j) / H;
  std::array<double, N> r;
  for (size_t d = 0; d < N; ++d) {
    const double c00 = (bottom[0][d] + left[0][d]) / 2, c10 = (bottom[W][d] + right[0][d]) / 2;
    const double c01 = (top[0][d] + left[H][d]) / 2, c11 = (top[W][d] + right[H][d]) / 2;
    r[d] = (1 - t) * bottom[i][d] + t * top[i][d] + (1 - s) * left[j][d] + s * right[j][d] -
           ((1 - s) * (1 - t) * c00 + s * (1 - t) * c10 + (1 - s) * t * c01 + s * t * c11);
  }
  return r;
}

struct Collapser {
  const TMesh& tm;
  const TMeshIncidence& inc;
  const std::vector<int64_t>& len;
  const QuadMesh* mesh;

  std::vector<std::array<int64_t, 2>> size;  // per patch: width (side 0), height (side 1)
  std::vector<int> arc_first, patch_first;   // first interior point of each arc / patch
  int num_points = 0;
  std::vector<Vec3> point_position;
  // Per non-degenerate patch: point ids, (W+1) × (H+1) — or, for an irregular patch, one per
  // vertex of its pattern.
  std::vector<std::vector<int>> grid;
  // Per non-degenerate patch with a grid: grid_coordinates of its grid points (else empty).
  std::vector<std::vector<Vec2>> grid_uv;
  bool allow_irregular = false;
  std::vector<quant::QuadPattern> pattern;     // per patch: its pattern if irregular (else empty)
  std::optional<detail::ZipPlacement> zipped;  // with zips and a mesh
  bool irregular(int p) const { return !pattern[p].quads.empty(); }

  int arc_point(int a, int64_t k) const {
    if (k == 0) return tm.arc_ends[a][0];
    if (k == len[a]) return tm.arc_ends[a][1];
    return arc_first[a] + static_cast<int>(k) - 1;
  }
  // Point k of half-arc h, counted from its tail.
  int half_arc_point(int h, int64_t k) const {
    const int a = TMesh::arc_of(h);
    return arc_point(a, (h & 1) ? len[a] - k : k);
  }
  int64_t side_length(int p, int k) const {
    int64_t sum = 0;
    for (int h : tm.patch_sides[p][k]) sum += len[TMesh::arc_of(h)];
    return sum;
  }
  // The points of a chain of half-arcs (a patch side, a zip's side) by position 0..length (a
  // zero arc puts both of its ends at one position; they are the same class, so either stands
  // for it).
  std::vector<int> chain_points(const std::vector<int>& chain) const {
    std::vector<int> out;
    for (int h : chain) {
      const int64_t x = len[TMesh::arc_of(h)];
      if (out.empty()) out.push_back(half_arc_point(h, 0));
      for (int64_t i = 1; i <= x; ++i) out.push_back(half_arc_point(h, i));
    }
    return out;
  }
  std::vector<int> side_points(int p, int k) const { return chain_points(tm.patch_sides[p][k]); }
  bool has_grid(int p) const {
    if (!mesh || tm.patch_grid.size() != tm.patch_sides.size() || tm.patch_grid[p].empty() ||
        tm.patch_grid[p].width < 1 || tm.patch_grid[p].height < 1)
      return false;
    for (const auto& side : tm.patch_sides[p])
      for (int h : side)
        if (TMesh::arc_of(h) >= static_cast<int>(tm.arc_chain.size()) ||
            tm.arc_chain[TMesh::arc_of(h)].size() < 2)
          return false;
    return true;
  }

  void check_input() const;
  void number_points();
  void place_vertices_and_arcs();
  void place_patch_interior(int p);
  std::vector<Vec2> grid_coordinates(int p, const std::array<std::vector<Vec2>, 4>& shift) const;
  std::array<std::vector<Vec2>, 4> side_shifts(int p) const;
  void shift_sides_off_zips(int p, const std::array<std::vector<Vec2>, 4>& shift);
  void place_irregular_interior(int p);
  Vec2 side_coordinate(int p, int k, int64_t position) const;
};

}  // namespace bimdf::tmesh::detail
