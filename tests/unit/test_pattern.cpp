// Quad patterns (quant/pattern.hpp): every admissible side vector gets an all-quad disk with
// exactly the prescribed boundary and convex quads; regular side vectors get the regular
// pattern, checked against the closed-form quad count and singularity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "bimdf/quant/pattern.hpp"

namespace bimdf::quant {
namespace {

// Calls f on every side vector with k sides in [1, max_side], even perimeter ≥ 4.
template <typename F>
void for_each_side_vector(int k, int max_side, F f) {
  std::vector<int> l(k, 1);
  while (true) {
    int sum = 0;
    for (int x : l) sum += x;
    if (sum % 2 == 0 && sum >= 4) f(l);
    int i = 0;
    while (i < k && l[i] == max_side) l[i++] = 1;
    if (i == k) return;
    ++l[i];
  }
}

// Independent check of the pattern's topology and geometry; returns "" or what is wrong.
std::string check_pattern(const QuadPattern& p) {
  const int perimeter = p.perimeter();
  const int n = p.num_vertices();
  std::map<std::pair<int, int>, int> directed;
  for (const auto& q : p.quads) {
    for (int a = 0; a < 4; ++a) {
      if (q[a] < 0 || q[a] >= n) return "vertex id out of range";
      if (!directed.emplace(std::pair{q[a], q[(a + 1) % 4]}, 1).second)
        return "directed edge used twice (non-manifold or flipped)";
    }
    if (std::set<int>(q.begin(), q.end()).size() != 4) return "quad repeats a vertex";
  }
  int edges = 0;
  std::set<std::pair<int, int>> boundary;
  for (const auto& [e, one] : directed) {
    if (directed.count({e.second, e.first})) {
      edges += e.first < e.second;
    } else {
      boundary.insert(e);
      ++edges;
    }
  }
  std::set<std::pair<int, int>> ring;
  for (int v = 0; v < perimeter; ++v) ring.insert({v, (v + 1) % perimeter});
  if (boundary != ring) return "boundary is not the ring 0…P−1";
  if (n - edges + static_cast<int>(p.quads.size()) != 1) return "Euler characteristic is not 1";
  for (const auto& q : p.quads) {
    for (int a = 0; a < 4; ++a) {
      const auto& u = p.positions[q[(a + 3) % 4]];
      const auto& v = p.positions[q[a]];
      const auto& w = p.positions[q[(a + 1) % 4]];
      if ((v[0] - u[0]) * (w[1] - v[1]) - (v[1] - u[1]) * (w[0] - v[0]) < -1e-9)
        return "quad is not convex";
    }
  }
  // Boundary vertices evenly spaced on the sides of pattern_polygon.
  const int k = static_cast<int>(p.sides.size());
  const auto polygon = pattern_polygon(p.sides);
  int v = 0;
  for (int j = 0; j < k; ++j)
    for (int t = 0; t < p.sides[j]; ++t, ++v) {
      const auto &a = polygon[j], &b = polygon[(j + 1) % k];
      const double f = double(t) / p.sides[j];
      if (std::abs(p.positions[v][0] - (a[0] + f * (b[0] - a[0]))) > 1e-9 ||
          std::abs(p.positions[v][1] - (a[1] + f * (b[1] - a[1]))) > 1e-9)
        return "boundary vertex " + std::to_string(v) + " is misplaced";
    }
  return "";
}

// Valence of every vertex (number of distinct neighbours).
std::vector<int> valences(const QuadPattern& p) {
  std::vector<std::set<int>> neighbours(p.num_vertices());
  for (const auto& q : p.quads)
    for (int a = 0; a < 4; ++a) {
      neighbours[q[a]].insert(q[(a + 1) % 4]);
      neighbours[q[(a + 1) % 4]].insert(q[a]);
    }
  std::vector<int> out;
  for (const auto& s : neighbours) out.push_back(static_cast<int>(s.size()));
  return out;
}

TEST(QuadPattern, EverySmallSideVectorGetsAValidPattern) {
  std::map<PatternKind, int> kinds;
  for (int k = 3; k <= 6; ++k) {
    for_each_side_vector(k, k <= 4 ? 7 : 5, [&](const std::vector<int>& l) {
      const QuadPattern p = make_quad_pattern(l);
      ++kinds[p.kind];
      std::string sides;
      for (int x : l) sides += " " + std::to_string(x);
      ASSERT_EQ(check_pattern(p), "") << "sides" << sides;
      ASSERT_EQ(p.sides, l);
    });
  }
  // The fan is a last resort that these sizes never need.
  EXPECT_EQ(kinds[PatternKind::Fan], 0);
  EXPECT_GT(kinds[PatternKind::Cut], 0);
  EXPECT_GT(kinds[PatternKind::Regular], 0);
}

TEST(QuadPattern, PolygonHasTheSideLengthsOnACircle) {
  int exact = 0;
  for (int k = 3; k <= 6; ++k)
    for_each_side_vector(k, 7, [&](const std::vector<int>& l) {
      const auto c = pattern_polygon(l);
      ASSERT_EQ(static_cast<int>(c.size()), k);
      int sum = 0, longest = 0;
      for (int x : l) sum += x, longest = std::max(longest, x);
      // Strictly convex and counter-clockwise.
      for (int j = 0; j < k; ++j) {
        const auto &a = c[j], &b = c[(j + 1) % k], &d = c[(j + 2) % k];
        ASSERT_GT((b[0] - a[0]) * (d[1] - b[1]) - (b[1] - a[1]) * (d[0] - b[0]), 1e-9);
      }
      if (2 * longest > 0.9 * sum) return;  // blended towards equal sides
      ++exact;
      // Side lengths l_j, corners on one circle (the circumcentre of the first three).
      const auto &p = c[0], &q = c[1], &r = c[2];
      const double d = 2 * (p[0] * (q[1] - r[1]) + q[0] * (r[1] - p[1]) + r[0] * (p[1] - q[1]));
      const double p2 = p[0] * p[0] + p[1] * p[1], q2 = q[0] * q[0] + q[1] * q[1],
                   r2 = r[0] * r[0] + r[1] * r[1];
      const double ux = (p2 * (q[1] - r[1]) + q2 * (r[1] - p[1]) + r2 * (p[1] - q[1])) / d;
      const double uy = (p2 * (r[0] - q[0]) + q2 * (p[0] - r[0]) + r2 * (q[0] - p[0])) / d;
      const double radius = std::hypot(p[0] - ux, p[1] - uy);
      for (int j = 0; j < k; ++j) {
        const auto &a = c[j], &b = c[(j + 1) % k];
        EXPECT_NEAR(std::hypot(b[0] - a[0], b[1] - a[1]), l[j], 1e-9);
        EXPECT_NEAR(std::hypot(a[0] - ux, a[1] - uy), radius, 1e-9);
      }
    });
  EXPECT_GT(exact, 1000);
}

TEST(QuadPattern, RegularSideVectorsGetTheRegularPattern) {
  int regular = 0;
  for (int k = 3; k <= 6; ++k) {
    for_each_side_vector(k, k <= 4 ? 8 : 11 - k, [&](const std::vector<int>& l) {
      // Oracle: every strip vector with l_j = e_{j−1} + e_{j+1}, found by choosing e_0 and e_1
      // and propagating e_{j+1} = l_j − e_{j−1} around the cycle.
      std::vector<int> found;
      int solutions = 0;
      if (k != 4) {
        for (int e0 = 0; e0 <= 12; ++e0)
          for (int e1 = 0; e1 <= 12; ++e1) {
            std::vector<int> e(k);
            e[0] = e0, e[1] = e1;
            for (int j = 1; j + 1 < k; ++j) e[j + 1] = l[j] - e[j - 1];
            bool ok = true;
            for (int j = 0; j < k && ok; ++j)
              ok = e[j] >= 0 && l[j] == e[(j + k - 1) % k] + e[(j + 1) % k];
            if (ok) ++solutions, found = e;
          }
      }
      const QuadPattern p = make_quad_pattern(l);
      const std::vector<int> v = valences(p);
      int expected_quads = 0;
      if (k == 4) {
        if (l[0] != l[2] || l[1] != l[3]) return;
        expected_quads = l[0] * l[1];
      } else {
        if (solutions == 0) return;
        ASSERT_EQ(solutions, 1);
        int zero_runs = 0;
        for (int j = 0; j < k; ++j) zero_runs += found[j] == 0 && found[(j + k - 1) % k] != 0;
        if (zero_runs > 1) return;  // would pinch: not a regular pattern
        ASSERT_EQ(regular_strip_counts(l), found);
        for (int j = 0; j < k; ++j) expected_quads += found[j] * found[(j + k - 1) % k];
      }
      ++regular;
      ASSERT_EQ(p.kind, PatternKind::Regular);
      ASSERT_EQ(static_cast<int>(p.quads.size()), expected_quads);
      // Singularities: none for grids; one interior vertex of valence k when every strip
      // count is positive.
      std::map<int, int> interior_valences;
      for (int x = p.perimeter(); x < p.num_vertices(); ++x) ++interior_valences[v[x]];
      if (k == 4) {
        EXPECT_EQ(interior_valences.size(), interior_valences.count(4));
      } else if (std::find(found.begin(), found.end(), 0) == found.end()) {
        EXPECT_EQ(interior_valences[k], 1);
        EXPECT_EQ(interior_valences.size(), 1u + interior_valences.count(4));
      }
    });
  }
  EXPECT_GT(regular, 500);
}

TEST(QuadPattern, IrregularPatternsStayNearlyRegular) {
  // Side vectors one emergency unit away from regular: a quad with one side 2 longer than its
  // opposite, a triangle violating its triangle inequality, a pentagon with two neighbouring
  // sides one longer. Each gets at most four interior singularities.
  for (const std::vector<int>& l : std::vector<std::vector<int>>{
           {4, 3, 6, 3}, {5, 5, 7, 5}, {2, 2, 6}, {1, 1, 4}, {3, 3, 3, 3, 3, 5}, {6, 4, 4, 4}}) {
    const QuadPattern p = make_quad_pattern(l);
    ASSERT_EQ(check_pattern(p), "");
    EXPECT_EQ(p.kind, PatternKind::Cut);
    const std::vector<int> v = valences(p);
    int singular = 0;
    for (int x = p.perimeter(); x < p.num_vertices(); ++x) singular += v[x] != 4;
    EXPECT_LE(singular, 4) << l[0] << " " << l[1] << " " << l[2];
  }
}

TEST(QuadPattern, RejectsSideVectorsWithoutPattern) {
  const auto message = [](const std::vector<int>& l) -> std::string {
    try {
      make_quad_pattern(l);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message({2, 2}), "quad pattern: 2 sides, expected 3 to 6");
  EXPECT_EQ(message({1, 1, 1, 1, 1, 1, 2}), "quad pattern: 7 sides, expected 3 to 6");
  EXPECT_EQ(message({2, 0, 2}), "quad pattern: side 1 has length 0, expected at least 1");
  EXPECT_EQ(message({2, 2, 1}), "quad pattern: perimeter 5, expected an even number of at least 4");
  EXPECT_EQ(message({1, 1, 1, 1, 1, 1}), "no error");
}

}  // namespace
}  // namespace bimdf::quant
