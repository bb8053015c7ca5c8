// Random problems for round-trip and property tests: every edge kind, bounds (finite, infinite,
// fixed, negative), demands, and every cost kind, always valid (validate() passes).
#pragma once

#include <random>

#include "bimdf/problem.hpp"

namespace bimdf::testing {

struct RandomProblemOptions {
  int min_nodes = 1;
  int max_nodes = 6;
  int min_edges = 0;
  int max_edges = 10;
  bool outer_edges = true;
  bool all_cost_kinds = true;  // false: only libSatsuma's kinds (zero, abs, quad, scale, sum)
  bool names = false;
};

Cost random_cost(std::mt19937_64& rng, const RandomProblemOptions& options, int64_t lower,
                 int64_t upper, int depth = 0);
Problem random_problem(std::mt19937_64& rng, const RandomProblemOptions& options = {});

// Replaces the demands by σ·x for a random x within bounds (and within [−3, 5]), so that the
// problem is feasible — random demands rarely are.
void plant_feasible_demands(Problem& problem, std::mt19937_64& rng);

}  // namespace bimdf::testing
