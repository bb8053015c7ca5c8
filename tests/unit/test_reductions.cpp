// Each reduction together with its lift (DESIGN §3): solve the reduced problem by brute force,
// lift the flow back, and check that it is feasible for the original with the same cost — and
// that the reduction loses nothing: both optima agree, and so does infeasibility.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <stdexcept>

#include "backend/min_cost_flow.hpp"
#include "backend/perfect_matching.hpp"
#include "bimdf/flow.hpp"
#include "brute_force.hpp"
#include "core/deep_stack.hpp"
#include "random_problem.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/chains.hpp"
#include "reduce/components.hpp"
#include "reduce/double_cover.hpp"
#include "reduce/fixed_edges.hpp"
#include "reduce/linearize.hpp"
#include "reduce/matching_gadgets.hpp"
#include "reduce/outer_edges.hpp"
#include "reduce/parity.hpp"
#include "reduce/phase_one.hpp"
#include "solve/refine.hpp"
#include "solve/residual_pruning.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

using testing::brute_force;

const int kInstances = testing::scaled(1500);

Problem tiny(std::mt19937_64& rng, int i) {
  testing::RandomProblemOptions opt;
  opt.max_nodes = 4;
  opt.max_edges = 6;
  Problem p = testing::random_problem(rng, opt);
  if (i % 2) testing::plant_feasible_demands(p, rng);
  return p;
}

// Splits up to two edges (a, b) into (a, w) and (w, b) through a new pass-through node w, so
// that chains occur often. The second half gets a random cost and bounds of its own.
Problem subdivided(Problem p, std::mt19937_64& rng) {
  for (int k = 0; k < 2 && p.num_edges() > 0; ++k) {
    const int e = static_cast<int>(rng() % p.num_edges());
    if (p.is_outer(e)) continue;
    const int w = p.add_node(0);
    const End b = p.end_b[e];
    p.end_b[e] = End{w, true};
    const int64_t lo = -static_cast<int64_t>(rng() % 3), up = lo + 2 + rng() % 6;
    p.add_edge(End{w, false}, b, lo, up, testing::random_cost(rng, {}, lo, up));
  }
  return p;
}

// Each edge's cost minimizer, parity-repaired by the spanning-tree T-join.
detail::ParityRepair tjoin_repaired_minimizers(const Problem& p) {
  std::vector<int64_t> g(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) g[e] = p.cost[e].argmin(p.lower[e], p.upper[e]);
  return detail::repair_parity(p, g, detail::ParityMode::SpanningTreeTJoin);
}

// The reduced problem's optimum, lifted, is feasible for the original and as good as its
// optimum; infeasibility is preserved. `lift` maps a reduced flow to an original one.
template <typename Lift>
void expect_equivalent(const Problem& original, const Problem& reduced, const Lift& lift,
                       int instance) {
  const auto truth = brute_force(original);
  const auto r = brute_force(reduced);
  ASSERT_EQ(r.feasible, truth.feasible) << "instance " << instance;
  if (!r.feasible) return;
  const std::vector<int64_t> x = lift(r.flow);
  const FlowCheck check = check_flow(original, x);
  ASSERT_TRUE(check.feasible()) << "instance " << instance;
  EXPECT_TRUE(testing::relatively_close(check.objective, truth.optimum)) << "instance " << instance;
}

TEST(Reductions, FixedEdgesLiftExactly) {
  std::mt19937_64 rng(21);
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = tiny(rng, i);
    const auto red = detail::eliminate_fixed_edges(p);
    for (int e = 0; e < red.reduced.num_edges(); ++e)
      ASSERT_LT(red.reduced.lower[e], red.reduced.upper[e]);
    expect_equivalent(
        p, red.reduced, [&](const auto& f) { return red.lift(f); }, i);
  }
}

TEST(Reductions, OuterEdgesLiftExactly) {
  std::mt19937_64 rng(22);
  int with_outer = 0;
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = tiny(rng, i);
    const auto red = detail::eliminate_outer_edges(p);
    for (int e = 0; e < red.reduced.num_edges(); ++e) ASSERT_FALSE(red.reduced.is_outer(e));
    with_outer += red.boundary_node >= 0;
    expect_equivalent(
        p, red.reduced, [&](const auto& f) { return red.lift(f); }, i);
  }
  EXPECT_GT(with_outer, kInstances / 4);
}

TEST(Reductions, ChainsLiftExactly) {
  std::mt19937_64 rng(23);
  int collapsed = 0;
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = detail::eliminate_outer_edges(subdivided(tiny(rng, i), rng)).reduced;
    const auto red = detail::collapse_chains(p);
    collapsed += red.collapsed_nodes > 0;
    if (red.empty_chain_edge >= 0) {
      EXPECT_FALSE(brute_force(p).feasible) << "instance " << i;
      continue;
    }
    expect_equivalent(
        p, red.reduced, [&](const auto& f) { return red.lift(f); }, i);
  }
  EXPECT_GT(collapsed, kInstances / 2);
}

TEST(Reductions, ComponentsLiftExactly) {
  std::mt19937_64 rng(24);
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = tiny(rng, i);
    const auto split = detail::split_components(p);
    std::vector<std::vector<int64_t>> flows;
    bool feasible = true;
    for (const Problem& part : split.parts) {
      const auto r = brute_force(part);
      feasible = feasible && r.feasible;
      flows.push_back(r.flow);
    }
    const auto truth = brute_force(p);
    ASSERT_EQ(feasible, truth.feasible) << "instance " << i;
    if (!feasible) continue;
    const FlowCheck check = check_flow(p, split.lift(flows));
    ASSERT_TRUE(check.feasible());
    EXPECT_TRUE(testing::relatively_close(check.objective, truth.optimum)) << "instance " << i;
  }
}

// Parity repair keeps the guess within bounds and makes every residual even, or proves the
// problem infeasible.
TEST(Reductions, ParityRepairEvensResidualsOrProvesInfeasibility) {
  std::mt19937_64 rng(25);
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = detail::eliminate_outer_edges(tiny(rng, i)).reduced;
    std::vector<int64_t> g(p.num_edges());
    for (int e = 0; e < p.num_edges(); ++e) g[e] = p.cost[e].argmin(p.lower[e], p.upper[e]);
    for (auto mode : {detail::ParityMode::SpanningTreeTJoin, detail::ParityMode::RoundToEven}) {
      const auto r = detail::repair_parity(p, g, mode);
      if (r.odd_node >= 0) {
        EXPECT_FALSE(brute_force(p).feasible) << "instance " << i;
        continue;
      }
      std::vector<int64_t> residual = p.demand;
      for (int e = 0; e < p.num_edges(); ++e) {
        ASSERT_GE(r.guess[e], p.lower[e]);
        ASSERT_LE(r.guess[e], p.upper[e]);
        residual[p.end_a[e].node] -= p.end_a[e].sign() * r.guess[e];
        residual[p.end_b[e].node] -= p.end_b[e].sign() * r.guess[e];
      }
      for (int64_t b : residual) ASSERT_EQ(b % 2, 0) << "instance " << i;
    }
  }
}

// The backend's duals certify its flow: complementary slackness on every arc, and the scaled
// costs are the llround(c·S) it promises.
void expect_optimal_duals(const detail::DirectedMcf& mcf, const detail::MinCostFlowResult& r,
                          int instance) {
  for (int a = 0; a < mcf.num_arcs(); ++a) {
    ASSERT_EQ(r.scaled_cost[a], std::llround(mcf.cost[a] * r.cost_scale))
        << "instance " << instance;
    if (r.reduced_cost[a] > 0) {
      ASSERT_EQ(r.flow[a], 0) << "instance " << instance << " arc " << a;
    }
    if (r.reduced_cost[a] < 0) {
      ASSERT_EQ(r.flow[a], mcf.capacity[a]) << "instance " << instance << " arc " << a;
    }
  }
}

// Linearization + any double cover: whenever the cover's min-cost flow exists, it lifts to a
// feasible flow of the problem; the relaxation is feasible whenever the problem is.
TEST(Reductions, DoubleCoversLiftToFeasibleFlows) {
  std::mt19937_64 rng(26);
  int lifted = 0;
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = detail::eliminate_outer_edges(tiny(rng, i)).reduced;
    const auto repaired = tjoin_repaired_minimizers(p);
    if (repaired.odd_node >= 0) continue;
    const auto lin = detail::linearize(p, repaired.guess, {});
    const bool feasible = brute_force(p).feasible;
    for (auto kind :
         {detail::DoubleCoverKind::Asymmetric, detail::DoubleCoverKind::AsymmetricSwapped,
          detail::DoubleCoverKind::Symmetric, detail::DoubleCoverKind::Relaxation}) {
      const auto dc = detail::build_double_cover(lin.mcf, kind);
      const auto r = detail::solve_min_cost_flow(dc.mcf);
      if (r.status == detail::MinCostFlowStatus::Optimal) expect_optimal_duals(dc.mcf, r, i);
      if (kind == detail::DoubleCoverKind::Relaxation) {
        if (feasible) {
          EXPECT_EQ(r.status, detail::MinCostFlowStatus::Optimal) << "instance " << i;
        }
        continue;
      }
      if (r.status != detail::MinCostFlowStatus::Optimal) continue;
      const auto x = lin.lift(dc.lift(r.flow, lin.mcf.num_arcs()));
      ASSERT_TRUE(check_flow(p, x).feasible()) << "instance " << i;
      ++lifted;
    }
  }
  EXPECT_GT(lifted, kInstances);
}

// Reduced-cost fixing of a refinement round, against brute force on the box x ± 2 (the integer
// circulations of the residual are exactly the flows in that box): a proof of optimality means
// no better flow in the box, an integral LP optimum is the box optimum, and an improving
// circulation — the box optimum, written with each edge's cheapest pieces first — never needs
// a fixed arc.
TEST(Reductions, ResidualPruningKeepsEveryImprovingCirculation) {
  std::mt19937_64 rng(28);
  int proofs = 0, integral = 0, improving = 0, fixed = 0;
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = detail::eliminate_outer_edges(tiny(rng, i)).reduced;
    // A feasible, usually non-optimal flow: the optimum for other costs.
    Problem other = p;
    for (int e = 0; e < p.num_edges(); ++e)
      other.cost[e] = testing::random_cost(rng, {}, p.lower[e], p.upper[e]);
    const auto start = brute_force(other);
    if (!start.feasible) continue;
    const std::vector<int64_t>& x = start.flow;
    detail::LinearizeOptions unit;
    unit.max_deviation = 2;
    unit.step = 1;
    unit.tails = false;
    const detail::Linearization lin = detail::linearize(p, x, unit);
    const detail::ResidualPruning pruned = detail::prune_residual(lin.mcf);
    fixed += static_cast<int>(pruned.fixed_arcs);

    Problem box = p;
    for (int e = 0; e < p.num_edges(); ++e) {
      box.lower[e] = std::max(p.lower[e], x[e] - 2);
      box.upper[e] = std::min(p.upper[e], x[e] + 2);
    }
    const auto best = brute_force(box);
    ASSERT_TRUE(best.feasible) << "instance " << i;
    const double cost_x = objective(p, x);
    const bool improves = best.optimum < cost_x - 1e-9 * std::max(1.0, std::fabs(cost_x));
    if (pruned.proves_optimal) {
      ++proofs;
      ASSERT_FALSE(improves) << "instance " << i;
    }
    if (!pruned.integral_circulation.empty()) {
      ++integral;
      EXPECT_TRUE(testing::relatively_close(objective(p, lin.lift(pruned.integral_circulation)),
                                            best.optimum))
          << "instance " << i;
    }
    if (!improves) continue;
    ++improving;
    std::vector<char> free_arc(lin.mcf.num_arcs(), 0);
    for (int a : pruned.arc_of) free_arc[a] = 1;
    std::vector<int64_t> left(p.num_edges());
    for (int e = 0; e < p.num_edges(); ++e) left[e] = best.flow[e] - x[e];
    for (int a = 0; a < lin.mcf.num_arcs(); ++a) {  // pieces of an edge come cheapest first
      const int e = lin.arc_edge[a];
      if (left[e] * lin.arc_direction[a] <= 0) continue;
      const int64_t use = std::min<int64_t>(std::abs(left[e]), lin.mcf.capacity[a]);
      left[e] -= lin.arc_direction[a] * use;
      ASSERT_TRUE(free_arc[a]) << "instance " << i << ": arc " << a << " of edge " << e;
    }
  }
  EXPECT_GT(proofs, kInstances / 20);
  EXPECT_GT(improving, kInstances / 20);
  EXPECT_GT(fixed, 0);
  std::cout << "[ suite    ] residual pruning: " << proofs << " proofs, " << integral
            << " integral optima, " << improving << " improving, " << fixed << " arcs fixed\n";
}

// A tiny zero-demand Bi-MCF for the b-matching tests: up to `max_nodes` nodes, up to 6 arcs.
detail::BiMcf tiny_bimcf(std::mt19937_64& rng, int max_nodes) {
  detail::BiMcf c;
  const int n = 1 + static_cast<int>(rng() % max_nodes), m = static_cast<int>(rng() % 7);
  c.demand.assign(n, 0);
  for (int a = 0; a < m; ++a) {
    c.end_a.push_back(End{static_cast<int>(rng() % n), rng() % 2 == 0});
    c.end_b.push_back(End{static_cast<int>(rng() % n), rng() % 2 == 0});
    c.capacity.push_back(1 + static_cast<int64_t>(rng() % 2));
    c.cost.push_back(static_cast<double>(static_cast<int>(rng() % 9) - 5));
  }
  return c;
}

// The cheapest circulation y (0 ≤ y ≤ capacity) that `within_limits` accepts, by enumeration:
// its cost (0, the zero circulation, at most).
double cheapest_circulation(const detail::BiMcf& c,
                            const std::function<bool(const std::vector<int64_t>&)>& within_limits) {
  const int n = c.num_nodes(), m = c.num_arcs();
  double best = 0;
  std::vector<int64_t> y(m, 0);
  while (true) {
    std::vector<int64_t> balance(n, 0);
    double cost = 0;
    for (int a = 0; a < m; ++a) {
      for (const End& e : {c.end_a[a], c.end_b[a]}) balance[e.node] += e.sign() * y[a];
      cost += c.cost[a] * static_cast<double>(y[a]);
    }
    if (std::all_of(balance.begin(), balance.end(), [](int64_t b) { return b == 0; }) &&
        within_limits(y))
      best = std::min(best, cost);
    int a = 0;
    while (a < m && y[a] == c.capacity[a]) y[a++] = 0;
    if (a == m) break;
    ++y[a];
  }
  return best;
}

// The circulation the b-matching reduction's maximum-weight perfect matching (gadgets, LEMON)
// gives.
std::vector<int64_t> bmatching_circulation(const detail::BiMcf& c, const detail::Throughflow& tf) {
  const detail::BMatchingReduction bm = detail::reduce_to_bmatching(c, tf);
  const detail::MatchingReduction mm = detail::reduce_to_perfect_matching(bm.bmatching);
  const auto matched = detail::max_weight_perfect_matching(mm.graph);
  if (!matched) return {};  // a failure: the all-slack matching always exists
  return bm.lift(mm.lift(*matched, bm.bmatching.num_edges()), c.num_arcs());
}

double circulation_cost(const detail::BiMcf& c, const std::vector<int64_t>& y) {
  double cost = 0;
  for (int a = 0; a < c.num_arcs(); ++a) cost += c.cost[a] * static_cast<double>(y[a]);
  return cost;
}

// The b-matching reduction with a throughflow limit per node (bmatching.hpp): the maximum-weight
// perfect b-matching, through the perfect-matching gadgets and LEMON, is the cheapest
// circulation whose head-side flow at each node v stays within K(v), found by enumeration.
TEST(Reductions, BMatchingIsTheCheapestCirculationWithinEachNodesThroughflow) {
  std::mt19937_64 rng(31);
  int nonzero = 0;
  for (int i = 0; i < testing::scaled(600); ++i) {
    const detail::BiMcf c = tiny_bimcf(rng, 4);
    const int n = c.num_nodes();
    std::vector<int> k(n);
    for (int& kv : k) kv = 1 + static_cast<int>(rng() % 4);
    const double best = cheapest_circulation(c, [&](const std::vector<int64_t>& y) {
      std::vector<int64_t> head_side(n, 0);
      for (int a = 0; a < c.num_arcs(); ++a)
        for (const End& e : {c.end_a[a], c.end_b[a]})
          if (e.head) head_side[e.node] += y[a];
      for (int v = 0; v < n; ++v)
        if (head_side[v] > k[v]) return false;
      return true;
    });
    const std::vector<int64_t> flow = bmatching_circulation(c, {k, {}});
    ASSERT_EQ(flow.size(), c.capacity.size()) << "instance " << i;
    EXPECT_EQ(circulation_cost(c, flow), best) << "instance " << i;
    nonzero += best < 0;
  }
  EXPECT_GT(nonzero, testing::scaled(600) / 10);
}

// The same with tiers (bmatching.hpp): a tiered node's limit is per part, the i-th of the E arc
// ends at a side going to part ⌊i·parts/E⌋ (parts = min(⌈K/P⌉, the larger side's E), at least
// 1; a loop is one end that takes two units), each part carrying at most its degree P units.
TEST(Reductions, TieredBMatchingIsTheCheapestCirculationWithinEachPartsLimit) {
  std::mt19937_64 rng(37);
  constexpr int kTierAbove = 2, kPartDegree = 2;
  int nonzero = 0, tiered_used = 0;
  for (int i = 0; i < testing::scaled(600); ++i) {
    const detail::BiMcf c = tiny_bimcf(rng, 3);
    const int n = c.num_nodes(), m = c.num_arcs();
    std::vector<int> k(n);
    for (int& kv : k) kv = 1 + static_cast<int>(rng() % 6);
    // Each side's ends in arc order, with the part they fall into.
    auto side = [](End e) { return 2 * e.node + (e.head ? 0 : 1); };
    std::vector<int> ends(2 * n, 0);
    for (int a = 0; a < m; ++a) {
      ++ends[side(c.end_a[a])];
      if (side(c.end_b[a]) != side(c.end_a[a])) ++ends[side(c.end_b[a])];
    }
    std::vector<int> parts(2 * n), seen(2 * n, 0), part_a(m), part_b(m);
    for (int s = 0; s < 2 * n; ++s)
      parts[s] = std::max(1, std::min((k[s / 2] + kPartDegree - 1) / kPartDegree,
                                      std::max(ends[s & ~1], ends[s | 1])));
    for (int a = 0; a < m; ++a) {
      const int sa = side(c.end_a[a]), sb = side(c.end_b[a]);
      part_a[a] = seen[sa]++ * parts[sa] / ends[sa];
      part_b[a] = sb == sa ? part_a[a] : seen[sb]++ * parts[sb] / ends[sb];
    }
    const double best = cheapest_circulation(c, [&](const std::vector<int64_t>& y) {
      std::vector<int64_t> head_side(n, 0);
      std::vector<std::vector<int64_t>> part_use(2 * n);
      for (int s = 0; s < 2 * n; ++s) part_use[s].assign(parts[s], 0);
      for (int a = 0; a < m; ++a) {
        for (const End& e : {c.end_a[a], c.end_b[a]})
          if (e.head) head_side[e.node] += y[a];
        part_use[side(c.end_a[a])][part_a[a]] += y[a];
        part_use[side(c.end_b[a])][part_b[a]] += y[a];
      }
      for (int v = 0; v < n; ++v) {
        if (k[v] <= kTierAbove && head_side[v] > k[v]) return false;
        if (k[v] <= kTierAbove) continue;
        for (int s : {2 * v, 2 * v + 1})
          for (int64_t u : part_use[s])
            if (u > kPartDegree) return false;
      }
      return true;
    });
    detail::Throughflow tf{k, std::vector<int>(n, 0)};
    for (int v = 0; v < n; ++v)
      if (k[v] > kTierAbove) tf.part_degree[v] = kPartDegree;
    const std::vector<int64_t> flow = bmatching_circulation(c, tf);
    ASSERT_EQ(flow.size(), c.capacity.size()) << "instance " << i;
    EXPECT_EQ(circulation_cost(c, flow), best) << "instance " << i;
    nonzero += best < 0;
    bool uses_tier = false;
    for (int a = 0; a < m; ++a)
      uses_tier =
          uses_tier ||
          (flow[a] > 0 && (k[c.end_a[a].node] > kTierAbove || k[c.end_b[a].node] > kTierAbove));
    tiered_used += uses_tier;
  }
  EXPECT_GT(nonzero, testing::scaled(600) / 10);
  EXPECT_GT(tiered_used, testing::scaled(600) / 10);
}

// Refinement's throughflow limits: 2 at ordinary nodes, kBusyThroughflow from kBusyArcs arcs,
// more at hubs (in tiers), at most kMaxThroughflow.
TEST(Reductions, HubsGetLargerThroughflowLimits) {
  detail::BiMcf c;
  c.demand.assign(4, 0);
  auto arcs = [&](int v, int w, int count) {
    for (int i = 0; i < count; ++i) {
      c.end_a.push_back(End{v, true});
      c.end_b.push_back(End{w, false});
      c.capacity.push_back(1);
      c.cost.push_back(1);
    }
  };
  static_assert(detail::kBusyArcs == 24 && detail::kHubArcs == 128);
  arcs(0, 1, 127);  // node 0: 127 arcs, node 1: 127 + 10
  arcs(1, 2, 10);   // node 2: 10 + 9000
  arcs(2, 3, 9000);
  const detail::Throughflow tf = detail::refinement_throughflow(c);
  const int pd = detail::kTierPartDegree, busy = detail::kBusyThroughflow;
  EXPECT_EQ(tf.limit,
            (std::vector<int>{busy, 8, detail::kMaxThroughflow, detail::kMaxThroughflow}));
  EXPECT_EQ(tf.part_degree, (std::vector<int>{0, pd, pd, pd}));
  // The first 137 arcs only: nodes 2 and 3 are ordinary (10 and 0 arcs).
  c.end_a.resize(137), c.end_b.resize(137), c.capacity.resize(137), c.cost.resize(137);
  const detail::Throughflow fewer = detail::refinement_throughflow(c);
  EXPECT_EQ(fewer.limit, (std::vector<int>{busy, 8, 2, 2}));
  EXPECT_EQ(fewer.part_degree, (std::vector<int>{0, pd, 0, 0}));
  arcs(3, 0, 24);  // node 3: 24 arcs (busy), node 0: 151 (hub)
  arcs(2, 1, 13);  // node 2: 23 (still ordinary), node 1: 150
  const detail::Throughflow more = detail::refinement_throughflow(c);
  EXPECT_EQ(more.limit, (std::vector<int>{8, 8, 2, busy}));
  EXPECT_EQ(more.part_degree, (std::vector<int>{pd, pd, 0, 0}));
}

// Phase 1 (the approximation's last resort) with exact refinement: the artificial flow goes to
// zero exactly when the problem is feasible, and then the lifted flow is feasible.
TEST(Reductions, PhaseOneRefinementDecidesFeasibility) {
  std::mt19937_64 rng(27);
  int feasible_count = 0;
  for (int i = 0; i < kInstances; ++i) {
    const Problem p = detail::eliminate_outer_edges(tiny(rng, i)).reduced;
    const auto repaired = tjoin_repaired_minimizers(p);
    if (repaired.odd_node >= 0) continue;
    const detail::PhaseOne phase_one = detail::build_phase_one(p, repaired.guess);
    const detail::RefineResult refined = detail::refine(phase_one.problem, phase_one.start);
    ASSERT_TRUE(refined.converged);
    const bool feasible = phase_one.artificial_flow(refined.flow) == 0;
    ASSERT_EQ(feasible, brute_force(p).feasible) << "instance " << i;
    if (!feasible) continue;
    ++feasible_count;
    ASSERT_TRUE(check_flow(p, phase_one.lift(refined.flow)).feasible()) << "instance " << i;
  }
  EXPECT_GT(feasible_count, kInstances / 4);
}

}  // namespace
}  // namespace bimdf

namespace {

// Recursion that needs depth * (sizeof pad + frame) bytes of stack: 200000 levels of 256-byte
// pads need more than 50 MiB, far beyond the default 8 MiB.
int deep_recursion(int depth) {
  volatile char pad[256];
  pad[depth % 256] = static_cast<char>(depth);
  if (depth == 0) return pad[0];
  return deep_recursion(depth - 1) + (pad[depth % 256] == static_cast<char>(depth));
}

}  // namespace

TEST(DeepStack, RecursionDeeperThanTheDefaultStackCompletes) {
  int result = -1;
  bimdf::detail::run_with_stack(std::size_t{512} << 20, [&] { result = deep_recursion(200000); });
  EXPECT_EQ(result, 200000);
}

TEST(DeepStack, ExceptionsReachTheCaller) {
  EXPECT_THROW(bimdf::detail::run_with_stack(
                   std::size_t{64} << 20, [] { throw std::runtime_error("from the deep thread"); }),
               std::runtime_error);
}
