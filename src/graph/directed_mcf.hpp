// A directed minimum-cost flow problem as plain arrays, in LEMON's convention: supply[v] =
// outflow − inflow, lower bounds 0, capacities that may be infinite (INT64_MAX, the same value
// as bimdf::kInfinity). Costs stay double; the backend scales them (backend/min_cost_flow.hpp).
// Deliberately free of other bimdf headers: the C++17 backend includes it (DESIGN §6). It lives
// in src/graph/, below both the reductions that build it and the backends that solve it
// (DESIGN §4).
#pragma once

#include <cstdint>
#include <vector>

namespace bimdf::detail {

struct DirectedMcf {
  std::vector<int64_t> supply;  // per node: outflow − inflow
  std::vector<int> source;      // per arc
  std::vector<int> target;
  std::vector<int64_t> capacity;  // ≥ 0, or INT64_MAX for unbounded
  std::vector<double> cost;       // per unit of flow

  int num_nodes() const { return static_cast<int>(supply.size()); }
  int num_arcs() const { return static_cast<int>(source.size()); }
};

}  // namespace bimdf::detail
