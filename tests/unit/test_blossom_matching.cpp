// Our perfect matching solver (backend/blossom_matching.hpp) against two independent oracles:
// enumeration of every perfect matching on small graphs, and LEMON's solver on larger ones;
// with and without warm starts, which may change the path but never the optimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "backend/blossom_matching.hpp"
#include "backend/perfect_matching.hpp"
#include "bimdf/problem.hpp"
#include "bimdf/solve.hpp"
#include "matching_test_support.hpp"
#include "random_problem.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/matching_gadgets.hpp"
#include "solve/residual_pruning.hpp"

namespace {

using bimdf::detail::BlossomMatching;
using bimdf::testing::brute_force;
using bimdf::testing::Graph;
using bimdf::testing::random_graph;
using bimdf::testing::solve;

TEST(BlossomMatching, EqualsEnumerationOnSmallGraphsFromAnyStart) {
  std::mt19937 rng(7);
  int with_matching = 0;
  for (int it = 0; it < 3000; ++it) {
    const int n = 2 * (1 + static_cast<int>(rng() % 5));
    const Graph g = random_graph(rng, n, n / 2 + static_cast<int>(rng() % (3 * n)), 10);
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    if (it % 3 == 1) {  // arbitrary duals: made feasible by the solver
      std::vector<int64_t> y(g.n);
      for (int64_t& x : y) x = static_cast<int64_t>(rng() % 41) - 20;
      solver.initial_duals(y);
    }
    if (it % 4 == 2) {  // arbitrary matched flags: only consistent tight ones are kept
      std::vector<char> flags(g.a.size());
      for (char& f : flags) f = rng() % 3 == 0;
      solver.initial_matching(flags);
    }
    const std::optional<int64_t> expected = brute_force(g);
    const std::optional<int64_t> got = solve(g, solver);
    ASSERT_EQ(got.has_value(), expected.has_value()) << "case " << it;
    if (expected) {
      EXPECT_EQ(*got, *expected) << "case " << it;
      ++with_matching;
    }
  }
  EXPECT_GT(with_matching, 1000);  // the cases are not mostly infeasible
}

TEST(BlossomMatching, EqualsLemonOnLargerGraphs) {
  std::mt19937 rng(11);
  int infeasible = 0;
  for (int it = 0; it < 90; ++it) {
    const int n = 2 * (20 + static_cast<int>(rng() % 200));
    // Sparse random graphs often lack a perfect matching; every third case gets none planted.
    Graph g = random_graph(rng, n, it % 3 == 0 ? n + n / 2 : 3 * n, 1000);
    for (int v = 0; it % 3 != 0 && v + 1 < n; v += 2) {  // a planted perfect matching
      g.a.push_back(v);
      g.b.push_back(v + 1);
      g.w.push_back(static_cast<int64_t>(rng() % 2001) - 1000);
    }
    const std::optional<int64_t> lemon = bimdf::testing::lemon_optimum(g);
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    if (it % 2 == 1) {  // warm starts: many blossoms, expansions and reused ids
      std::vector<int64_t> y(g.n);
      for (int64_t& x : y) x = static_cast<int64_t>(rng() % 2001) - 1000;
      std::vector<char> flags(g.a.size());
      for (char& f : flags) f = rng() % 2;
      solver.initial_duals(y).initial_matching(flags);
    }
    const std::optional<int64_t> got = solve(g, solver);
    ASSERT_EQ(got.has_value(), lemon.has_value()) << "case " << it;
    if (!lemon) {
      ++infeasible;
      continue;
    }
    EXPECT_EQ(*got, *lemon) << "case " << it;
  }
  EXPECT_GT(infeasible, 5);
  EXPECT_LT(infeasible, 60);
}

// A tower of k nested blossoms: from the root 0 an alternating path 0 − 1 = 2 − 3 = 4 ... (the
// "=" pairs start matched, every edge tight), and a closing edge from 2i back to 0 that becomes
// tight at dual change i, so level i closes around level i − 1. The last free vertex L hangs
// off 2k and meets the tower only after it is complete: the augmentation rotates through all k
// levels, and the certificate must sum z along chains deeper than its short walk (32 levels).
// Every perfect matching uses (2k, L); the rest can weigh 0, so the optimum is w(2k, L).
TEST(BlossomMatching, DeeplyNestedBlossoms) {
  for (int k : {3, 20, 300}) {
    Graph g;
    const int last = 2 * k + 1;
    g.n = last + 1;
    std::vector<char> start;
    auto add = [&](int a, int b, int64_t w, bool matched) {
      g.a.push_back(a);
      g.b.push_back(b);
      g.w.push_back(w);
      start.push_back(matched);
    };
    add(0, 1, 0, false);
    for (int i = 1; i <= k; ++i) {
      if (i > 1) add(2 * i - 2, 2 * i - 1, 0, false);
      add(2 * i - 1, 2 * i, 0, true);
      add(2 * i, 0, -i, false);
    }
    add(2 * k, last, -(k + 1), false);
    BlossomMatching solver(g.n, g.a, g.b, g.w);
    solver.initial_duals(std::vector<int64_t>(g.n, 0)).initial_matching(start);
    EXPECT_EQ(solve(g, solver), -(k + 1)) << "k = " << k;
    EXPECT_EQ(solver.free_after_start(), 2);
    if (k <= 3) {
      EXPECT_EQ(brute_force(g), -(k + 1));
    }
  }
}

TEST(BlossomMatching, ReportsGraphsWithoutPerfectMatching) {
  // Two triangles: six vertices, every one with edges, but each triangle is odd.
  const std::vector<int> a{0, 1, 2, 3, 4, 5}, b{1, 2, 0, 4, 5, 3};
  const std::vector<int64_t> w{1, 2, 3, 4, 5, 6};
  BlossomMatching odd(6, a, b, w);
  EXPECT_EQ(odd.run(), BlossomMatching::Status::NoPerfectMatching);
  BlossomMatching isolated(8, a, b, w);  // vertices 6 and 7 have no edge
  EXPECT_EQ(isolated.run(), BlossomMatching::Status::NoPerfectMatching);
  BlossomMatching empty(0, {}, {}, {});
  EXPECT_EQ(empty.run(), BlossomMatching::Status::Optimal);
}

TEST(BlossomMatching, RejectsBadInputWithAMessage) {
  auto message = [](auto make) { return bimdf::testing::invalid_argument_message(make); };
  const std::vector<int> a{0, 1}, b{1, 1};
  const std::vector<int64_t> w{1, 1};
  EXPECT_EQ(message([&] { BlossomMatching(2, a, b, w); }),
            "blossom matching: edge 1 is a loop or has an end out of range");
  EXPECT_EQ(message([&] { BlossomMatching(2, std::vector<int>{0}, std::vector<int>{2}, w); }),
            "blossom matching: edge arrays of different sizes");
  EXPECT_EQ(message([&] {
              BlossomMatching(2, std::vector<int>{0}, std::vector<int>{1},
                              std::vector<int64_t>{int64_t{1} << 57});
            }),
            "blossom matching: |weight| * (nodes + 1) must stay below 2^58");
  BlossomMatching ok(2, std::vector<int>{0}, std::vector<int>{1}, std::vector<int64_t>{5});
  EXPECT_EQ(message([&] { ok.initial_duals(std::vector<int64_t>{1}); }),
            "blossom matching: one initial dual per vertex expected");
  EXPECT_EQ(message([&] {
              ok.initial_duals(std::vector<int64_t>{0, int64_t{1} << 58});
            }),
            "blossom matching: initial duals must stay below 2^58");
  EXPECT_EQ(message([&] {
              BlossomMatching(2, std::vector<int>{0}, std::vector<int>{1},
                              std::vector<int64_t>{std::numeric_limits<int64_t>::min()});
            }),
            "blossom matching: |weight| * (nodes + 1) must stay below 2^58");
}

// The gadget duals keep every edge at a gadget feasible (slack ≥ 0) whatever the b-duals, and
// the greedy matching uses only edges of the matching graph, each vertex at most once.
TEST(BlossomMatching, GadgetDualsAreFeasibleOnEveryGadgetEdge) {
  std::mt19937 rng(5);
  for (int it = 0; it < 200; ++it) {
    bimdf::detail::BMatching bm;
    const int nodes = 2 + static_cast<int>(rng() % 6);
    bm.degree.assign(nodes, 2);
    for (int e = 0; e < 3 * nodes; ++e) {
      bm.end_a.push_back(static_cast<int>(rng() % nodes));
      bm.end_b.push_back(static_cast<int>(rng() % nodes));
      bm.capacity.push_back(1);
      bm.weight.push_back(static_cast<double>(static_cast<int>(rng() % 21) - 10));
    }
    const bimdf::detail::MatchingReduction r = bimdf::detail::reduce_to_perfect_matching(bm);
    std::vector<int64_t> bdual(nodes), bweight(bm.num_edges());
    for (int64_t& y : bdual) y = static_cast<int64_t>(rng() % 21) - 10;
    for (int e = 0; e < bm.num_edges(); ++e) bweight[e] = static_cast<int64_t>(bm.weight[e]);
    const std::vector<int64_t> y = bimdf::detail::gadget_duals(bm, r, bdual, bweight);
    const bimdf::detail::MatchingGraph& g = r.graph;
    for (int e = 0; e < g.num_edges(); ++e) {
      if (r.bnode_of_node[g.end_a[e]] >= 0 && r.bnode_of_node[g.end_b[e]] >= 0) continue;
      EXPECT_GE(y[g.end_a[e]] + y[g.end_b[e]], static_cast<int64_t>(g.weight[e]))
          << "case " << it << ", edge " << e;
    }
    std::vector<int> value(bm.num_edges());
    for (int& v : value) v = static_cast<int>(rng() % 2);
    const std::vector<char> matched = bimdf::detail::gadget_matching(bm, r, value);
    std::vector<int> degree(g.num_nodes, 0);
    for (int e = 0; e < g.num_edges(); ++e)
      if (matched[e]) ++degree[g.end_a[e]], ++degree[g.end_b[e]];
    for (int v = 0; v < g.num_nodes; ++v) EXPECT_LE(degree[v], 1) << "case " << it;
  }
}

// The whole exact solver with our matching backends reaches LEMON's optimum; the persistent one
// does resume its matching in later rounds (not silently solve afresh).
TEST(BlossomMatching, ExactSolverAgreesWithTheLemonBackend) {
  for (const bimdf::MatchingBackend backend :
       {bimdf::MatchingBackend::Blossom, bimdf::MatchingBackend::Persistent}) {
    const bool persistent = backend == bimdf::MatchingBackend::Persistent;
    std::mt19937_64 rng(3);
    bimdf::testing::RandomProblemOptions options;
    options.min_nodes = 15;
    options.max_nodes = 40;
    options.min_edges = 30;
    options.max_edges = 90;
    int optimal = 0;
    int64_t matchings = 0, resumed = 0;
    for (int seed = 0; seed < 40; ++seed) {
      bimdf::Problem p = bimdf::testing::random_problem(rng, options);
      bimdf::testing::plant_feasible_demands(p, rng);
      bimdf::Solver ours(p), lemon(p);
      const bimdf::SolveStatus so = ours.matching(backend).run();
      const bimdf::SolveStatus sl = lemon.matching(bimdf::MatchingBackend::Lemon).run();
      ASSERT_EQ(so, sl) << "seed " << seed << (persistent ? ", persistent" : "");
      if (so != bimdf::SolveStatus::Optimal) continue;
      ++optimal;
      const auto& stats = ours.solution().stats;
      matchings += std::get<int64_t>(stats.at("matchings_solved"));
      resumed += std::get<int64_t>(stats.at("matchings_resumed"));
      EXPECT_EQ(std::get<int64_t>(stats.at("matching_lemon_fallbacks")), 0);
      EXPECT_EQ(std::get<int64_t>(stats.at("matching_persistent_fallbacks")), 0);
      const double a = ours.solution().objective, b = lemon.solution().objective;
      EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::fabs(b)))
          << "seed " << seed << (persistent ? ", persistent" : "");
    }
    EXPECT_GE(optimal, 30);
    EXPECT_GT(matchings, 20);  // the LP alone did not settle them
    if (persistent) {
      EXPECT_GT(resumed, 10);
    } else {
      EXPECT_EQ(resumed, 0);
    }
  }
}

// A residual with ~130 unit arcs per node: the largest matching it can lead to has far more
// nodes per LP node than usual, so the LP's cost scale must shrink (lp_scale_log2 < 52) for the
// matching weights to stay within the blossom solver's bound — and they do, whatever the LP
// keeps free.
TEST(BlossomMatching, PruningLpScaleLeavesTheMatchingItsHeadroom) {
  std::mt19937 rng(5);
  bimdf::detail::BiMcf residual;
  const int n = 3;
  residual.demand.assign(n, 0);
  for (int k = 0; k < 200; ++k) {
    residual.end_a.push_back({static_cast<int>(rng() % n), rng() % 2 == 0});
    residual.end_b.push_back({static_cast<int>(rng() % n), rng() % 2 == 0});
    residual.capacity.push_back(1);
    residual.cost.push_back(std::uniform_real_distribution<double>(-1, 1)(rng));
  }
  const int log2_limit = bimdf::detail::lp_scale_log2(residual);
  EXPECT_LT(log2_limit, 52);
  const bimdf::detail::ResidualPruning pruned = bimdf::detail::prune_residual(residual);
  ASSERT_FALSE(pruned.proves_optimal);
  // The limits refinement uses: above 2 at these hubs, so more copies per node.
  const bimdf::detail::Throughflow throughflow =
      bimdf::detail::refinement_throughflow(pruned.reduced);
  EXPECT_GT(*std::max_element(throughflow.limit.begin(), throughflow.limit.end()), 2);
  const auto bm = bimdf::detail::reduce_to_bmatching(pruned.reduced, throughflow);
  const auto mm = bimdf::detail::reduce_to_perfect_matching(bm.bmatching);
  std::vector<int64_t> weight;
  for (double w : mm.graph.weight) weight.push_back(2 * std::llround(w * pruned.cost_scale));
  EXPECT_NO_THROW(BlossomMatching(mm.graph.num_nodes, mm.graph.end_a, mm.graph.end_b, weight));
}

}  // namespace
