// Small matching problems for the perfect matching tests: a plain graph, its optimum by
// enumeration, random instances, and a run of our solver checked for a perfect matching.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/blossom_matching.hpp"
#include "backend/perfect_matching.hpp"

namespace bimdf::testing {

using bimdf::detail::BlossomMatching;

struct Graph {
  int n = 0;
  std::vector<int> a, b;
  std::vector<int64_t> w;
};

// Largest weight over all perfect matchings, or nullopt: vertex 0 (the lowest unmatched) tries
// every partner.
inline std::optional<int64_t> brute_force(const Graph& g) {
  std::vector<char> used(g.n, 0);
  std::optional<int64_t> best;
  std::function<void(int64_t)> go = [&](int64_t sum) {
    int v = 0;
    while (v < g.n && used[v]) ++v;
    if (v == g.n) {
      if (!best || sum > *best) best = sum;
      return;
    }
    used[v] = 1;
    for (size_t e = 0; e < g.a.size(); ++e) {
      const int u = g.a[e] == v ? g.b[e] : g.b[e] == v ? g.a[e] : -1;
      if (u < 0 || used[u]) continue;
      used[u] = 1;
      go(sum + g.w[e]);
      used[u] = 0;
    }
    used[v] = 0;
  };
  go(0);
  return best;
}

inline Graph random_graph(std::mt19937& rng, int n, int m, int max_weight) {
  Graph g;
  g.n = n;
  for (int k = 0; k < m; ++k) {
    const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
    if (a == b) continue;
    g.a.push_back(a);
    g.b.push_back(b);
    g.w.push_back(static_cast<int64_t>(rng() % (2 * max_weight + 1)) - max_weight);
  }
  return g;
}

// Runs the solver; checks that the matching is perfect, uses only edges `enabled` allows
// (empty: all), and returns its weight.
inline std::optional<int64_t> solve(const Graph& g, BlossomMatching& solver,
                                    const std::vector<char>& enabled = {}) {
  if (solver.run() != BlossomMatching::Status::Optimal) return std::nullopt;
  const std::vector<char> matched = solver.matched_edges();
  std::vector<int> degree(g.n, 0);
  int64_t sum = 0;
  for (size_t e = 0; e < matched.size(); ++e)
    if (matched[e]) {
      EXPECT_TRUE(enabled.empty() || enabled[e]) << "disabled edge " << e << " matched";
      ++degree[g.a[e]];
      ++degree[g.b[e]];
      sum += g.w[e];
    }
  for (int v = 0; v < g.n; ++v) EXPECT_EQ(degree[v], 1) << "vertex " << v;
  EXPECT_EQ(sum, solver.matching_weight());
  return sum;
}

// The weight of LEMON's maximum-weight perfect matching (the independent oracle), or nullopt.
inline std::optional<int64_t> lemon_optimum(const Graph& g) {
  bimdf::detail::MatchingGraph mg;
  mg.num_nodes = g.n;
  mg.end_a = g.a;
  mg.end_b = g.b;
  for (int64_t w : g.w) mg.weight.push_back(static_cast<double>(w));
  const std::optional<std::vector<char>> m = bimdf::detail::max_weight_perfect_matching(mg);
  if (!m) return std::nullopt;
  int64_t sum = 0;
  for (size_t e = 0; e < g.w.size(); ++e) sum += (*m)[e] ? g.w[e] : 0;
  return sum;
}

// The message of the std::invalid_argument `call` throws, or "no exception".
template <typename Call>
std::string invalid_argument_message(Call call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace bimdf::testing
