// Components routed to their dedicated algorithm (src/solve/special_structure.hpp): directed
// min-cost flows (linear or curved costs), with any nodes' rows written negated, and perfect
// matchings, written as Bi-MDF, are solved by network simplex or one blossom run — checked
// against the CBC MILP oracle (an independent solver) and the path the solver reports;
// problems that only look alike (an odd cycle of two-headed edges, a loop, a demand of 2) take
// the general path, and infeasible ones are still proven infeasible there.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "bimdf/flow.hpp"
#include "bimdf/solve.hpp"
#include "milp_model.hpp"

namespace bimdf {
namespace {

std::string path_of(const Solution& s) {
  return std::get<std::string>(s.stats.at("approximation_path"));
}

Solution solve_exactly(const Problem& p) {
  Solver solver(p);
  solver.run();
  return solver.solution();
}

// A random directed network (n nodes, m arcs plus a ring, finite and infinite capacities, some
// lower bounds; linear costs, or with `curved` also deviation costs) with balanced supplies;
// the rows of the nodes in `negated` are written multiplied by −1 (every end at them flipped,
// the demand negated).
Problem directed_network(std::mt19937_64& rng, int n, int m, const std::vector<char>& negated,
                         bool curved = false) {
  std::uniform_int_distribution<int> node(0, n - 1), cost(-5, 20), cap(1, 6), amount(0, 5);
  Problem p;
  for (int v = 0; v < n; ++v) p.add_node(0);
  std::vector<int64_t> net(n, 0);  // inflow − outflow of a planted flow
  std::uniform_real_distribution<double> target(-2, 12);
  const auto arc = [&](int s, int t, int64_t lo, int64_t up, double c, int64_t planted) {
    Cost cost = Cost::linear(c);
    if (curved && p.num_edges() % 3 == 1) cost = Cost::quad_deviation(target(rng), 0.5 + c / 20);
    if (curved && p.num_edges() % 3 == 2) cost = Cost::abs_deviation(target(rng), 1 + c / 20);
    p.add_edge({s, negated[s] != 0}, End{t, negated[t] == 0}, lo, up, cost);
    net[t] += planted, net[s] -= planted;
  };
  for (int v = 0; v < n; ++v) arc(v, (v + 1) % n, 0, kInfinity, 10, amount(rng));
  for (int k = 0; k < m; ++k) {
    const int s = node(rng), t = node(rng);
    if (s == t) continue;
    const int64_t lo = k % 5 == 0 ? 1 : 0, up = lo + cap(rng);
    // Drawn last first, as gcc evaluated them as arguments: the same network under any compiler.
    const int64_t planted = std::uniform_int_distribution<int64_t>(lo, up)(rng);
    arc(s, t, lo, up, cost(rng), planted);
  }
  for (int v = 0; v < n; ++v) p.demand[v] = negated[v] ? -net[v] : net[v];
  return p;
}

// 40 random directed networks with random rows negated: optimal, as the oracle says, and
// solved as one directed min-cost flow.
// With `outer`, three outer edges (sources and sinks of either sign, bounds [0, 4], linear or
// quadratic costs) are added, and a fourth that must bring node 0 the 2 units added to its
// demand.
void expect_routed_directed_flows(uint64_t seed, bool curved, bool outer = false) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 40; ++i) {
    const int n = 4 + i % 9;
    std::vector<char> negated(n);
    for (char& x : negated) x = static_cast<char>(rng() % 2);
    Problem p = directed_network(rng, n, 2 * n, negated, curved);
    for (int k = 0; outer && k < 3; ++k) {
      const Cost cost = k == 2 ? Cost::quad_deviation(3, 1) : Cost::linear(k == 0 ? -7 : 2);
      p.add_edge({static_cast<int>(rng() % n), rng() % 2 == 0}, std::nullopt, 0, 4, cost);
    }
    if (outer) {  // node 0 needs 2 more from outside: the outside's supply is not 0
      p.demand[0] += 2;
      p.add_edge({0, true}, std::nullopt, 0, 4, Cost::linear(1));
    }
    ASSERT_FALSE(validate(p)) << i;
    const Solution s = solve_exactly(p);
    const testing::MilpResult milp = testing::solve_milp(p, -40, 200);
    ASSERT_TRUE(milp.feasible) << i;
    ASSERT_EQ(s.status, SolveStatus::Optimal) << i;
    EXPECT_TRUE(check_flow(p, s.flow).feasible()) << i;
    EXPECT_NEAR(s.objective, milp.objective, 1e-6 * std::max(1.0, std::fabs(milp.objective))) << i;
    EXPECT_EQ(path_of(s), "directed min-cost flow (1 component)") << i;
    EXPECT_EQ(std::get<int64_t>(s.stats.at("fallbacks")), 0) << i;  // no cover failed
  }
}

TEST(SpecialStructure, DirectedFlowsWithNegatedRowsMatchTheMilpOracle) {
  expect_routed_directed_flows(5, false);
}

// Curved costs on an orientable component: windows of unit arcs around each cost's minimum,
// widened where the optimum falls outside (without widening, 31 of these checks fail), give
// the exact optimum.
TEST(SpecialStructure, DirectedFlowsWithCurvedCostsMatchTheMilpOracle) {
  expect_routed_directed_flows(13, true);
}

// Outer edges are arcs to and from the outside: routed as given, before their elimination
// adds a loop.
TEST(SpecialStructure, DirectedFlowsWithOuterEdgesMatchTheMilpOracle) {
  expect_routed_directed_flows(17, true, true);
}

// A random graph with a planted perfect matching (pairs 2k, 2k + 1) among other edges.
Problem perfect_matching(std::mt19937_64& rng, int n, bool heads) {
  std::uniform_int_distribution<int> node(0, n - 1);
  std::uniform_real_distribution<double> weight(-3, 10);
  Problem p;
  for (int v = 0; v < n; ++v) p.add_node(heads ? 1 : -1);
  const auto edge = [&](int a, int b) {
    // Any cost: only c(1) − c(0) matters on [0, 1].
    const Cost c = a % 3 == 0 ? Cost::quad_deviation(weight(rng), 1) : Cost::linear(weight(rng));
    p.add_edge({a, heads}, End{b, heads}, 0, 1, c);
  };
  for (int v = 0; v + 1 < n; v += 2) edge(v, v + 1);
  for (int k = 0; k < 2 * n; ++k) {
    const int a = node(rng), b = node(rng);
    if (a != b) edge(a, b);
  }
  return p;
}

TEST(SpecialStructure, PerfectMatchingsMatchTheMilpOracle) {
  std::mt19937_64 rng(8);
  for (int i = 0; i < 40; ++i) {
    const Problem p = perfect_matching(rng, 2 * (3 + i % 8), i % 2 == 0);
    ASSERT_FALSE(validate(p)) << i;
    const Solution s = solve_exactly(p);
    const testing::MilpResult milp = testing::solve_milp(p);
    ASSERT_TRUE(milp.feasible) << i;
    ASSERT_EQ(s.status, SolveStatus::Optimal) << i;
    EXPECT_TRUE(check_flow(p, s.flow).feasible()) << i;
    EXPECT_NEAR(s.objective, milp.objective, 1e-6 * std::max(1.0, std::fabs(milp.objective))) << i;
    EXPECT_EQ(path_of(s), "perfect matching (1 component)") << i;
  }
}

// Look-alikes take the general path and still reach the oracle's optimum.
TEST(SpecialStructure, LookAlikesTakeTheGeneralPath) {
  std::vector<Problem> problems;
  {  // A triangle of two-headed edges: the sign graph has an odd cycle.
    Problem p;
    for (int v = 0; v < 3; ++v) p.add_node(2);
    for (int v = 0; v < 3; ++v)
      p.add_edge({v, true}, End{(v + 1) % 3, true}, 0, 3, Cost::linear(v));
    problems.push_back(p);
  }
  {  // A directed cycle with a tail–tail loop: a loop has no orientation.
    Problem p;
    for (int v = 0; v < 4; ++v) p.add_node(v == 0 ? -3 : v == 2 ? 1 : 0);
    for (int v = 0; v < 4; ++v)
      p.add_edge({v, false}, End{(v + 1) % 4, true}, 0, 5, Cost::quad_deviation(1, 1));
    p.add_edge({2, false}, End{2, false}, 0, 3, Cost::linear(1));
    problems.push_back(p);
  }
  {  // Two-headed unit edges, but one demand of 2: a b-matching, not a perfect matching.
    Problem p;
    for (int v = 0; v < 5; ++v) p.add_node(v == 0 ? 2 : 1);
    for (int a = 0; a < 5; ++a)
      for (int b = a + 1; b < 5; ++b)
        p.add_edge({a, true}, End{b, true}, 0, 1, Cost::linear(a + b));
    problems.push_back(p);
  }
  for (size_t i = 0; i < problems.size(); ++i) {
    const Problem& p = problems[i];
    ASSERT_FALSE(validate(p)) << i;
    const Solution s = solve_exactly(p);
    const testing::MilpResult milp = testing::solve_milp(p);
    ASSERT_TRUE(milp.feasible) << i;
    ASSERT_EQ(s.status, SolveStatus::Optimal) << i;
    EXPECT_NEAR(s.objective, milp.objective, 1e-9) << i;
    EXPECT_EQ(path_of(s).find("directed"), std::string::npos) << i << ": " << path_of(s);
    EXPECT_EQ(path_of(s).find("matching"), std::string::npos) << i << ": " << path_of(s);
  }
}

// Unbalanced supplies, or a graph without a perfect matching: the dedicated algorithm finds
// nothing, and the general path proves the problem infeasible.
TEST(SpecialStructure, InfeasibleLookAlikesAreProvenInfeasible) {
  Problem flow;
  for (int v = 0; v < 3; ++v) flow.add_node(v == 0 ? -2 : 1 + v);  // supplies don't balance
  flow.add_edge({0, false}, End{1, true}, 0, 5, Cost::linear(1));
  flow.add_edge({1, false}, End{2, true}, 0, 5, Cost::linear(1));
  Problem star;  // a star with three leaves has no perfect matching
  for (int v = 0; v < 4; ++v) star.add_node(1);
  for (int v = 1; v < 4; ++v) star.add_edge({0, true}, End{v, true}, 0, 1, Cost::linear(1));
  for (const Problem* p : {&flow, &star}) {
    ASSERT_FALSE(validate(*p));
    EXPECT_FALSE(testing::solve_milp(*p).feasible);
    EXPECT_EQ(solve_exactly(*p).status, SolveStatus::Infeasible);
  }
}

}  // namespace
}  // namespace bimdf
