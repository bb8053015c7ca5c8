// What a solver returns (and the JSON solution format carries, docs/formats.md §3).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bimdf {

enum class SolveStatus {
  Optimal,     // a verified flow of minimum cost
  Feasible,    // a verified flow; optimality not proven (approximation, or a limit was hit)
  Infeasible,  // proven: no flow satisfies bounds and conservation (the stats say why)
  Unbounded,   // reserved: validated problems are never unbounded (every cost has a minimum)
};
std::string_view status_name(SolveStatus status);  // "optimal", "feasible", …

using StatValue = std::variant<bool, int64_t, double, std::string>;

struct Solution {
  SolveStatus status = SolveStatus::Feasible;
  double objective = 0;                    // Σ cost(flow), recomputed in double; NaN if none
  std::vector<int64_t> flow;               // one value per edge, input order; empty if none
  std::map<std::string, StatValue> stats;  // timings, counts, paths taken, reasons
};

}  // namespace bimdf
