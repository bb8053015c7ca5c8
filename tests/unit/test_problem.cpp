// The problem model: edge kinds, components, flow verification and summaries.
#include <gtest/gtest.h>

#include "bimdf/flow.hpp"
#include "bimdf/summary.hpp"

namespace bimdf {
namespace {

// 0 -> 1 (head-tail), 1 = 2 (head-head), loop -2 at 2, outer head at 3, isolated node 4.
Problem sample() {
  Problem p;
  for (int64_t b : {-1, 3, -2, 2, 0}) p.add_node(b);
  p.add_edge({0, false}, End{1, true}, 0, kInfinity, Cost::abs_deviation(1, 1));
  p.add_edge({1, true}, End{2, true}, 0, 5, Cost::quad_deviation(2, 0.5));
  p.add_edge({2, false}, End{2, false}, 1, 1, Cost::zero());
  p.add_edge({3, true}, std::nullopt, -kInfinity, kInfinity, Cost::linear(0));
  return p;
}

TEST(Problem, EdgeKinds) {
  const Problem p = sample();
  EXPECT_EQ(p.edge_kind(0), EdgeKind::HeadTail);
  EXPECT_EQ(p.edge_kind(1), EdgeKind::HeadHead);
  EXPECT_EQ(p.edge_kind(2), EdgeKind::LoopTails);
  EXPECT_EQ(p.edge_kind(3), EdgeKind::OuterHead);
  EXPECT_STREQ(edge_kind_name(EdgeKind::LoopHeads), "loop +2");
}

TEST(Problem, ConnectedComponents) {
  int count = 0;
  EXPECT_EQ(connected_components(sample(), &count), (std::vector<int>{0, 0, 0, 1, 2}));
  EXPECT_EQ(count, 3);
}

TEST(Problem, CheckFlowAcceptsAFeasibleFlow) {
  // Conservation forces x0 = 1 (node 0), x1 = 2 (node 1), then node 2: 2 - 2·x2 = -2 -> x2 = 2,
  // outside the loop's fixed bound 1: the only flow that conserves violates a bound.
  const Problem p = sample();
  const FlowCheck bad = check_flow(p, std::vector<int64_t>{1, 2, 2, 2});
  EXPECT_FALSE(bad.feasible());
  ASSERT_EQ(bad.bound_violations.size(), 1u);
  EXPECT_EQ(bad.bound_violations[0].edge, 2);
  EXPECT_TRUE(bad.conservation_violations.empty());

  Problem q = p;
  q.demand[2] = 0;  // x = (1, 2, 1, 2): node 2 gets 2 - 2 = 0
  const FlowCheck good = check_flow(q, std::vector<int64_t>{1, 2, 1, 2});
  EXPECT_TRUE(good.feasible());
  EXPECT_DOUBLE_EQ(good.objective, 0.0 + 0.0 + 0.0 + 0.0);
  const FlowCheck off = check_flow(q, std::vector<int64_t>{3, 2, 1, 2});
  ASSERT_EQ(off.conservation_violations.size(), 2u);
  EXPECT_EQ(off.conservation_violations[0].node, 0);
  EXPECT_EQ(static_cast<int64_t>(off.conservation_violations[0].net_flow), -3);
  EXPECT_EQ(off.conservation_violations[0].demand, -1);
  EXPECT_EQ(off.conservation_violations[1].node, 1);
  EXPECT_DOUBLE_EQ(off.objective, 2.0);
}

TEST(Problem, CheckFlowIsExactForHugeValues) {
  Problem p;
  p.add_node(0);
  p.add_edge({0, true}, End{0, true}, -kInfinity, kInfinity, Cost::zero());
  // 2·x overflows int64 but not the 128-bit check.
  const FlowCheck c = check_flow(p, std::vector<int64_t>{INT64_MAX});
  ASSERT_EQ(c.conservation_violations.size(), 1u);
  EXPECT_TRUE(c.conservation_violations[0].net_flow == static_cast<__int128>(INT64_MAX) * 2);
  EXPECT_FALSE(check_flow(p, std::vector<int64_t>{1, 2}).size_ok);
}

TEST(Problem, Summary) {
  const ProblemSummary s = summarize(sample());
  EXPECT_EQ(s.nodes, 5);
  EXPECT_EQ(s.edges, 4);
  EXPECT_EQ(s.nodes_with_demand, 4);
  EXPECT_EQ(s.total_demand, 2.0);
  EXPECT_EQ(s.edge_kinds[static_cast<int>(EdgeKind::HeadTail)], 1);
  EXPECT_EQ(s.edge_kinds[static_cast<int>(EdgeKind::OuterHead)], 1);
  EXPECT_EQ(s.cost_kinds[static_cast<int>(CostKind::Zero)], 1);
  EXPECT_EQ(s.fixed_edges, 1);
  EXPECT_EQ(s.finite_upper, 2);
  EXPECT_EQ(s.positive_lower, 1);
  EXPECT_EQ(s.negative_lower, 1);
  EXPECT_EQ(s.components, 3);
  EXPECT_EQ(s.largest_component_nodes, 3);
  EXPECT_EQ(s.largest_component_edges, 3);
  // Component {0,1,2} has total demand 0: fine. {3} has an outer edge: fine. {4}: demand 0.
  EXPECT_EQ(s.parity_infeasible_components, 0);
}

TEST(Problem, SummaryFindsParityInfeasibility) {
  Problem p;
  p.add_node(1);  // odd demand, only a head-head loop: 2·x = 1 has no integer solution
  p.add_edge({0, true}, End{0, true}, 0, kInfinity, Cost::zero());
  p.add_node(2);  // head-tail edges only, total demand 2 ≠ 0
  p.add_node(0);
  p.add_edge({1, true}, End{2, false}, 0, kInfinity, Cost::zero());
  p.add_node(3);  // the same odd demand, but an outer edge can absorb it
  p.add_edge({3, true}, std::nullopt, 0, kInfinity, Cost::zero());
  EXPECT_EQ(summarize(p).parity_infeasible_components, 2);
}

TEST(Problem, SumTermsAreCountedByKind) {
  Problem p;
  p.add_node();
  p.add_edge({0, true}, End{0, true}, 0, 3,
             Cost::sum({Cost::abs_deviation(1, 1),
                        Cost::sum({Cost::quad_deviation(1, 1), Cost::abs_deviation(2, 1)})}));
  const ProblemSummary s = summarize(p);
  EXPECT_EQ(s.cost_kinds[static_cast<int>(CostKind::Sum)], 1);
  EXPECT_EQ(s.cost_terms[static_cast<int>(CostKind::AbsDeviation)], 2);
  EXPECT_EQ(s.cost_terms[static_cast<int>(CostKind::QuadDeviation)], 1);
}

}  // namespace
}  // namespace bimdf
