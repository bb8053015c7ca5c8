// collapse_and_tessellate (tmesh/collapse.hpp). Every output vertex starts as a *point*: a
// T-mesh vertex, an interior point of an arc, or an interior grid point of a patch. Zero arcs
// and zero-width patches identify points (union–find); the classes are the output vertices.
// Points are numbered T-mesh vertices first, then arc points arc by arc, then patch points
// patch by patch, so that everything below is deterministic. Irregular patches (relaxed
// quantization) take their pattern from tmesh/irregular_patch.hpp; the finished mesh is
// checked by tmesh/collapse_check.hpp. The state is tmesh/collapser.hpp; where points go,
// collapse_placement.cpp.
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

#include "tmesh/collapse_check.hpp"
#include "tmesh/collapser.hpp"
#include "tmesh/irregular_patch.hpp"

namespace bimdf::tmesh {
namespace detail {

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

}  // namespace detail

using detail::Collapser;
using detail::UnionFind;

CollapsedMesh collapse_and_tessellate(const TMesh& tmesh, const TMeshIncidence& incidence,
                                      const std::vector<int64_t>& arc_length, const QuadMesh* mesh,
                                      bool allow_irregular, const std::vector<Zip>& zips) {
  Collapser c{tmesh, incidence, arc_length,      mesh, {}, {}, {}, 0, {},
              {},    {},        allow_irregular, {},   {}};
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
  c.grid_uv.resize(np);
  for (int p = 0; p < np; ++p)
    if (c.irregular(p))
      c.place_irregular_interior(p);
    else if (!c.grid[p].empty())
      c.place_patch_interior(p);
  if (mesh) {
    result.quad_grid_uv.assign(out.num_quads(), {});
    for (int q = 0; q < out.num_quads(); ++q) {
      const int p = out.quad_patch[q];
      if (c.grid_uv[p].empty() || c.irregular(p)) {
        result.quad_grid_uv[q].fill({-1, -1});
        continue;
      }
      const auto [i, j] = quad_cell[q];
      const int64_t W = c.size[p][0];
      const std::array<std::array<int, 2>, 4> corner{
          {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
      for (int k = 0; k < 4; ++k)
        result.quad_grid_uv[q][k] = c.grid_uv[p][size_t(corner[k][1]) * (W + 1) + corner[k][0]];
    }
  }
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
