// Our warm-startable min-cost flow solver (backend/shortest_path_flow.hpp) against two
// independent oracles: enumeration of every integer flow on tiny networks, and LEMON's network
// simplex (solve_min_cost_flow without a start) on larger ones; from zero and from arbitrary
// potentials, which may change the path but never the optimum.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/min_cost_flow.hpp"
#include "backend/shortest_path_flow.hpp"

namespace {

using bimdf::detail::DirectedMcf;
using bimdf::detail::MinCostFlowStatus;
using bimdf::detail::ShortestPathFlow;
constexpr int64_t kInf = std::numeric_limits<int64_t>::max();

struct Network {
  std::vector<int64_t> supply;
  std::vector<int> source, target;
  std::vector<int64_t> capacity, cost;
};

Network random_network(std::mt19937& rng, int n, int m, int max_capacity, int max_cost,
                       double infinite_share) {
  Network g;
  std::uniform_int_distribution<int> node(0, n - 1), cap(0, max_capacity),
      cost(-max_cost, max_cost);
  std::uniform_real_distribution<double> coin(0, 1);
  for (int a = 0; a < m; ++a) {
    g.source.push_back(node(rng));
    g.target.push_back(node(rng));
    const bool infinite = coin(rng) < infinite_share;
    g.capacity.push_back(infinite ? kInf : cap(rng));
    // Infinite arcs cost ≥ 0, so that no cycle of them has negative cost (bounded problems).
    g.cost.push_back(infinite ? std::abs(cost(rng)) : cost(rng));
  }
  // Supplies that a random flow within the capacities would produce, then sometimes disturbed
  // so that some networks are infeasible.
  g.supply.assign(n, 0);
  for (int a = 0; a < m; ++a) {
    const int64_t f = std::uniform_int_distribution<int64_t>(
        0, g.capacity[a] == kInf ? max_capacity : g.capacity[a])(rng);
    g.supply[g.source[a]] += f;
    g.supply[g.target[a]] -= f;
  }
  if (coin(rng) < 0.2) {
    const int v = node(rng), w = node(rng);
    const int64_t d = std::uniform_int_distribution<int64_t>(1, 3)(rng);
    g.supply[v] += d;
    g.supply[w] -= d;
  }
  return g;
}

int64_t cost_of(const Network& g, const std::vector<int64_t>& flow) {
  int64_t c = 0;
  for (size_t a = 0; a < flow.size(); ++a) c += g.cost[a] * flow[a];
  return c;
}

// The cheapest feasible flow by enumeration (finite capacities only), or nullopt.
std::optional<int64_t> enumerate(const Network& g) {
  const int n = static_cast<int>(g.supply.size()), m = static_cast<int>(g.source.size());
  std::vector<int64_t> flow(m, 0);
  std::optional<int64_t> best;
  std::function<void(int)> go = [&](int a) {
    if (a == m) {
      std::vector<int64_t> net(n, 0);
      for (int k = 0; k < m; ++k) {
        net[g.source[k]] += flow[k];
        net[g.target[k]] -= flow[k];
      }
      if (net != g.supply) return;
      const int64_t c = cost_of(g, flow);
      if (!best || c < *best) best = c;
      return;
    }
    for (flow[a] = 0; flow[a] <= g.capacity[a]; ++flow[a]) go(a + 1);
    flow[a] = 0;
  };
  go(0);
  return best;
}

// Checks bounds, conservation and the reduced-cost conditions independently of the solver.
void expect_optimal(const Network& g, const std::vector<int64_t>& flow,
                    const std::vector<int64_t>& potential) {
  const int n = static_cast<int>(g.supply.size());
  std::vector<int64_t> net(n, 0);
  for (size_t a = 0; a < flow.size(); ++a) {
    ASSERT_GE(flow[a], 0);
    ASSERT_LE(flow[a], g.capacity[a]);
    net[g.source[a]] += flow[a];
    net[g.target[a]] -= flow[a];
    const int64_t r = g.cost[a] + potential[g.source[a]] - potential[g.target[a]];
    if (flow[a] < g.capacity[a]) {
      EXPECT_GE(r, 0) << "arc " << a;
    }
    if (flow[a] > 0) {
      EXPECT_LE(r, 0) << "arc " << a;
    }
  }
  EXPECT_EQ(net, g.supply);
}

std::vector<int64_t> random_potentials(std::mt19937& rng, int n, int spread) {
  std::vector<int64_t> p(n);
  for (int64_t& x : p) x = std::uniform_int_distribution<int64_t>(-spread, spread)(rng);
  return p;
}

TEST(ShortestPathFlow, MatchesEnumerationOnTinyNetworks) {
  std::mt19937 rng(11);
  int optimal = 0, infeasible = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Network g = random_network(rng, 2 + trial % 3, 1 + trial % 6, 2, 5, 0);
    const std::optional<int64_t> best = enumerate(g);
    ShortestPathFlow solver(g.supply, g.source, g.target, g.capacity, g.cost);
    if (trial % 2) solver.initial_potentials(random_potentials(rng, g.supply.size(), 8));
    const ShortestPathFlow::Status status = solver.run();
    if (!best) {
      EXPECT_EQ(status, ShortestPathFlow::Status::Infeasible) << "trial " << trial;
      ++infeasible;
      continue;
    }
    ASSERT_EQ(status, ShortestPathFlow::Status::Optimal) << "trial " << trial;
    EXPECT_EQ(cost_of(g, solver.flow()), *best) << "trial " << trial;
    expect_optimal(g, solver.flow(), solver.potential());
    ++optimal;
  }
  EXPECT_GT(optimal, 1500);  // both outcomes are exercised
  EXPECT_GT(infeasible, 200);
}

TEST(ShortestPathFlow, MatchesNetworkSimplexFromAnyStart) {
  std::mt19937 rng(12);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 10 + trial % 190;
    const Network g = random_network(rng, n, 3 * n, 6, 1000, 0.1);
    DirectedMcf mcf{g.supply, g.source, g.target, g.capacity, {}};
    for (int64_t c : g.cost) mcf.cost.push_back(static_cast<double>(c));
    const auto lemon = bimdf::detail::solve_min_cost_flow(mcf);  // no start: network simplex
    ShortestPathFlow solver(g.supply, g.source, g.target, g.capacity, g.cost);
    if (trial % 3 == 1) solver.initial_potentials(random_potentials(rng, n, 3000));
    // An optimum's own potentials (a cold run's): the start then leaves imbalance only where
    // tight arcs must carry flow, every path found is tight, and the potentials never move.
    std::vector<int64_t> optimal_potential;
    if (trial % 3 == 2) {
      ShortestPathFlow cold(g.supply, g.source, g.target, g.capacity, g.cost);
      if (cold.run() == ShortestPathFlow::Status::Optimal) optimal_potential = cold.potential();
      if (!optimal_potential.empty()) solver.initial_potentials(optimal_potential);
    }
    const ShortestPathFlow::Status status = solver.run();
    ASSERT_NE(lemon.status, MinCostFlowStatus::Unbounded);
    if (lemon.status == MinCostFlowStatus::Infeasible) {
      EXPECT_EQ(status, ShortestPathFlow::Status::Infeasible) << "trial " << trial;
      continue;
    }
    ASSERT_EQ(status, ShortestPathFlow::Status::Optimal) << "trial " << trial;
    EXPECT_EQ(cost_of(g, solver.flow()), cost_of(g, lemon.flow)) << "trial " << trial;
    expect_optimal(g, solver.flow(), solver.potential());
    if (!optimal_potential.empty()) {
      EXPECT_EQ(solver.potential(), optimal_potential);
    }
    ++compared;
  }
  EXPECT_GT(compared, 150);
}

TEST(ShortestPathFlow, WarmStartedMinCostFlowAgreesWithNetworkSimplex) {
  // solve_min_cost_flow with a start takes the shortest-path solver when the start is good
  // and the network simplex otherwise; either way the optimum is the cold one's.
  std::mt19937 rng(13);
  bimdf::detail::MinCostFlowTally methods;
  int skipped = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 50 + trial;
    const Network g = random_network(rng, n, 4 * n, 4, 100, 0.05);
    DirectedMcf mcf{g.supply, g.source, g.target, g.capacity, {}};
    for (int64_t c : g.cost) mcf.cost.push_back(c / 7.0);
    const auto cold = bimdf::detail::solve_min_cost_flow(mcf);
    if (cold.status != MinCostFlowStatus::Optimal) {
      ++skipped;
      continue;
    }
    // Near the optimum's potentials or far from them.
    std::vector<double> start = bimdf::detail::potentials_in_cost_units(cold);
    const double noise = trial % 2 ? 0.001 : 5;
    for (double& p : start) p += std::uniform_real_distribution<double>(-noise, noise)(rng);
    const auto warm = bimdf::detail::solve_min_cost_flow(mcf, 60, start);
    ASSERT_EQ(warm.status, MinCostFlowStatus::Optimal) << "trial " << trial;
    methods.add(warm.method);
    Network scaled = g;
    scaled.cost = warm.scaled_cost;
    EXPECT_EQ(cost_of(scaled, warm.flow), cost_of(scaled, cold.flow)) << "trial " << trial;
    expect_optimal(scaled, warm.flow, warm.potential);
  }
  // Every solve was given a start. On random networks the optimum has many tight arcs that
  // carry part of their capacity, which a start leaves empty: too much imbalance for the
  // shortest paths, so the network simplex answers (the shared instances take the shortest
  // paths: ExactShared; a start they take below).
  EXPECT_EQ(methods.cold, 0);
  EXPECT_EQ(methods.warm, 100 - skipped);
  EXPECT_GT(methods.warm_abandoned, 0);
}

TEST(ShortestPathFlow, NetworkSimplexFromAStartAgreesWithAColdOne) {
  // A start too far off for the shortest paths goes to the network simplex on the costs the
  // start reduces, the arcs it prices negative turned around. The status is the cold simplex's
  // — infeasible and unbounded networks included — and so is the optimum, whose flow and
  // potentials are checked against the original costs.
  std::mt19937 rng(21);
  bimdf::detail::MinCostFlowTally methods;
  int infeasible = 0, unbounded = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 20 + trial;
    Network g = random_network(rng, n, 4 * n, 5, 200, 0.1);
    if (trial % 10 == 0) {  // 0 → 1 → 0, infinite, total cost −1
      g.source.insert(g.source.end(), {0, 1});
      g.target.insert(g.target.end(), {1, 0});
      g.capacity.insert(g.capacity.end(), {kInf, kInf});
      g.cost.insert(g.cost.end(), {-3, 2});
    }
    if (trial % 7 == 3) g.supply.insert(g.supply.end(), {1, -1});  // two nodes, no arc between
    // An empty arc of cost 2000 sets the integer scale (min_cost_flow.hpp), so that costs
    // reduced by the start below stay within its bound and the simplex takes the start.
    g.source.push_back(0);
    g.target.push_back(1);
    g.capacity.push_back(0);
    g.cost.push_back(2000);
    DirectedMcf mcf{g.supply, g.source, g.target, g.capacity, {}};
    for (int64_t c : g.cost) mcf.cost.push_back(static_cast<double>(c));
    const auto cold = bimdf::detail::solve_min_cost_flow(mcf);
    std::vector<double> start(g.supply.size());
    for (double& p : start) p = std::uniform_real_distribution<double>(-300, 300)(rng);
    // From any size on (the default starts only large networks so).
    const auto warm = bimdf::detail::solve_min_cost_flow(mcf, 60, start, 0);
    methods.add(warm.method);
    ASSERT_EQ(warm.status, cold.status) << "trial " << trial;
    infeasible += cold.status == MinCostFlowStatus::Infeasible;
    unbounded += cold.status == MinCostFlowStatus::Unbounded;
    if (cold.status != MinCostFlowStatus::Optimal) continue;
    Network scaled = g;
    scaled.cost = warm.scaled_cost;
    EXPECT_EQ(cost_of(scaled, warm.flow), cost_of(scaled, cold.flow)) << "trial " << trial;
    expect_optimal(scaled, warm.flow, warm.potential);
  }
  EXPECT_EQ(methods.warm_abandoned, 200);
  EXPECT_GT(infeasible, 25);
  EXPECT_GT(unbounded, 10);
}

TEST(ShortestPathFlow, AGoodStartIsFinishedByShortestPaths) {
  // 0 → 1 → 2, one unit, both arcs full at the optimum; potentials that price both at −1 leave
  // no imbalance once they are saturated.
  DirectedMcf mcf{{1, 0, -1}, {0, 1}, {1, 2}, {1, 1}, {1.0, 1.0}};
  const auto warm = bimdf::detail::solve_min_cost_flow(mcf, 60, {0.0, 2.0, 4.0});
  ASSERT_EQ(warm.status, MinCostFlowStatus::Optimal);
  EXPECT_EQ(warm.method, bimdf::detail::MinCostFlowMethod::WarmStart);
  EXPECT_EQ(warm.flow, (std::vector<int64_t>{1, 1}));
  const auto cold = bimdf::detail::solve_min_cost_flow(mcf);
  EXPECT_EQ(cold.method, bimdf::detail::MinCostFlowMethod::NetworkSimplex);
}

TEST(ShortestPathFlow, NegativeCycleOfInfiniteArcsIsLeftToTheExactFallback) {
  // 0 → 1 → 0 with total cost −1 and infinite capacity: unbounded.
  const std::vector<int64_t> supply = {0, 0};
  ShortestPathFlow solver(supply, {0, 1}, {1, 0}, {kInf, kInf}, {-3, 2});
  EXPECT_EQ(solver.run(), ShortestPathFlow::Status::NeedsExactFallback);
  DirectedMcf mcf{supply, {0, 1}, {1, 0}, {kInf, kInf}, {-3.0, 2.0}};
  EXPECT_EQ(bimdf::detail::solve_min_cost_flow(mcf, 60, {0.0, 0.0}).status,
            MinCostFlowStatus::Unbounded);
}

TEST(ShortestPathFlow, InfiniteArcsCarryWhatIsNeeded) {
  // 5 units from 0 to 2 over an infinite, cheap arc and a finite, cheaper one of capacity 2.
  ShortestPathFlow solver({5, 0, -5}, {0, 1, 0}, {1, 2, 2}, {kInf, kInf, 2}, {1, 1, 1});
  ASSERT_EQ(solver.run(), ShortestPathFlow::Status::Optimal);
  EXPECT_EQ(solver.flow(), (std::vector<int64_t>{3, 3, 2}));
}

TEST(ShortestPathFlow, GivesUpAtTheWorkLimit) {
  // A path 0 → 1 → … → 9: the unit at 0 needs a search over 9 arcs to reach node 9.
  std::vector<int64_t> supply(10, 0);
  supply[0] = 1;
  supply[9] = -1;
  std::vector<int> source, target;
  for (int v = 0; v < 9; ++v) source.push_back(v), target.push_back(v + 1);
  const std::vector<int64_t> capacity(9, 1), cost(9, 3);
  ShortestPathFlow limited(supply, source, target, capacity, cost);
  EXPECT_EQ(limited.work_limit(5).run(), ShortestPathFlow::Status::WorkLimitReached);
  ShortestPathFlow unlimited(supply, source, target, capacity, cost);
  ASSERT_EQ(unlimited.run(), ShortestPathFlow::Status::Optimal);
  EXPECT_EQ(unlimited.flow(), std::vector<int64_t>(9, 1));
}

TEST(ShortestPathFlow, SuppliesThatDoNotCancelAreLeftToTheExactFallback) {
  ShortestPathFlow solver({2, -1}, {0}, {1}, {5}, {1});
  EXPECT_EQ(solver.run(), ShortestPathFlow::Status::NeedsExactFallback);
}

TEST(ShortestPathFlow, ProvesInfeasibility) {
  // Node 0 must send 3 units through an arc of capacity 2.
  ShortestPathFlow solver({3, -3}, {0}, {1}, {2}, {1});
  EXPECT_EQ(solver.run(), ShortestPathFlow::Status::Infeasible);
}

TEST(ShortestPathFlow, RejectsBadInput) {
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([] {
              ShortestPathFlow({0, 0}, {0}, {2}, {1}, {1});
            }),
            "shortest path flow: arc 0 has an end out of range");
  EXPECT_EQ(message([] {
              ShortestPathFlow({0, 0}, {0}, {1}, {-1}, {1});
            }),
            "shortest path flow: arc 0 has a negative capacity");
  EXPECT_EQ(message([] {
              ShortestPathFlow({0, 0}, {0}, {1, 0}, {1}, {1});
            }),
            "shortest path flow: arc arrays of different sizes");
  EXPECT_EQ(message([] {
              ShortestPathFlow({0, 0}, {0}, {1}, {1}, {1}).initial_potentials({0});
            }),
            "shortest path flow: 1 initial potentials for 2 nodes");
}

}  // namespace
