// collapse_and_tessellate (tmesh/collapse.hpp). Every output vertex starts as a *point*: a
// T-mesh vertex, an interior point of an arc, or an interior grid point of a patch. Zero arcs
// and zero-width patches identify points (union–find); the classes are the output vertices.
// Points are numbered T-mesh vertices first, then arc points arc by arc, then patch points
// patch by patch, so that everything below is deterministic. Irregular patches (relaxed
// quantization) take their pattern from tmesh/irregular_patch.hpp; the finished mesh is
// checked by tmesh/collapse_check.hpp.
#include "bimdf/tmesh/collapse.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/union_find.hpp"
#include "tmesh/collapse_check.hpp"
#include "tmesh/irregular_patch.hpp"
#include "tmesh/zip_placement.hpp"

namespace bimdf::tmesh {
namespace {

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
  std::array<std::vector<Vec2>, 4> side_shifts(int p) const;
  void shift_sides_off_zips(int p, const std::array<std::vector<Vec2>, 4>& shift);
  void place_irregular_interior(int p);
  Vec2 side_coordinate(int p, int k, int64_t position) const;
};

void Collapser::check_input() const {
  const int na = tm.num_arcs(), np = tm.num_patches();
  if (static_cast<int>(len.size()) != na)
    throw std::invalid_argument(std::to_string(len.size()) + " arc lengths for " +
                                std::to_string(na) + " arcs");
  if (static_cast<int>(inc.half_arc_patch.size()) != 2 * na)
    throw std::invalid_argument("the incidence does not belong to this T-mesh");
  for (int a = 0; a < na; ++a)
    if (len[a] < 0 || len[a] > kMaxPoints)
      throw std::invalid_argument("arc " + std::to_string(a) + ": length " +
                                  std::to_string(len[a]) + ", expected 0 to 2^28");
  for (int p = 0; p < np; ++p) {
    const std::array<int64_t, 4> x{side_length(p, 0), side_length(p, 1), side_length(p, 2),
                                   side_length(p, 3)};
    if (allow_irregular && (x[0] != x[2] || x[1] != x[3])) {
      if (const std::string issue = detail::irregular_sides_issue(x); !issue.empty())
        throw std::invalid_argument("patch " + std::to_string(p) + ": " + issue);
      continue;
    }
    for (int k = 0; k < 2; ++k)
      if (x[k] != x[k + 2])
        throw std::invalid_argument(
            "patch " + std::to_string(p) + ": sides " + std::to_string(k) + " and " +
            std::to_string(k + 2) + " have lengths " + std::to_string(side_length(p, k)) + " and " +
            std::to_string(side_length(p, k + 2)) + ", opposite sides must be equal");
  }
}

void Collapser::number_points() {
  int64_t n = tm.num_vertices();
  const auto grow = [&](int64_t extra) {
    n += extra;
    if (n > kMaxPoints)
      throw std::invalid_argument("the quantization asks for more than 2^28 quad vertices");
  };
  arc_first.resize(tm.num_arcs());
  for (int a = 0; a < tm.num_arcs(); ++a) {
    arc_first[a] = static_cast<int>(n);
    grow(std::max<int64_t>(len[a] - 1, 0));
  }
  patch_first.resize(tm.num_patches());
  size.resize(tm.num_patches());
  pattern.resize(tm.num_patches());
  for (int p = 0; p < tm.num_patches(); ++p) {
    size[p] = {side_length(p, 0), side_length(p, 1)};
    patch_first[p] = static_cast<int>(n);
    if (size[p] != std::array<int64_t, 2>{side_length(p, 2), side_length(p, 3)}) {
      // check_input let it through: allow_irregular, every side ≥ 1, even perimeter.
      pattern[p] =
          detail::irregular_pattern({size[p][0], size[p][1], side_length(p, 2), side_length(p, 3)});
      grow(pattern[p].num_vertices() - pattern[p].perimeter());
    } else if (size[p][0] > 0 && size[p][1] > 0) {
      grow((size[p][0] - 1) * (size[p][1] - 1));
    }
  }
  num_points = static_cast<int>(n);
}

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

// Interior grid points of a non-degenerate patch: a Coons patch over its sides, in the input
// grid's coordinates (then bilinear on the input quad there) or in 3D; along zips, plus the
// Coons patch of its sides' shifts.
void Collapser::place_patch_interior(int p) {
  const int W = static_cast<int>(size[p][0]), H = static_cast<int>(size[p][1]);
  const std::array<std::vector<Vec2>, 4> shift = side_shifts(p);
  if (!shift[0].empty()) shift_sides_off_zips(p, shift);
  if (W < 2 || H < 2) return;
  const std::vector<int>& ids = grid[p];
  const auto id = [&](int i, int j) { return ids[size_t(j) * (W + 1) + i]; };
  if (has_grid(p)) {
    std::vector<Vec2> bottom(W + 1), top(W + 1), left(H + 1), right(H + 1);
    for (int i = 0; i <= W; ++i)
      bottom[i] = side_coordinate(p, 0, i), top[i] = side_coordinate(p, 2, W - i);
    for (int j = 0; j <= H; ++j)
      right[j] = side_coordinate(p, 1, j), left[j] = side_coordinate(p, 3, H - j);
    std::vector<Vec2> bottom_d, top_d, left_d, right_d;
    if (!shift[0].empty()) {
      for (int i = 0; i <= W; ++i)
        bottom_d.push_back(shift[0][i]), top_d.push_back(shift[2][W - i]);
      for (int j = 0; j <= H; ++j)
        right_d.push_back(shift[1][j]), left_d.push_back(shift[3][H - j]);
    }
    for (int j = 1; j < H; ++j)
      for (int i = 1; i < W; ++i) {
        Vec2 uv = coons(bottom, top, left, right, i, j);
        if (!bottom_d.empty()) {
          const Vec2 d = coons(bottom_d, top_d, left_d, right_d, i, j);
          uv = {uv[0] + d[0], uv[1] + d[1]};
        }
        point_position[id(i, j)] = detail::point_on_grid(*mesh, tm.patch_grid[p], uv);
      }
    return;
  }
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

}  // namespace

CollapsedMesh collapse_and_tessellate(const TMesh& tmesh, const TMeshIncidence& incidence,
                                      const std::vector<int64_t>& arc_length, const QuadMesh* mesh,
                                      bool allow_irregular, const std::vector<Zip>& zips) {
  Collapser c{tmesh, incidence, arc_length, mesh, {}, {}, {}, 0, {}, {}, allow_irregular, {}, {}};
  c.check_input();
  c.number_points();
  const int np = tmesh.num_patches();
  CollapsedMesh result;
  UnionFind classes(c.num_points);
  // Two chains of points facing each other (a zero-width patch's long sides, a two-gon's
  // sides), both walked with their own face on the left: identified position by position, the
  // first from its start with the second from its end.
  const auto close_between = [&](const std::vector<int>& a, const std::vector<int>& b) {
    for (size_t s = 0; s < a.size(); ++s) classes.unite(a[s], b[b.size() - 1 - s]);
  };
  for (int a = 0; a < tmesh.num_arcs(); ++a) {
    result.zero_arcs += arc_length[a] == 0;
    if (arc_length[a] == 0) classes.unite(tmesh.arc_ends[a][0], tmesh.arc_ends[a][1]);
  }
  c.grid.resize(np);
  for (int p = 0; p < np; ++p) {
    const int64_t W = c.size[p][0], H = c.size[p][1];
    std::array<std::vector<int>, 4> side;
    for (int k = 0; k < 4; ++k) side[k] = c.side_points(p, k);
    if (c.irregular(p)) {
      ++result.irregular_patches;
      c.grid[p] = detail::pattern_points(c.pattern[p], side, c.patch_first[p]);
      continue;
    }
    if (W == 0 || H == 0) {
      // Side k (walked forward) meets side k+2 walked backwards, position by position.
      ++result.collapsed_patches;
      for (int k : {0, 1})
        if (c.size[p][1 - k] == 0) close_between(side[k], side[k + 2]);
      if (W == 0 && H == 0)
        for (int k = 1; k < 4; ++k) classes.unite(side[0][0], side[k][0]);
      continue;
    }
    std::vector<int>& g = c.grid[p];
    g.assign(size_t(W + 1) * (H + 1), -1);
    const auto at = [&](int64_t i, int64_t j) -> int& { return g[size_t(j) * (W + 1) + i]; };
    for (int64_t i = 0; i <= W; ++i) at(i, 0) = side[0][i], at(W - i, H) = side[2][i];
    for (int64_t j = 0; j <= H; ++j) at(W, j) = side[1][j], at(0, H - j) = side[3][j];
    int next = c.patch_first[p];
    for (int64_t j = 1; j < H; ++j)
      for (int64_t i = 1; i < W; ++i) at(i, j) = next++;
  }
  for (size_t z = 0; z < zips.size(); ++z) {
    std::array<std::vector<int>, 2> points;
    for (int s = 0; s < 2; ++s) {
      for (size_t i = 0; i < zips[z][s].size(); ++i) {
        const int h = zips[z][s][i];
        if (h < 0 || h >= tmesh.num_half_arcs() || !incidence.is_border(h) ||
            (i > 0 && tmesh.half_arc_head(zips[z][s][i - 1]) != tmesh.half_arc_tail(h)))
          throw std::invalid_argument("zip " + std::to_string(z) + ": half-arc " +
                                      std::to_string(h) + " is not the next border half-arc");
      }
      points[s] = c.chain_points(zips[z][s]);
    }
    if (points[0].empty() || points[0].size() != points[1].size())
      throw std::invalid_argument("zip " + std::to_string(z) + ": its sides have lengths " +
                                  std::to_string(int64_t(points[0].size()) - 1) + " and " +
                                  std::to_string(int64_t(points[1].size()) - 1));
    close_between(points[0], points[1]);
  }
  if (np > 0 && result.collapsed_patches == np)
    throw CollapseError("every patch would collapse (width or height 0): no quad is left");

  // Output vertices in order of first use by the quads, patch by patch, row by row.
  std::vector<int> vertex_of(c.num_points, -1);
  std::vector<std::array<int, 2>> quad_cell;
  QuadMesh& out = result.mesh;
  for (int p = 0; p < np; ++p) {
    const int64_t W = c.size[p][0], H = c.size[p][1];
    if (W == 0 || H == 0) continue;
    const std::vector<int>& g = c.grid[p];
    const auto vertex_of_point = [&](int point) {
      int& v = vertex_of[classes.find(point)];
      if (v < 0) v = out.num_vertices(), out.vertices.push_back({0, 0, 0});
      return v;
    };
    if (c.irregular(p)) {
      const auto& quads = c.pattern[p].quads;
      for (size_t f = 0; f < quads.size(); ++f) {
        out.quads.push_back({vertex_of_point(g[quads[f][0]]), vertex_of_point(g[quads[f][1]]),
                             vertex_of_point(g[quads[f][2]]), vertex_of_point(g[quads[f][3]])});
        out.quad_patch.push_back(p);
        quad_cell.push_back({static_cast<int>(f), -1});
      }
      continue;
    }
    const auto vertex = [&](int64_t i, int64_t j) {
      return vertex_of_point(g[size_t(j) * (W + 1) + i]);
    };
    for (int64_t j = 0; j < H; ++j)
      for (int64_t i = 0; i < W; ++i) {
        out.quads.push_back(
            {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
        out.quad_patch.push_back(p);
        quad_cell.push_back({static_cast<int>(i), static_cast<int>(j)});
      }
  }

  // Positions: every point's own, then each vertex at the mean of its points.
  if (mesh && !zips.empty()) c.zipped.emplace(tmesh, arc_length, zips);
  c.place_vertices_and_arcs();
  for (int p = 0; p < np; ++p)
    if (c.irregular(p))
      c.place_irregular_interior(p);
    else if (!c.grid[p].empty())
      c.place_patch_interior(p);
  const int nv = out.num_vertices();
  std::vector<int> class_size(nv, 0);
  std::vector<std::vector<int>> vertex_arcs(tmesh.num_vertices());
  for (int a = 0; a < tmesh.num_arcs(); ++a)
    for (int v : tmesh.arc_ends[a]) vertex_arcs[v].push_back(a);
  result.origin.resize(nv);
  const auto add_patches_of_arc = [&](CollapsedVertex& o, int a) {
    for (int h : {2 * a, 2 * a + 1})
      if (incidence.half_arc_patch[h] >= 0) o.patches.push_back(incidence.half_arc_patch[h]);
  };
  for (int q = 0; q < c.num_points; ++q) {
    const int v = vertex_of[classes.find(q)];
    if (v < 0) continue;
    ++class_size[v];
    for (int d = 0; d < 3; ++d) out.vertices[v][d] += c.point_position[q][d];
    CollapsedVertex& o = result.origin[v];
    if (q < tmesh.num_vertices()) {
      o.tmesh_vertices.push_back(q);
      for (int a : vertex_arcs[q]) o.arcs.push_back(a), add_patches_of_arc(o, a);
    } else if (q < (np > 0 ? c.patch_first[0] : c.num_points)) {
      const int a = static_cast<int>(std::upper_bound(c.arc_first.begin(), c.arc_first.end(), q) -
                                     c.arc_first.begin()) -
                    1;
      o.arcs.push_back(a), add_patches_of_arc(o, a);
      o.arc_points.push_back({a, c.point_position[q]});
    } else {
      o.patches.push_back(
          static_cast<int>(std::upper_bound(c.patch_first.begin(), c.patch_first.end(), q) -
                           c.patch_first.begin() - 1));
    }
  }
  for (int v = 0; v < nv; ++v) {
    for (int d = 0; d < 3; ++d) out.vertices[v][d] /= class_size[v];
    CollapsedVertex& o = result.origin[v];
    for (std::vector<int>* ids : {&o.patches, &o.arcs, &o.tmesh_vertices}) {
      std::sort(ids->begin(), ids->end());
      ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
    }
  }
  detail::check_result(result, quad_cell, class_size);
  return result;
}

}  // namespace bimdf::tmesh
