// Helpers shared by the T-mesh model and JSON tests (test_tmesh_model.cpp, test_tmesh_json.cpp):
// a hand-built T-junction fixture, seeded random grid T-meshes, field-by-field comparison and
// the JSON text of a T-mesh.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh::testsupport {

// Three patches on a 2×2 quad grid (mesh vertex (x, y) = 3y + x): a tall patch P0 on the left,
// P1 and P2 stacked on the right. Their shared corner, vertex 7, lies inside P0's side 1: a
// T-junction. Every outer arc is a border arc.
//
//   6 ---a5--- 5 ---a4--- 4
//   |          |          |
//   a6   P0    a8   P2    a3
//   |          |          |
//   |          7 ---a9--- 3
//   |          |          |
//   |          a7   P1    a2
//   |          |          |
//   0 ---a0--- 1 ---a1--- 2
inline TMesh t_junction_tmesh() {
  TMesh t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0},
                {2, 2, 0}, {1, 2, 0}, {0, 2, 0}, {1, 1, 0.1}};
  t.vertex_mesh_vertex = {0, 1, 2, 5, 8, 7, 6, 4};
  t.arc_ends = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 0}, {1, 7}, {7, 5}, {7, 3}};
  t.arc_target = {1.25, 0.75, 1, 1, 0.75, 1.25, 2.5, 1.1, 0.9, 0.8};
  t.arc_chain = {{0, 1}, {1, 2}, {2, 5}, {5, 8}, {8, 7}, {7, 6}, {6, 3, 0}, {1, 4}, {4, 7}, {4, 5}};
  t.arc_feature = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  t.patch_sides = {{{{0}, {14, 16}, {10}, {12}}},  // 0 → 1 → 7 → 5 → 6 → 0
                   {{{2}, {4}, {19}, {15}}},       // 1 → 2 → 3 → 7 → 1
                   {{{18}, {6}, {8}, {17}}}};      // 7 → 3 → 4 → 5 → 7
  t.patch_grid = {PatchGrid{1, 2, {0, 1, 3, 4, 6, 7}}, PatchGrid{1, 1, {1, 2, 4, 5}},
                  PatchGrid{1, 1, {4, 5, 7, 8}}};
  t.nonzero_paths = {{14, 16}, {0, 2}, {18, 6}};
  return t;
}

inline void expect_same(const TMesh& a, const TMesh& b) {
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.vertex_mesh_vertex, b.vertex_mesh_vertex);
  EXPECT_EQ(a.arc_ends, b.arc_ends);
  EXPECT_EQ(a.arc_target, b.arc_target);  // exact: doubles must survive the text form
  EXPECT_EQ(a.arc_chain, b.arc_chain);
  EXPECT_EQ(a.arc_feature, b.arc_feature);
  EXPECT_EQ(a.patch_sides, b.patch_sides);
  ASSERT_EQ(a.patch_grid.size(), b.patch_grid.size());
  for (size_t p = 0; p < a.patch_grid.size(); ++p) {
    EXPECT_EQ(a.patch_grid[p].width, b.patch_grid[p].width) << "patch " << p;
    EXPECT_EQ(a.patch_grid[p].height, b.patch_grid[p].height) << "patch " << p;
    EXPECT_EQ(a.patch_grid[p].vertices, b.patch_grid[p].vertices) << "patch " << p;
  }
  EXPECT_EQ(a.nonzero_paths, b.nonzero_paths);
}

inline std::string to_json(const TMesh& t) {
  std::ostringstream out;
  bimdf::tmesh::write_tmesh_json(out, t);
  return out.str();
}

// A k×l grid of patches over a quad mesh whose columns and rows are 1–3 quads wide; some
// horizontally adjacent patches are merged, which turns the vertical arc between them into
// T-junctions above and below. Arcs are randomly oriented, so both half-arc parities occur.
inline TMesh random_grid_tmesh(std::mt19937& rng, bool geometry, int& border_half_arcs) {
  std::uniform_int_distribution<int> size(1, 4), quads(1, 3), coin(0, 1);
  std::uniform_real_distribution<double> real(-10, 10), target(0, 6);
  const int k = size(rng), l = size(rng);
  border_half_arcs = 2 * (k + l);
  std::vector<int> x0 = {0}, y0 = {0};  // mesh coordinate where column i / row j starts
  for (int i = 0; i < k; ++i) x0.push_back(x0.back() + quads(rng));
  for (int j = 0; j < l; ++j) y0.push_back(y0.back() + quads(rng));
  const int mesh_width = x0.back() + 1;
  auto mesh_vertex = [&](int x, int y) { return y * mesh_width + x; };
  auto vertex = [&](int i, int j) { return j * (k + 1) + i; };

  TMesh t;
  for (int j = 0; j <= l; ++j)
    for (int i = 0; i <= k; ++i) {
      t.vertices.push_back({real(rng), real(rng), real(rng)});
      if (geometry) t.vertex_mesh_vertex.push_back(mesh_vertex(x0[i], y0[j]));
    }
  // merged[j][i]: the patch in row j continues from column i to column i + 1.
  std::vector<std::vector<bool>> merged(l, std::vector<bool>(k, false));
  for (int j = 0; j < l; ++j)
    for (int i = 0; i + 1 < k; ++i) merged[j][i] = coin(rng) && coin(rng);
  const bool features = coin(rng);
  // Adds the arc from grid point (i, j) one step right (or up) and returns its half-arc in
  // that direction.
  auto add_arc = [&](int i, int j, bool right) {
    const int i2 = right ? i + 1 : i, j2 = right ? j : j + 1;
    std::vector<int> chain;
    for (int y = y0[j]; y <= y0[j2]; ++y)
      for (int x = x0[i]; x <= x0[i2]; ++x) chain.push_back(mesh_vertex(x, y));
    const bool flip = coin(rng);
    if (flip) std::reverse(chain.begin(), chain.end());
    const int a = t.num_arcs();
    t.arc_ends.push_back(flip ? std::array<int, 2>{vertex(i2, j2), vertex(i, j)}
                              : std::array<int, 2>{vertex(i, j), vertex(i2, j2)});
    t.arc_target.push_back(target(rng));
    if (geometry) t.arc_chain.push_back(chain);
    if (features) t.arc_feature.push_back(static_cast<uint8_t>(coin(rng)));
    return 2 * a + (flip ? 1 : 0);
  };
  std::vector<std::vector<int>> horizontal(l + 1, std::vector<int>(k));  // (i, j) → (i + 1, j)
  for (int j = 0; j <= l; ++j)
    for (int i = 0; i < k; ++i) horizontal[j][i] = add_arc(i, j, true);
  std::vector<std::vector<int>> vertical(l, std::vector<int>(k + 1, -1));  // (i, j) → (i, j + 1)
  for (int j = 0; j < l; ++j)
    for (int i = 0; i <= k; ++i)
      if (i == 0 || i == k || !merged[j][i - 1]) vertical[j][i] = add_arc(i, j, false);
  for (int j = 0; j < l; ++j)
    for (int i = 0; i < k;) {
      int i2 = i + 1;
      while (i2 < k && merged[j][i2 - 1]) ++i2;
      std::array<std::vector<int>, 4> sides;
      for (int c = i; c < i2; ++c) sides[0].push_back(horizontal[j][c]);
      sides[1] = {vertical[j][i2]};
      for (int c = i2 - 1; c >= i; --c) sides[2].push_back(TMesh::opposite(horizontal[j + 1][c]));
      sides[3] = {TMesh::opposite(vertical[j][i])};
      t.patch_sides.push_back(sides);
      if (geometry) {
        PatchGrid g{x0[i2] - x0[i], y0[j + 1] - y0[j], {}};
        for (int y = y0[j]; y <= y0[j + 1]; ++y)
          for (int x = x0[i]; x <= x0[i2]; ++x) g.vertices.push_back(mesh_vertex(x, y));
        t.patch_grid.push_back(std::move(g));
      }
      i = i2;
    }
  // Non-zero paths: random runs along rows and up the left column.
  std::uniform_int_distribution<int> row(0, l), column(0, k - 1);
  for (int n = coin(rng) + coin(rng); n > 0; --n) {
    const int j = row(rng), a = column(rng), b = column(rng);
    std::vector<int> path;
    for (int c = std::min(a, b); c <= std::max(a, b); ++c) path.push_back(horizontal[j][c]);
    t.nonzero_paths.push_back(path);
  }
  if (coin(rng)) {
    std::vector<int> path;
    for (int j = 0; j < l; ++j) path.push_back(vertical[j][0]);
    t.nonzero_paths.push_back(path);
  }
  return t;
}

}  // namespace bimdf::tmesh::testsupport
