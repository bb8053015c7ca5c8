// Doublet removal (src/mesh/doublets.hpp): interior vertices of valence 2 go, their two quads
// merged into one, only where allowed, off the border, and where the merge is the better quad.
#include <gtest/gtest.h>

#include "mesh/doublets.hpp"

namespace bimdf {
namespace {

// The square [0, 2]² split by v = (1, 1) on its diagonal into two quads with a 180° corner at
// v: v a x b and v b y a, with a = (0, 0), x = (2, 0), b = (2, 2), y = (0, 2). A third quad on
// the right (x, (3, 0), (3, 2), b) keeps x and b from being the only corners.
QuadMesh doublet() {
  QuadMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}, {3, 0, 0}, {3, 2, 0}};
  m.quads = {{4, 0, 1, 2}, {1, 5, 6, 2}, {4, 2, 3, 0}};
  m.quad_patch = {7, 8, 9};
  return m;
}

TEST(Doublets, AValenceTwoVertexGoesAndItsQuadsMerge) {
  QuadMesh m = doublet();
  std::vector<int> renumber;
  EXPECT_EQ(detail::remove_doublets(m, std::vector<char>(7, 1), renumber), 1);
  EXPECT_EQ(renumber, (std::vector<int>{0, 1, 2, 3, -1, 4, 5}));
  ASSERT_EQ(m.num_vertices(), 6);
  // The merged quad a x b y takes the first quad's place and patch.
  EXPECT_EQ(m.quads, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {1, 4, 5, 2}}));
  EXPECT_EQ(m.quad_patch, (std::vector<int>{7, 8}));
  EXPECT_EQ(m.vertices[4], (std::array<double, 3>{3, 0, 0}));
}

TEST(Doublets, AVertexThatMustStayStays) {
  QuadMesh m = doublet();
  std::vector<char> may_go(7, 1);
  may_go[4] = 0;  // e.g. on a feature curve
  std::vector<int> renumber;
  EXPECT_EQ(detail::remove_doublets(m, may_go, renumber), 0);
  EXPECT_EQ(m.num_quads(), 3);
  // On the border: only the first quad, v has valence 1 there; and a corner of two quads on
  // the border (valence 2 there is a straight border vertex) stays too.
  QuadMesh border = doublet();
  border.quads.pop_back();
  border.quad_patch.pop_back();
  EXPECT_EQ(detail::remove_doublets(border, std::vector<char>(7, 1), renumber), 0);
  EXPECT_EQ(border.num_quads(), 2);
}

TEST(Doublets, NoMergeThatMakesTheWorseQuadWorse) {
  // A closed book: two near-unit squares on the spine a–v–b, 90° at v in both, their far
  // corners x and y almost on top of each other. Each quad is fine (scaled Jacobian 0.98); the
  // merged quad a x b y would be a sliver, so v stays.
  QuadMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2}, {1, 1, -0.2}};  // v a b x y
  m.quads = {{0, 1, 3, 2}, {0, 2, 4, 1}};
  std::vector<int> renumber;
  EXPECT_EQ(detail::remove_doublets(m, std::vector<char>(5, 1), renumber), 0);
  EXPECT_EQ(m.num_quads(), 2);
  // Opened flat, y beyond v: the second quad has a reflex corner at v and the merged kite
  // a x b y is better, so v goes.
  m.vertices[4] = {-1, -1, 0};
  m.quads = {{0, 1, 3, 2}, {0, 2, 4, 1}};
  EXPECT_EQ(detail::remove_doublets(m, std::vector<char>(5, 1), renumber), 1);
  EXPECT_EQ(m.quads, (std::vector<std::array<int, 4>>{{0, 2, 1, 3}}));
}

}  // namespace
}  // namespace bimdf
