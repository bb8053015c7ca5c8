#include "milp_model.hpp"

#include <Cbc_C_Interface.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace bimdf::testing {

MilpResult solve_milp(const Problem& p, int64_t window_lower, int64_t window_upper,
                      double time_limit_s, int64_t radius) {
  MilpResult result;
  result.window_lower = window_lower;
  result.window_upper = window_upper;
  std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)> model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setAllowableGap(m, 0.0);
  Cbc_setAllowableFractionGap(m, 0.0);
  Cbc_setParameter(m, "integerTolerance", "1e-9");
  if (time_limit_s > 0) Cbc_setMaximumSeconds(m, time_limit_s);

  const int edges = p.num_edges();
  std::vector<int64_t> lo(edges), hi(edges);
  for (int e = 0; e < edges; ++e) {
    lo[e] = p.lower[e] == -kInfinity ? std::min(window_lower, p.upper[e]) : p.lower[e];
    hi[e] = p.upper[e] == kInfinity ? std::max(window_upper, lo[e]) : p.upper[e];

    Cbc_addCol(m, "", static_cast<double>(lo[e]), static_cast<double>(hi[e]), 0.0, 1, 0, nullptr,
               nullptr);
  }
  for (int e = 0; e < edges; ++e) Cbc_addCol(m, "", -1e30, 1e30, 1.0, 0, 0, nullptr, nullptr);
  // Conservation.
  std::vector<std::vector<std::pair<int, double>>> rows(p.num_nodes());
  for (int e = 0; e < edges; ++e) {
    rows[p.end_a[e].node].push_back({e, static_cast<double>(p.end_a[e].sign())});
    if (!p.is_outer(e))
      rows[p.end_b[e].node].push_back({e, static_cast<double>(p.end_b[e].sign())});
  }
  for (int v = 0; v < p.num_nodes(); ++v) {
    std::vector<int> cols;
    std::vector<double> coefs;
    for (const auto& [e, c] : rows[v]) {
      auto it = std::find(cols.begin(), cols.end(), e);
      if (it == cols.end()) {
        cols.push_back(e);
        coefs.push_back(c);
      } else {
        coefs[it - cols.begin()] += c;  // loops: ±2
      }
    }
    Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), 'E',
               static_cast<double>(p.demand[v]));
  }
  // Epigraphs: t_e − slope·x_e ≥ c(k) − slope·k, one row per slope change (pieces of equal
  // slope are the same row).
  for (int e = 0; e < edges; ++e) {
    const int cols[2] = {edges + e, e};
    if (lo[e] == hi[e]) {
      const double one[1] = {1.0};
      Cbc_addRow(m, "", 1, cols, one, 'G', p.cost[e](lo[e]));
      continue;
    }
    auto pieces = [&](int64_t from, int64_t to, bool add) {
      int64_t count = 0;
      double last_slope = NAN;
      for (int64_t k = from; k < to; ++k) {
        const double ck = p.cost[e](k), slope = p.cost[e](k + 1) - ck;
        if (slope == last_slope) continue;
        last_slope = slope;
        ++count;
        if (!add) continue;
        const double coefs[2] = {1.0, -slope};
        Cbc_addRow(m, "", 2, cols, coefs, 'G', ck - slope * static_cast<double>(k));
      }
      return count;
    };
    // Curved costs over a long range would need a row per integer: limit those to the cost's
    // minimizer ± radius when asked to.
    if (radius > 0 && pieces(lo[e], hi[e], false) > 2 * radius + 1) {
      const int64_t a = p.cost[e].argmin(lo[e], hi[e]);
      lo[e] = std::max(lo[e], a - radius);
      hi[e] = std::min(hi[e], a + radius);
      Cbc_setColLower(m, e, static_cast<double>(lo[e]));
      Cbc_setColUpper(m, e, static_cast<double>(hi[e]));
    }
    pieces(lo[e], hi[e], true);
  }
  Cbc_solve(m);
  if (Cbc_isProvenInfeasible(m)) return result;
  if (!Cbc_isProvenOptimal(m)) {
    if (time_limit_s <= 0) throw std::runtime_error("CBC did not prove optimality");
    result.proven = false;
    if (Cbc_bestSolution(m) == nullptr) return result;  // nothing found in time
  }
  const double* x = result.proven ? Cbc_getColSolution(m) : Cbc_bestSolution(m);
  result.feasible = true;
  result.flow.resize(edges);
  for (int e = 0; e < edges; ++e) result.flow[e] = std::llround(x[e]);
  result.objective = 0;
  for (int e = 0; e < edges; ++e) result.objective += p.cost[e](result.flow[e]);
  return result;
}

}  // namespace bimdf::testing
