// Quad T-mesh quantization (tmesh/quantize.hpp): Algorithm 2's constraints imply every
// non-zero path; the exact solve equals a CBC MILP written directly on the T-mesh (integer arc
// lengths, equal opposite sides, min-one rows), sharing nothing with the Bi-MDF model; every
// result passes check_quantization; the coarse stage collapses what it may.
#include <Cbc_C_Interface.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include "bimdf/tmesh/quantize.hpp"
#include "test_helpers.hpp"

namespace bimdf::tmesh {
namespace {

// A C × R grid of cells with random column widths / row heights as targets, some horizontally
// adjacent cells merged into one patch (their shared arc removed, which leaves T-junctions),
// and random straight non-zero paths along the grid lines.
struct GridTMesh {
  TMesh tmesh;
  int columns = 0, rows = 0;
};

GridTMesh random_grid_tmesh(std::mt19937& rng, int columns, int rows, int paths) {
  GridTMesh g;
  g.columns = columns, g.rows = rows;
  TMesh& t = g.tmesh;
  const auto vertex = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) t.vertices.push_back({double(i), double(j), 0});
  std::uniform_real_distribution<double> length(0.2, 4.0);
  std::vector<double> width(columns), height(rows);
  for (double& w : width) w = length(rng);
  for (double& h : height) h = length(rng);
  // Which cells merge with their right neighbour (pairs never overlap).
  std::vector<std::vector<char>> merge(rows, std::vector<char>(columns, 0));
  std::bernoulli_distribution coin(0.3);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i + 1 < columns; ++i)
      if (coin(rng)) merge[j][i] = 1, ++i;
  const auto removed = [&](int i, int j) {  // the vertical arc at x = i in row j
    return i > 0 && i < columns && merge[j][i - 1];
  };
  std::vector<std::vector<int>> h_arc(rows + 1, std::vector<int>(columns, -1));
  std::vector<std::vector<int>> v_arc(columns + 1, std::vector<int>(rows, -1));
  const auto add_arc = [&](int a, int b, double target) {
    t.arc_ends.push_back({a, b});
    t.arc_target.push_back(target);
    return t.num_arcs() - 1;
  };
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < columns; ++i)
      h_arc[j][i] = add_arc(vertex(i, j), vertex(i + 1, j), width[i]);
  for (int i = 0; i <= columns; ++i)
    for (int j = 0; j < rows; ++j)
      if (!removed(i, j)) v_arc[i][j] = add_arc(vertex(i, j), vertex(i, j + 1), height[j]);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int last = merge[j][i] ? i + 1 : i;
      std::array<std::vector<int>, 4> sides;
      for (int k = i; k <= last; ++k) sides[0].push_back(2 * h_arc[j][k]);
      sides[1].push_back(2 * v_arc[last + 1][j]);
      for (int k = last; k >= i; --k) sides[2].push_back(2 * h_arc[j + 1][k] + 1);
      sides[3].push_back(2 * v_arc[i][j] + 1);
      t.patch_sides.push_back(sides);
      i = last;
    }
  std::uniform_int_distribution<int> pick(0, 1 << 20);
  for (int m = 0; m < paths; ++m) {
    std::vector<int> path;
    if (pick(rng) % 2) {  // horizontal, along y = j
      const int j = pick(rng) % (rows + 1), a = pick(rng) % columns, b = pick(rng) % columns;
      for (int i = std::min(a, b); i <= std::max(a, b); ++i) path.push_back(2 * h_arc[j][i]);
    } else {  // vertical, along x = i, over rows whose arc exists
      const int i = pick(rng) % (columns + 1), j0 = pick(rng) % rows;
      for (int j = j0; j < rows && v_arc[i][j] >= 0; ++j) path.push_back(2 * v_arc[i][j]);
      if (path.empty()) path.push_back(2 * h_arc[0][0]);
    }
    t.nonzero_paths.push_back(path);
  }
  return g;
}

// Whether `constraints` imply path m directly: one of its arcs, or a side (or that side's
// opposite, whose length is equal) lying wholly on the path.
bool implies_path(const TMesh& t, const MinOneConstraints& c, const std::vector<int>& path) {
  std::vector<int> arcs;
  for (int h : path) arcs.push_back(TMesh::arc_of(h));
  std::sort(arcs.begin(), arcs.end());
  const auto on_path = [&](int a) { return std::binary_search(arcs.begin(), arcs.end(), a); };
  for (int a : c.arcs)
    if (on_path(a)) return true;
  for (const SideRef& s : c.sides)
    for (int k : {s[1], (s[1] + 2) % 4}) {
      bool all = true;
      for (int h : t.patch_sides[s[0]][k]) all = all && on_path(TMesh::arc_of(h));
      if (all) return true;
    }
  return false;
}

// The optimum of the T-mesh quantization as a MILP solved by CBC: integer x_a ∈ [0, cap],
// Σ side k = Σ side k+2 per patch, and either Algorithm 2's constraints (x_a ≥ 1, Σ side ≥ 1)
// or every non-zero path's Σ x ≥ 1. The cost (x − t)² or |x − t| through an epigraph variable
// per arc, exact at integers. Returns NaN when infeasible.
double milp_optimum(const TMesh& t, DeviationCost cost, double side_weight,
                    const MinOneConstraints* constraints, int cap) {
  std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)> model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setAllowableGap(m, 0.0);
  Cbc_setAllowableFractionGap(m, 0.0);
  // Columns: arc lengths x_a, then one width w per patch and side pair (a patch's side 0 / 2
  // or 1 / 3 length, bound to both sides' sums below), then an epigraph variable for each.
  const int n = t.num_arcs(), np = t.num_patches(), vars = n + 2 * np;
  const int width_cap = cap * n;
  for (int a = 0; a < n; ++a) Cbc_addCol(m, "", 0, cap, 0, 1, 0, nullptr, nullptr);
  for (int w = 0; w < 2 * np; ++w) Cbc_addCol(m, "", 0, width_cap, 0, 1, 0, nullptr, nullptr);
  for (int v = 0; v < vars; ++v) Cbc_addCol(m, "", 0, 1e30, 1, 0, 0, nullptr, nullptr);
  std::vector<double> target(vars), weight(vars, 1);
  for (int a = 0; a < n; ++a) target[a] = t.arc_target[a];
  const auto side_target = [&](int p, int k) {
    double sum = 0;
    for (int h : t.patch_sides[p][k]) sum += t.arc_target[TMesh::arc_of(h)];
    return sum;
  };
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < 2; ++k) {
      target[n + 2 * p + k] = 0.5 * (side_target(p, k) + side_target(p, k + 2));
      weight[n + 2 * p + k] = side_weight;
    }
  const auto c = [&](int v, double x) {
    const double d = x - target[v];
    return weight[v] * (cost == DeviationCost::Quadratic ? d * d : std::fabs(d));
  };
  for (int v = 0; v < vars; ++v)
    for (int k = 0; k < (v < n ? cap : width_cap); ++k) {
      // epigraph: y_v ≥ c(k) + (c(k+1) − c(k))(x_v − k)
      const double slope = c(v, k + 1) - c(v, k);
      int cols[2] = {vars + v, v};
      double coefs[2] = {1, -slope};
      Cbc_addRow(m, "", 2, cols, coefs, 'G', c(v, k) - slope * k);
    }
  const auto add_sum = [&](const std::vector<std::pair<int, double>>& terms, char sense,
                           double rhs) {
    std::vector<int> cols;
    std::vector<double> coefs;
    for (auto [a, w] : terms) cols.push_back(a), coefs.push_back(w);
    Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), sense, rhs);
  };
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < 4; ++k) {  // side k's arcs sum to its pair's width
      std::vector<std::pair<int, double>> terms{{n + 2 * p + k % 2, -1}};
      for (int h : t.patch_sides[p][k]) terms.push_back({TMesh::arc_of(h), 1});
      add_sum(terms, 'E', 0);
    }
  if (constraints) {
    for (int a : constraints->arcs) add_sum({{a, 1}}, 'G', 1);
    for (const SideRef& s : constraints->sides) {
      std::vector<std::pair<int, double>> terms;
      for (int h : t.patch_sides[s[0]][s[1]]) terms.push_back({TMesh::arc_of(h), 1});
      add_sum(terms, 'G', 1);
    }
  } else {
    for (const auto& path : t.nonzero_paths) {
      std::vector<std::pair<int, double>> terms;
      for (int h : path) terms.push_back({TMesh::arc_of(h), 1});
      add_sum(terms, 'G', 1);
    }
  }
  Cbc_solve(m);
  if (Cbc_isProvenInfeasible(m)) return std::nan("");
  if (!Cbc_isProvenOptimal(m)) throw std::runtime_error("CBC did not prove optimality");
  const double* x = Cbc_getColSolution(m);
  double objective = 0;
  for (int v = 0; v < vars; ++v) objective += c(v, std::round(x[v]));
  return objective;
}

TEST(TMeshQuantize, AlgorithmTwoImpliesEveryPath) {
  std::mt19937 rng(7);
  int constraints = 0, paths = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const GridTMesh g = random_grid_tmesh(rng, 1 + trial % 5, 1 + (trial / 5) % 4, trial % 9);
    const TMeshIncidence inc = validate_tmesh(g.tmesh);
    const MinOneConstraints c = greedy_min_one_constraints(g.tmesh, inc);
    for (size_t m = 0; m < g.tmesh.nonzero_paths.size(); ++m)
      ASSERT_TRUE(implies_path(g.tmesh, c, g.tmesh.nonzero_paths[m]))
          << "trial " << trial << ", path " << m;
    // Never more constraints than paths: each one covers at least one new path.
    ASSERT_LE(c.size(), static_cast<int>(g.tmesh.nonzero_paths.size()));
    constraints += c.size(), paths += static_cast<int>(g.tmesh.nonzero_paths.size());
  }
  // Overlapping paths share constraints: the greedy set is smaller than one per path.
  EXPECT_LT(constraints, paths);
}

TEST(TMeshQuantize, OptimumEqualsTheMilpOracle) {
  std::mt19937 rng(11);
  int collapsed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const GridTMesh g = random_grid_tmesh(rng, 1 + trial % 4, 1 + (trial / 4) % 3, trial % 7);
    const TMesh& t = g.tmesh;
    const TMeshIncidence inc = validate_tmesh(t);
    QuantizeOptions o;
    o.cost = trial % 2 ? DeviationCost::Absolute : DeviationCost::Quadratic;
    o.side_weight = trial % 3 == 0 ? 0.0 : 1.0 + trial % 5;
    const TMeshQuantization q = quantize_tmesh(t, inc, o);
    ASSERT_EQ(q.status, SolveStatus::Optimal) << "trial " << trial;
    ASSERT_EQ(check_quantization(t, q.arc_length), "") << "trial " << trial;
    const double oracle = milp_optimum(t, o.cost, o.side_weight, &q.constraints, 12);
    ASSERT_TRUE(testing::relatively_close(q.objective, oracle))
        << "trial " << trial << ": " << q.objective << " vs CBC " << oracle;
    // Algorithm 2 only shrinks the feasible set: the exact path rows can do no worse.
    const double exact_paths = milp_optimum(t, o.cost, o.side_weight, nullptr, 12);
    ASSERT_LE(exact_paths, q.objective + 1e-9) << "trial " << trial;
    collapsed += q.zero_arcs > 0;
  }
  EXPECT_GT(collapsed, 30);  // targets down to 0.2: many T-meshes do collapse arcs
}

TEST(TMeshQuantize, CoarseLayoutCollapsesWhatThePathsAllow) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    const GridTMesh g = random_grid_tmesh(rng, 2 + trial % 3, 2 + trial % 2, 1 + trial % 4);
    const TMeshIncidence inc = validate_tmesh(g.tmesh);
    QuantizeOptions o;
    o.coarse = true;
    const TMeshQuantization q = quantize_tmesh(g.tmesh, inc, o);
    ASSERT_EQ(q.status, SolveStatus::Optimal);
    ASSERT_EQ(check_quantization(g.tmesh, q.arc_length), "");
    // The deviation stage keeps the coarse stage's zero pattern, so its zero arcs are the
    // coarse optimum's: at least as many as the plain quantization's.
    o.coarse = false;
    const TMeshQuantization fine = quantize_tmesh(g.tmesh, inc, o);
    ASSERT_GE(q.zero_arcs, fine.zero_arcs) << "trial " << trial;
    ASSERT_GE(q.objective, fine.objective - 1e-9);
  }
}

TEST(TMeshQuantize, ThinColumnCollapsesUnlessAPathCrossesIt) {
  // Three columns of one row; the middle one has width 0.3. Without paths it collapses (its
  // bottom and top arcs 0); a path along its bottom arc keeps it.
  std::mt19937 rng(1);
  GridTMesh g = random_grid_tmesh(rng, 3, 1, 0);
  TMesh& t = g.tmesh;
  // Arcs 0..2: bottom row, 3..5: top row (random_grid_tmesh numbers horizontal arcs first).
  for (int a : {0, 2, 3, 5}) t.arc_target[a] = 3;
  for (int a : {1, 4}) t.arc_target[a] = 0.3;
  TMeshIncidence inc = validate_tmesh(t);
  TMeshQuantization q = quantize_tmesh(t, inc, {});
  EXPECT_EQ(q.arc_length[1], 0);
  EXPECT_EQ(q.arc_length[4], 0);
  t.nonzero_paths = {{2 * 1}};
  inc = validate_tmesh(t);
  q = quantize_tmesh(t, inc, {});
  EXPECT_EQ(q.arc_length[1], 1);
  EXPECT_EQ(q.arc_length[4], 1);
  ASSERT_EQ(q.constraints.size(), 1);
}

TEST(TMeshQuantize, CheckNamesTheViolation) {
  std::mt19937 rng(1);
  GridTMesh g = random_grid_tmesh(rng, 1, 1, 0);
  TMesh& t = g.tmesh;  // arcs: 0 bottom, 1 top, 2 left, 3 right
  t.nonzero_paths = {{0}};
  EXPECT_EQ(check_quantization(t, {1, 2, 1, 1}), "patch 0: sides 0 and 2 have lengths 1 and 2");
  EXPECT_EQ(check_quantization(t, {0, 0, 1, 1}), "non-zero path 0 has length 0");
  EXPECT_EQ(check_quantization(t, {1, 1, -1, -1}), "arc 2: negative length -1");
  EXPECT_EQ(check_quantization(t, {1}), "expected 4 arc lengths, got 1");
  EXPECT_EQ(check_quantization(t, {2, 2, 3, 3}), "");
}

}  // namespace
}  // namespace bimdf::tmesh
