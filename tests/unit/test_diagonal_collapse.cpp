// Diagonal collapse of inverted quads (src/mesh/diagonal_collapse.hpp): an inverted quad goes
// by merging two opposite corners, only where the vertex that goes may go, the mesh stays
// manifold and the quads around get better.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/diagonal_collapse.hpp"
#include "mesh/quad_quality.hpp"

namespace bimdf {
namespace {

// The 3 × 3 grid of unit squares on [0, 3]² (vertex i + 4 j at (i, j)) with vertex 10, at
// (2, 2), dragged to (1.25, 1.25): the centre quad 5 6 10 9 has a reflex corner there.
QuadMesh dented_grid() {
  QuadMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.vertices.push_back({double(i), double(j), 0});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int v = i + 4 * j;
      m.quads.push_back({v, v + 1, v + 5, v + 4});
      m.quad_patch.push_back(i + 3 * j);
    }
  m.vertices[10] = {1.25, 1.25, 0};
  return m;
}

double worst(const QuadMesh& m) {
  double w = 2;
  for (const auto& q : m.quads) w = std::min(w, detail::scaled_jacobian(m, q));
  return w;
}

TEST(DiagonalCollapse, AnInvertedQuadGoesAndNoneIsLeft) {
  QuadMesh m = dented_grid();
  ASSERT_LT(detail::scaled_jacobian(m, m.quads[4]), 0);
  std::vector<int> renumber, merged;
  EXPECT_EQ(detail::collapse_inverted_quads(m, std::vector<char>(16, 1), renumber, merged), 1);
  EXPECT_EQ(m.num_quads(), 8);
  EXPECT_EQ(m.num_vertices(), 15);
  EXPECT_EQ(std::count(renumber.begin(), renumber.end(), -1), 1);
  // The centre quad's patch is gone; the others keep theirs, in order.
  EXPECT_EQ(m.quad_patch, (std::vector<int>{0, 1, 2, 3, 5, 6, 7, 8}));
  // The merged vertex is one of the centre quad's corners and now has 4 + 4 − 2 quads.
  ASSERT_EQ(merged.size(), 1u);
  int quads_at_merged = 0;
  for (const auto& q : m.quads) quads_at_merged += std::count(q.begin(), q.end(), merged[0]);
  EXPECT_EQ(quads_at_merged, 6);
  const int old =
      static_cast<int>(std::find(renumber.begin(), renumber.end(), merged[0]) - renumber.begin());
  EXPECT_TRUE(old == 5 || old == 6 || old == 9 || old == 10) << old;
  EXPECT_GT(worst(m), 0);
}

TEST(DiagonalCollapse, CornersThatMustStayStay) {
  // None of the centre quad's corners may go (say, all on a feature curve): nothing changes.
  QuadMesh m = dented_grid();
  std::vector<char> may_go(16, 1);
  for (int v : {5, 6, 9, 10}) may_go[v] = 0;
  std::vector<int> renumber, merged;
  EXPECT_EQ(detail::collapse_inverted_quads(m, may_go, renumber, merged), 0);
  EXPECT_EQ(m.num_quads(), 9);
  EXPECT_TRUE(merged.empty());
}

TEST(DiagonalCollapse, NothingWithoutAnInvertedQuadOrWhereItWouldPinchTheMesh) {
  QuadMesh grid = dented_grid();
  grid.vertices[10] = {2, 2, 0};
  std::vector<int> renumber, merged;
  EXPECT_EQ(detail::collapse_inverted_quads(grid, std::vector<char>(16, 1), renumber, merged), 0);
  // A strip of two quads, the second dented: every vertex is on the border, and border
  // vertices never go (a merge there would pinch the border).
  QuadMesh strip;
  strip.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1.3, 0.3, 0}};
  strip.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  ASSERT_LT(detail::scaled_jacobian(strip, strip.quads[1]), 0);
  EXPECT_EQ(detail::collapse_inverted_quads(strip, std::vector<char>(6, 1), renumber, merged), 0);
  EXPECT_EQ(strip.num_quads(), 2);
}

TEST(DiagonalCollapse, OneCollapseOnRequestWhateverTheShapes) {
  // On the flat grid (nothing inverted) 5 takes in 10: quad 4 goes, 5 keeps its place and now
  // has six quads; the quads that had 10 have 5 instead.
  QuadMesh m = dented_grid();
  m.vertices[10] = {2, 2, 0};
  std::vector<int> renumber;
  ASSERT_TRUE(detail::collapse_diagonal(m, 4, 5, renumber));
  EXPECT_EQ(m.num_quads(), 8);
  EXPECT_EQ(renumber[10], -1);
  EXPECT_EQ(renumber[5], 5);
  EXPECT_EQ(renumber[11], 10);
  EXPECT_EQ(m.quads[4], (std::array<int, 4>{6, 7, 10, 5}));  // was 6 7 11 10
  EXPECT_EQ(m.vertices[5], (std::array<double, 3>{1, 1, 0}));
  // Corner 0 of quad 0 is on the border with one quad: 5 into 0 would leave 1 and 4 with one
  // quad each; refused, nothing changed.
  QuadMesh grid = dented_grid();
  EXPECT_FALSE(detail::collapse_diagonal(grid, 0, 0, renumber));
  EXPECT_EQ(grid.num_quads(), 9);
  EXPECT_THROW(detail::collapse_diagonal(grid, 0, 15, renumber), std::invalid_argument);
}

}  // namespace
}  // namespace bimdf
