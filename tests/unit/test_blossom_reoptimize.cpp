// Re-optimization of our perfect matching solver (backend/blossom_matching.hpp: update_edge,
// reopen, then run() from the kept solution) against independent oracles: enumeration on small
// graphs and LEMON's solver on larger ones, over many rounds of changes, each compared with
// the changed graph solved from scratch.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "backend/blossom_matching.hpp"
#include "matching_test_support.hpp"

namespace {

using bimdf::detail::BlossomMatching;
using bimdf::testing::Graph;

// The graph without its disabled edges (what the solver must answer for).
Graph enabled_part(const Graph& g, const std::vector<char>& enabled) {
  Graph out;
  out.n = g.n;
  for (size_t e = 0; e < g.a.size(); ++e)
    if (enabled[e]) {
      out.a.push_back(g.a[e]);
      out.b.push_back(g.b[e]);
      out.w.push_back(g.w[e]);
    }
  return out;
}

std::optional<int64_t> answer(const Graph& g, const std::vector<char>& enabled,
                              BlossomMatching& solver) {
  return bimdf::testing::solve(g, solver, enabled);
}

// One round of changes: `edges` random edges get new weights (and are disabled with
// probability 1/5, unless `keep` says they carry the planted matching), `vertices` random
// vertices are reopened.
void change(std::mt19937& rng, Graph& g, std::vector<char>& enabled, BlossomMatching& solver,
            int edges, int vertices, int max_weight, const std::vector<char>& keep) {
  for (int k = 0; k < edges; ++k) {
    const int e = static_cast<int>(rng() % g.a.size());
    g.w[e] = static_cast<int64_t>(rng() % (2 * max_weight + 1)) - max_weight;
    enabled[e] = keep[e] || rng() % 5 != 0;
    solver.update_edge(e, g.w[e], enabled[e]);
  }
  for (int k = 0; k < vertices; ++k) solver.reopen(static_cast<int>(rng() % g.n));
}

TEST(BlossomReoptimize, EqualsEnumerationOverRoundsOfChanges) {
  std::mt19937 rng(17);
  int rounds_with_matching = 0, resumed_infeasible = 0;
  int64_t parity_unmatched = 0;
  for (int it = 0; it < 600; ++it) {
    // Every third case dense, with small weights: many tight edges between odd blossoms, so
    // that the parity step must sometimes unmatch a pair.
    const bool dense = it % 3 == 0;
    const int n = 2 * (2 + static_cast<int>(rng() % 4));
    Graph g = bimdf::testing::random_graph(
        rng, n, dense ? 4 * n : n + static_cast<int>(rng() % (3 * n)), dense ? 3 : 10);
    std::vector<char> enabled(g.a.size(), 1), keep(g.a.size(), 0);
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    bool kept = answer(g, enabled, solver).has_value();
    for (int round = 0; round < 8; ++round) {
      // Drawn before the call, not as its arguments, whose order of evaluation is the
      // compiler's (this is gcc's order): the same cases under every compiler.
      const int vertices = static_cast<int>(rng() % (dense ? 4 : 2));
      const int edges = 1 + static_cast<int>(rng() % 3);
      change(rng, g, enabled, solver, edges, vertices, dense ? 3 : 10, keep);
      const std::optional<int64_t> expected = bimdf::testing::brute_force(enabled_part(g, enabled));
      const std::optional<int64_t> got = answer(g, enabled, solver);
      ASSERT_EQ(got.has_value(), expected.has_value()) << "case " << it << ", round " << round;
      if (got) {
        EXPECT_EQ(*got, *expected) << "case " << it << ", round " << round;
        ++rounds_with_matching;
        parity_unmatched += solver.parity_unmatched_pairs();
      } else if (kept) {
        ++resumed_infeasible;  // the next run starts afresh
      }
      kept = got.has_value();
    }
  }
  EXPECT_GT(rounds_with_matching, 1000);
  EXPECT_GT(resumed_infeasible, 20);  // failed resumes are covered too
  EXPECT_GT(parity_unmatched, 0);     // and pairs the parity step could not place
}

// Larger graphs with a planted perfect matching (never disabled) and many blossoms: every
// round equals LEMON on the changed graph, and a resumed run grows trees from few vertices.
TEST(BlossomReoptimize, EqualsLemonOverRoundsOfChangesAndStaysLocal) {
  std::mt19937 rng(23);
  int64_t free_resumed = 0, reopened = 0;
  for (int it = 0; it < 12; ++it) {
    const int n = 2 * (100 + static_cast<int>(rng() % 300));
    Graph g = bimdf::testing::random_graph(rng, n, 3 * n, 1000);
    std::vector<char> keep(g.a.size(), 0);
    for (int v = 0; v + 1 < n; v += 2) {
      g.a.push_back(v);
      g.b.push_back(v + 1);
      g.w.push_back(static_cast<int64_t>(rng() % 2001) - 1000);
      keep.push_back(1);
    }
    std::vector<char> enabled(g.a.size(), 1);
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    ASSERT_EQ(answer(g, enabled, solver), bimdf::testing::lemon_optimum(g)) << "case " << it;
    for (int round = 0; round < 15; ++round) {
      const int edges = 1 + static_cast<int>(rng() % 6);
      change(rng, g, enabled, solver, edges, static_cast<int>(rng() % 3), 1000, keep);
      const std::optional<int64_t> got = answer(g, enabled, solver);
      ASSERT_TRUE(got.has_value()) << "case " << it << ", round " << round;
      EXPECT_EQ(got, bimdf::testing::lemon_optimum(enabled_part(g, enabled)))
          << "case " << it << ", round " << round;
      free_resumed += solver.free_after_start();
      reopened += 2 * edges + 2;
    }
    // No change at all: the kept matching is certified as it is.
    ASSERT_TRUE(answer(g, enabled, solver).has_value());
    EXPECT_EQ(solver.free_after_start(), 0) << "case " << it;
  }
  // Each reopened vertex frees itself and its mate; parity moves free a few pairs more.
  EXPECT_LT(free_resumed, 3 * reopened);
}

TEST(BlossomReoptimize, RejectsBadUpdatesWithAMessage) {
  BlossomMatching solver(2, std::vector<int>{0}, std::vector<int>{1}, std::vector<int64_t>{5});
  auto message = [](auto call) { return bimdf::testing::invalid_argument_message(call); };
  EXPECT_EQ(message([&] { solver.update_edge(1, 0); }), "blossom matching: no edge 1");
  EXPECT_EQ(message([&] { solver.update_edge(0, int64_t{1} << 57); }),
            "blossom matching: |weight| * (nodes + 1) must stay below 2^58");
  EXPECT_EQ(message([&] { solver.reopen(2); }), "blossom matching: no vertex 2");
  // Disabling the only edge leaves no perfect matching; enabling it again restores it.
  ASSERT_EQ(solver.run(), BlossomMatching::Status::Optimal);
  solver.update_edge(0, 5, false);
  EXPECT_EQ(solver.run(), BlossomMatching::Status::NoPerfectMatching);
  solver.update_edge(0, 7, true);
  EXPECT_EQ(solver.run(), BlossomMatching::Status::Optimal);
  EXPECT_EQ(solver.matching_weight(), 7);
}

// A new start given after a run (initial duals or matching) is a fresh solve, not a resume
// from the old blossoms with the new duals mixed in.
TEST(BlossomReoptimize, ANewStartAfterARunSolvesAfresh) {
  std::mt19937 rng(31);
  for (int it = 0; it < 20; ++it) {
    const int n = 2 * (20 + static_cast<int>(rng() % 60));
    Graph g = bimdf::testing::random_graph(rng, n, 3 * n, 1000);
    for (int v = 0; v + 1 < n; v += 2) {
      g.a.push_back(v);
      g.b.push_back(v + 1);
      g.w.push_back(static_cast<int64_t>(rng() % 2001) - 1000);
    }
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    const std::optional<int64_t> optimum = bimdf::testing::lemon_optimum(g);
    ASSERT_EQ(bimdf::testing::solve(g, solver), optimum) << "case " << it;
    std::vector<int64_t> y(g.n);
    for (int64_t& x : y) x = static_cast<int64_t>(rng() % 2001) - 1000;
    std::vector<char> flags(g.a.size());
    for (char& f : flags) f = rng() % 2;
    if (it % 2 == 0) {
      solver.initial_duals(y);
    } else {
      solver.initial_matching(flags);
    }
    EXPECT_EQ(bimdf::testing::solve(g, solver), optimum) << "case " << it;
  }
}

}  // namespace
