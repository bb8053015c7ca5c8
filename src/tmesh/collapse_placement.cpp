// The placement of collapse_and_tessellate's points (tmesh/collapser.hpp): T-mesh vertices and
// arc points along the input's chains, patch interiors as Coons patches in the input grid's
// coordinates (shifted along zips), irregular patches by Tutte's embedding.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tmesh/collapser.hpp"
#include "tmesh/irregular_patch.hpp"

namespace bimdf::tmesh::detail {

// T-mesh vertices at their mesh vertex (or their own position), arc points at their fraction
// of the arc's chain counted in mesh edges (exact when the length equals the chain's), or of
// the straight arc.
void Collapser::place_vertices_and_arcs() {
  point_position.assign(num_points, Vec3{0, 0, 0});
  for (int v = 0; v < tm.num_vertices(); ++v) {
    const int m =
        v < static_cast<int>(tm.vertex_mesh_vertex.size()) ? tm.vertex_mesh_vertex[v] : -1;
    point_position[v] =
        mesh && m >= 0 && m < mesh->num_vertices() ? mesh->vertices[m] : tm.vertices[v];
  }
  for (int a = 0; a < tm.num_arcs(); ++a) {
    const int64_t x = len[a];
    const std::vector<int>* chain =
        mesh && a < static_cast<int>(tm.arc_chain.size()) && tm.arc_chain[a].size() >= 2
            ? &tm.arc_chain[a]
            : nullptr;
    if (chain && zipped && zipped->on_zip(a)) {
      // Both sides' points at the mean of their places on the line; so are the T-mesh
      // vertices inside it (T-junctions moved along it).
      for (int64_t k = 0; k <= x; ++k)
        if ((k > 0 && k < x) || zipped->inside(a, k))
          point_position[arc_point(a, k)] = zipped->arc_point(*mesh, a, k);
      continue;
    }
    for (int64_t k = 1; k < x; ++k) {
      Vec3& at = point_position[arc_point(a, k)];
      if (!chain) {
        at = lerp(point_position[tm.arc_ends[a][0]], point_position[tm.arc_ends[a][1]],
                  double(k) / double(x));
        continue;
      }
      const int64_t n = static_cast<int64_t>(chain->size()) - 1;
      const int64_t edge = k * n / x, rest = k * n % x;
      at = rest == 0 ? mesh->vertices[(*chain)[edge]]
                     : lerp(mesh->vertices[(*chain)[edge]], mesh->vertices[(*chain)[edge + 1]],
                            double(rest) / double(x));
    }
  }
}

// The patch grid coordinate (u, v) of output position `position` on side k of patch p: where
// a zero arc puts several points at one position, the middle of their coordinates.
Vec2 Collapser::side_coordinate(int p, int k, int64_t position) const {
  const PatchGrid& g = tm.patch_grid[p];
  double lo = 0, hi = 0, input = 0;
  int64_t out = 0;
  bool found = false;
  for (int h : tm.patch_sides[p][k]) {
    const int a = TMesh::arc_of(h);
    const int64_t x = len[a], n = static_cast<int64_t>(tm.arc_chain[a].size()) - 1;
    if (position >= out && position <= out + x) {
      const double first = x == 0 ? input : input + double(position - out) * n / double(x);
      const double last = x == 0 ? input + n : first;
      lo = found ? std::min(lo, first) : first;
      hi = found ? std::max(hi, last) : last;
      found = true;
    }
    out += x, input += n;
  }
  const double c = (lo + hi) / 2;
  switch (k) {
    case 0:
      return {c, 0};
    case 1:
      return {double(g.width), c};
    case 2:
      return {g.width - c, double(g.height)};
    default:
      return {0, g.height - c};
  }
}

// The shifts of a patch's sides by the zips along them (zip_placement.hpp), as grid vectors
// per side position, blended so that the four sides agree at the corners: a side's own shift
// along a zip, plus what its corners' shifts leave, linearly between them. Empty when no zip
// shifts the patch.
std::array<std::vector<Vec2>, 4> Collapser::side_shifts(int p) const {
  std::array<std::vector<Vec2>, 4> shift;
  if (!zipped || !has_grid(p)) return shift;
  static constexpr std::array<Vec2, 4> kDirection{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
  bool any = false;
  for (int k = 0; k < 4; ++k) {
    const int64_t length = side_length(p, k);
    shift[k].assign(length + 1, Vec2{0, 0});
    std::vector<char> set(length + 1, 0);
    int64_t out = 0;
    for (int h : tm.patch_sides[p][k]) {
      const int64_t x = len[TMesh::arc_of(h)];
      for (int64_t q = 0; q <= x; ++q) {
        if (set[out + q]) continue;
        set[out + q] = 1;
        const double d = zipped->shift(h, q);
        any = any || d != 0;
        shift[k][out + q] = {d * kDirection[k][0], d * kDirection[k][1]};
      }
      out += x;
    }
  }
  if (!any) return {};
  std::array<Vec2, 4> corner;  // corner k: where side k starts and side k − 1 ends
  for (int k = 0; k < 4; ++k) {
    const Vec2& start = shift[k].front();
    const Vec2& end = shift[(k + 3) % 4].back();
    corner[k] = {start[0] + end[0], start[1] + end[1]};
  }
  for (int k = 0; k < 4; ++k) {
    const size_t n = shift[k].size() - 1;
    const Vec2 first = shift[k].front(), last = shift[k].back();
    for (size_t i = 0; i <= n; ++i) {
      const double t = n > 0 ? double(i) / double(n) : 0;
      for (int d = 0; d < 2; ++d)
        shift[k][i][d] +=
            (1 - t) * (corner[k][d] - first[d]) + t * (corner[(k + 1) % 4][d] - last[d]);
    }
  }
  return shift;
}

// The points of arcs off the zips on a shifted patch's sides: shifted with it, so that an arc
// meeting a moved T-junction bends towards it rather than the quads beside it shearing.
void Collapser::shift_sides_off_zips(int p, const std::array<std::vector<Vec2>, 4>& shift) {
  for (int k = 0; k < 4; ++k) {
    int64_t out = 0;
    for (int h : tm.patch_sides[p][k]) {
      const int a = TMesh::arc_of(h);
      const int64_t x = len[a];
      if (!zipped->on_zip(a))
        for (int64_t q = 1; q < x; ++q) {
          const Vec2 uv = side_coordinate(p, k, out + q);
          const Vec2& d = shift[k][out + q];
          point_position[half_arc_point(h, q)] =
              detail::point_on_grid(*mesh, tm.patch_grid[p], {uv[0] + d[0], uv[1] + d[1]});
        }
      out += x;
    }
  }
}

// Patch p's grid points' coordinates in its input grid, row by row ((W+1) · (H+1)): side
// points at their side coordinates, corners at the mean of their two sides' (they differ where
// zero arcs meet there), interior points on the Coons patch over the sides; along zips, plus
// the Coons patch of the sides' shifts (side_shifts; empty: none).
std::vector<Vec2> Collapser::grid_coordinates(int p,
                                              const std::array<std::vector<Vec2>, 4>& shift) const {
  const int W = static_cast<int>(size[p][0]), H = static_cast<int>(size[p][1]);
  std::vector<Vec2> bottom(W + 1), top(W + 1), left(H + 1), right(H + 1);
  for (int i = 0; i <= W; ++i)
    bottom[i] = side_coordinate(p, 0, i), top[i] = side_coordinate(p, 2, W - i);
  for (int j = 0; j <= H; ++j)
    right[j] = side_coordinate(p, 1, j), left[j] = side_coordinate(p, 3, H - j);
  if (!shift[0].empty()) {
    const auto add = [](Vec2& a, const Vec2& d) { a = {a[0] + d[0], a[1] + d[1]}; };
    for (int i = 0; i <= W; ++i) add(bottom[i], shift[0][i]), add(top[i], shift[2][W - i]);
    for (int j = 0; j <= H; ++j) add(right[j], shift[1][j]), add(left[j], shift[3][H - j]);
  }
  std::vector<Vec2> uv(size_t(W + 1) * (H + 1));
  const auto at = [&](int i, int j) -> Vec2& { return uv[size_t(j) * (W + 1) + i]; };
  for (int j = 0; j <= H; ++j)
    for (int i = 0; i <= W; ++i) {
      const bool side_i = i == 0 || i == W, side_j = j == 0 || j == H;
      if (side_i && side_j) {
        const Vec2& a = j == 0 ? bottom[i] : top[i];
        const Vec2& b = i == 0 ? left[j] : right[j];
        at(i, j) = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
      } else if (side_j) {
        at(i, j) = j == 0 ? bottom[i] : top[i];
      } else if (side_i) {
        at(i, j) = i == 0 ? left[j] : right[j];
      } else {
        at(i, j) = coons(bottom, top, left, right, i, j);
      }
    }
  return uv;
}

// Interior grid points of a non-degenerate patch: at their grid coordinates (grid_coordinates,
// kept in grid_uv for CollapsedMesh::quad_grid_uv), evaluated on the input quad there — or,
// without a grid, a Coons patch in 3D.
void Collapser::place_patch_interior(int p) {
  const int W = static_cast<int>(size[p][0]), H = static_cast<int>(size[p][1]);
  const std::array<std::vector<Vec2>, 4> shift = side_shifts(p);
  if (!shift[0].empty()) shift_sides_off_zips(p, shift);
  const std::vector<int>& ids = grid[p];
  const auto id = [&](int i, int j) { return ids[size_t(j) * (W + 1) + i]; };
  if (has_grid(p)) {
    grid_uv[p] = grid_coordinates(p, shift);
    for (int j = 1; j < H; ++j)
      for (int i = 1; i < W; ++i)
        point_position[id(i, j)] =
            detail::point_on_grid(*mesh, tm.patch_grid[p], grid_uv[p][size_t(j) * (W + 1) + i]);
    return;
  }
  if (W < 2 || H < 2) return;
  // Without a grid: the mean position of the points at each side position.
  const auto side_positions = [&](int k) {
    const int64_t length = size[p][k % 2];
    std::vector<Vec3> sum(length + 1, Vec3{0, 0, 0});
    std::vector<int> count(length + 1, 0);
    int64_t out = 0;
    for (int h : tm.patch_sides[p][k]) {
      const int64_t x = len[TMesh::arc_of(h)];
      for (int64_t i = 0; i <= x; ++i) {
        const Vec3& q = point_position[half_arc_point(h, i)];
        for (int d = 0; d < 3; ++d) sum[out + i][d] += q[d];
        ++count[out + i];
      }
      out += x;
    }
    for (size_t s = 0; s < sum.size(); ++s)
      for (int d = 0; d < 3; ++d) sum[s][d] /= count[s];
    return sum;
  };
  std::vector<Vec3> bottom = side_positions(0), right = side_positions(1);
  std::vector<Vec3> top = side_positions(2), left = side_positions(3);
  std::reverse(top.begin(), top.end());
  std::reverse(left.begin(), left.end());
  for (int j = 1; j < H; ++j)
    for (int i = 1; i < W; ++i) point_position[id(i, j)] = coons(bottom, top, left, right, i, j);
}

// An irregular patch's pattern interior: Tutte's embedding with the boundary at the side
// points, in the patch grid's coordinates (then on the input quad there) or in 3D.
void Collapser::place_irregular_interior(int p) {
  const quant::QuadPattern& pat = pattern[p];
  const bool on_grid = has_grid(p);
  std::vector<Vec3> boundary;
  for (int k = 0; k < 4; ++k)
    for (int s = 0; s < pat.sides[k]; ++s) {
      const Vec2 uv = on_grid ? side_coordinate(p, k, s) : Vec2{0, 0};
      boundary.push_back(on_grid ? Vec3{uv[0], uv[1], 0}
                                 : point_position[grid[p][boundary.size()]]);
    }
  const std::vector<Vec3> inside = detail::place_pattern_interior(
      pat, boundary, on_grid ? mesh : nullptr, on_grid ? &tm.patch_grid[p] : nullptr);
  for (size_t i = 0; i < inside.size(); ++i)
    point_position[grid[p][pat.perimeter() + i]] = inside[i];
}

}  // namespace bimdf::tmesh::detail
