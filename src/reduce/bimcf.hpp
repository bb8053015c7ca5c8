// A bidirected minimum-cost flow problem (Bi-MCF, paper §3.3) as plain arrays: linear per-unit
// costs, every lower bound 0, capacities that may be kInfinity. Same sign conventions as
// Problem (problem.hpp): conservation Σ σ·y = demand at every node. Produced by linearize.hpp,
// consumed by the double cover (and, for exact refinement, the b-matching reduction).
#pragma once

#include <cstdint>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf::detail {

struct BiMcf {
  std::vector<int64_t> demand;  // per node
  std::vector<End> end_a;       // per arc; both ends always present (loops allowed)
  std::vector<End> end_b;
  std::vector<int64_t> capacity;  // > 0, or kInfinity
  std::vector<double> cost;       // per unit of flow

  int num_nodes() const { return static_cast<int>(demand.size()); }
  int num_arcs() const { return static_cast<int>(end_a.size()); }
};

}  // namespace bimdf::detail
