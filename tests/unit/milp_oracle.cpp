#include "milp_oracle.hpp"

#include <Cbc_C_Interface.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace bimdf::testing {

MilpResult solve_milp(const Problem& p, int64_t window_lower, int64_t window_upper) {
  MilpResult result;
  result.window_lower = window_lower;
  result.window_upper = window_upper;
  std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)> model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setAllowableGap(m, 0.0);
  Cbc_setAllowableFractionGap(m, 0.0);
  Cbc_setParameter(m, "integerTolerance", "1e-9");

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
    if (!p.is_outer(e)) rows[p.end_b[e].node].push_back({e, static_cast<double>(p.end_b[e].sign())});
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
  // Epigraphs: t_e − slope·x_e ≥ c(k) − slope·k.
  for (int e = 0; e < edges; ++e) {
    const int cols[2] = {edges + e, e};
    if (lo[e] == hi[e]) {
      const double one[1] = {1.0};
      Cbc_addRow(m, "", 1, cols, one, 'G', p.cost[e](lo[e]));
      continue;
    }
    for (int64_t k = lo[e]; k < hi[e]; ++k) {
      const double ck = p.cost[e](k), slope = p.cost[e](k + 1) - ck;
      const double coefs[2] = {1.0, -slope};
      Cbc_addRow(m, "", 2, cols, coefs, 'G', ck - slope * static_cast<double>(k));
    }
  }
  Cbc_solve(m);
  if (Cbc_isProvenInfeasible(m)) return result;
  if (!Cbc_isProvenOptimal(m)) throw std::runtime_error("CBC did not prove optimality");
  const double* x = Cbc_getColSolution(m);
  result.feasible = true;
  result.flow.resize(edges);
  for (int e = 0; e < edges; ++e) result.flow[e] = std::llround(x[e]);
  result.objective = 0;
  for (int e = 0; e < edges; ++e) result.objective += p.cost[e](result.flow[e]);
  return result;
}

}  // namespace bimdf::testing
