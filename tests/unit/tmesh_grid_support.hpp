// Shared by the quad T-mesh quantization tests (test_tmesh_quantize.cpp,
// test_tmesh_relaxed.cpp): random grid T-meshes with T-junctions and non-zero paths, and the
// CBC MILP oracle written directly on the T-mesh (sharing nothing with the Bi-MDF model).
#pragma once

#include <Cbc_C_Interface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bimdf/tmesh/half_arc.hpp"
#include "bimdf/tmesh/quantize.hpp"

namespace bimdf::tmesh::gridsupport {

// A C × R grid of cells with random column widths / row heights as targets, some horizontally
// adjacent cells merged into one patch (their shared arc removed, which leaves T-junctions),
// and random straight non-zero paths along the grid lines.
struct GridTMesh {
  TMesh tmesh;
  int columns = 0, rows = 0;
};

inline GridTMesh random_grid_tmesh(std::mt19937& rng, int columns, int rows, int paths) {
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

// The optimum of the T-mesh quantization as a MILP solved by CBC: integer x_a ∈ [0, cap],
// Σ side k = Σ side k+2 per patch, and either Algorithm 2's constraints (x_a ≥ 1, Σ side ≥ 1)
// or every non-zero path's Σ x ≥ 1. The cost (x − t)² or |x − t| through an epigraph variable
// per arc, exact at integers. Returns NaN when infeasible.
//
// With relaxed_weight ≥ 0, the relaxed quantization of §4.2.4 instead: x_a ∈ [1, cap] and four
// corner-turning variables c_k ≥ 0 per patch (k: between sides k and k+1), each costing
// relaxed_weight per unit, with Σ side k = w_(k mod 2) + c_(k−1) + c_k — side k's length is
// what crosses the patch to side k+2 plus what turns to either neighbour.
//
// With `two_gons` (the lines of an inflation of t, half_arc.hpp), the half-arc quantization
// of §4.3 instead: every arc on a line has a length per half-arc (x_h, each costing half the
// arc's deviation), sides sum their half-arcs, and along each line Σ x_h = Σ x_opposite(h);
// a line of one path has that sum ≥ 1, a line of two overlapping paths the left side's sum to
// vertex left_end ≥ 1 and the right side's from vertex right_start ≥ 1 — whatever
// `constraints` says. A bound on a cut arc applies to the half-arc on the line's left (its own
// id in the inflated T-mesh, < t.num_arcs()) or right (the right copy's id, whose arc is
// `arc_origin`'s). With reorder_weight ≥ 0 (bounded two-gons), instead of those ≥ 1 rows: per
// interior vertex i of the line, the offset Σ_{j ≤ i} (x_h_j − x_opposite(h_j)) = d⁺ − d⁻ with
// d± ≥ 0 costing reorder_weight each — or 0 where `pinned` (per line, per vertex 0..n) says so.
inline double milp_optimum(const TMesh& t, DeviationCost cost, double side_weight,
                           const MinOneConstraints* constraints, int cap,
                           double relaxed_weight = -1,
                           const std::vector<TwoGon>* two_gons = nullptr,
                           const std::vector<int>* arc_origin = nullptr, double reorder_weight = -1,
                           const std::vector<std::vector<char>>* pinned = nullptr) {
  const bool relaxed = relaxed_weight >= 0;
  // Length columns: one per arc, then one more per cut arc (its odd half-arc's).
  std::vector<int> column(t.num_half_arcs());
  for (int h = 0; h < t.num_half_arcs(); ++h) column[h] = TMesh::arc_of(h);
  std::vector<double> length_weight(t.num_arcs(), 1.0);
  std::vector<double> length_target(t.arc_target);
  if (two_gons)
    for (const TwoGon& g : *two_gons)
      for (int h : g.left) {
        const int a = TMesh::arc_of(h);
        if (column[2 * a + 1] != a) continue;
        column[2 * a + 1] = static_cast<int>(length_weight.size());
        length_weight[a] = 0.5;
        length_weight.push_back(0.5);
        length_target.push_back(t.arc_target[a]);
      }
  std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)> model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setAllowableGap(m, 0.0);
  Cbc_setAllowableFractionGap(m, 0.0);
  // Columns: arc lengths x_a, then one width w per patch and side pair (a patch's side 0 / 2
  // or 1 / 3 length, bound to both sides' sums below), then an epigraph variable for each,
  // then (relaxed) the corner variables.
  const int n = static_cast<int>(length_weight.size()), np = t.num_patches(), vars = n + 2 * np;
  const int width_cap = cap * n;
  for (int a = 0; a < n; ++a) Cbc_addCol(m, "", relaxed ? 1 : 0, cap, 0, 1, 0, nullptr, nullptr);
  for (int w = 0; w < 2 * np; ++w) Cbc_addCol(m, "", 0, width_cap, 0, 1, 0, nullptr, nullptr);
  for (int v = 0; v < vars; ++v) Cbc_addCol(m, "", 0, 1e30, 1, 0, 0, nullptr, nullptr);
  const int corners = 2 * vars;  // column of patch p's corner k: corners + 4p + k
  if (relaxed)
    for (int c = 0; c < 4 * np; ++c)
      Cbc_addCol(m, "", 0, width_cap, relaxed_weight, 1, 0, nullptr, nullptr);
  std::vector<double> target(vars), weight(vars, 1);
  for (int a = 0; a < n; ++a) target[a] = length_target[a], weight[a] = length_weight[a];
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
    for (int k = 0; k < 4; ++k) {  // side k's arcs sum to its pair's width (and its corners)
      std::vector<std::pair<int, double>> terms{{n + 2 * p + k % 2, -1}};
      if (relaxed)
        terms.push_back({corners + 4 * p + (k + 3) % 4, -1}),
            terms.push_back({corners + 4 * p + k, -1});
      for (int h : t.patch_sides[p][k]) terms.push_back({column[h], 1});
      add_sum(terms, 'E', 0);
    }
  std::vector<int> line_half(t.num_arcs(), -1);  // per cut arc: its line's half-arc
  if (two_gons)
    for (const TwoGon& g : *two_gons)
      for (int h : g.left) line_half[TMesh::arc_of(h)] = h;
  if (constraints) {
    for (int a : constraints->arcs) {
      if (a >= t.num_arcs()) {  // a right copy
        add_sum({{column[TMesh::opposite(line_half[arc_origin->at(a)])], 1}}, 'G', 1);
        continue;
      }
      add_sum({{line_half[a] >= 0 ? column[line_half[a]] : a, 1}}, 'G', 1);
    }
    for (const SideRef& s : constraints->sides) {
      std::vector<std::pair<int, double>> terms;
      for (int h : t.patch_sides[s[0]][s[1]]) terms.push_back({column[h], 1});
      add_sum(terms, 'G', 1);
    }
  } else {
    for (const auto& path : t.nonzero_paths) {
      std::vector<std::pair<int, double>> terms;
      for (int h : path) terms.push_back({column[h], 1});
      add_sum(terms, 'G', 1);
    }
  }
  int offsets = 0;  // offset columns d⁺, d⁻ follow all others
  const int first_offset = Cbc_getNumCols(m);
  if (two_gons)
    for (size_t r = 0; r < two_gons->size(); ++r) {
      const TwoGon& g = (*two_gons)[r];
      std::vector<std::pair<int, double>> both, one, left_prefix, right_suffix;
      const std::vector<int>& half_arcs = g.left;
      for (size_t i = 0; i < half_arcs.size(); ++i) {
        const int h = half_arcs[i];
        both.push_back({column[h], 1}), both.push_back({column[TMesh::opposite(h)], -1});
        one.push_back({column[h], 1});
        if (static_cast<int>(i) < g.left_end) left_prefix.push_back({column[h], 1});
        if (g.right_start >= 0 && static_cast<int>(i) >= g.right_start)
          right_suffix.push_back({column[TMesh::opposite(h)], 1});
        if (reorder_weight < 0 || i + 1 == half_arcs.size()) continue;
        if (pinned && r < pinned->size() && (*pinned)[r].size() > i + 1 && (*pinned)[r][i + 1]) {
          add_sum(both, 'E', 0);  // no drift at a pinned vertex
          continue;
        }
        for (int sign : {1, -1}) {
          Cbc_addCol(m, "", 0, 1e30, reorder_weight, 1, 0, nullptr, nullptr);
          both.push_back({first_offset + offsets++, -sign});
        }
        add_sum(both, 'E', 0);  // the offset at vertex i + 1
        both.resize(both.size() - 2);
      }
      add_sum(both, 'E', 0);
      if (reorder_weight >= 0) continue;
      if (g.paths.size() == 1) add_sum(one, 'G', 1);
      if (g.paths.size() == 2) add_sum(left_prefix, 'G', 1), add_sum(right_suffix, 'G', 1);
    }
  Cbc_solve(m);
  if (Cbc_isProvenInfeasible(m)) return std::nan("");
  if (!Cbc_isProvenOptimal(m)) throw std::runtime_error("CBC did not prove optimality");
  const double* x = Cbc_getColSolution(m);
  double objective = 0;
  for (int v = 0; v < vars; ++v) objective += c(v, std::round(x[v]));
  if (relaxed)
    for (int k = 0; k < 4 * np; ++k) objective += relaxed_weight * std::round(x[corners + k]);
  for (int k = 0; k < offsets; ++k) objective += reorder_weight * std::round(x[first_offset + k]);
  return objective;
}

}  // namespace bimdf::tmesh::gridsupport
