// One test per class of invalid input, asserting the whole message: it must name the file, the
// line (text) or JSON path, the node or edge, and what was expected.
#include <gtest/gtest.h>

#include "bimdf/io.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

using testing::input_error_of;

std::string bimdf_error(const std::string& text) {
  return input_error_of([&] { parse_bimdf(text, "bad.bimdf"); });
}
std::string json_error(const std::string& text) {
  return input_error_of([&] { parse_json_problem(text, "bad.json"); });
}
// A two-node .bimdf with one edge record `edge`.
std::string one_edge(const std::string& edge) { return "# t\n2\n0\n0\n1\n" + edge + "\n"; }
// A two-node JSON problem with one edge object `edge`.
std::string json_edge(const std::string& edge) {
  return R"({"nodes": [{}, {}], "edges": [)" + edge + "]}";
}

TEST(ValidationBimdf, BadToken) {
  EXPECT_EQ(bimdf_error("# t\n2\n0\nx\n"),
            "bad.bimdf:4: expected the demand of node 1 (an integer), got 'x'");
  EXPECT_EQ(bimdf_error(one_edge("0 1 2 0 0 1 0")),
            "bad.bimdf:6: expected edge 0: the head flag of the first end (1 = head, 0 = tail), "
            "got '2'");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 X 1 2")),
            "bad.bimdf:6: edge 0: unknown cost type 'X', expected 0, A, Q, S, +, Z, L, B or P");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1.5 0")),
            "bad.bimdf:6: expected edge 0: the upper bound (an integer or inf), got '1.5'");
}

TEST(ValidationBimdf, Truncated) {
  EXPECT_EQ(bimdf_error("# t\n2\n0\n0\n1\n0 1 1 0 0 1 A 1\n"),
            "bad.bimdf:6: unexpected end of file: expected edge 0: cost A weight (a number)");
  EXPECT_EQ(bimdf_error("# t\n3\n0\n"),
            "bad.bimdf:2: the node count 3 is more than the rest of the file can hold "
            "(truncated file?)");
}

TEST(ValidationBimdf, WrongCounts) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 0\n0 1 1 0 0 1 0")),
            "bad.bimdf:7: unexpected token '0' after the last edge (the file declares 1 edges)");
  EXPECT_EQ(bimdf_error("# t\n-1\n"), "bad.bimdf:2: the node count must be >= 0, got -1");
  EXPECT_EQ(bimdf_error("# t\n1\n0\n5000000000\n"),
            "bad.bimdf:4: the edge count 5000000000 is more than the rest of the file can hold "
            "(truncated file?)");
}

TEST(ValidationBimdf, NodeIdOutOfRange) {
  EXPECT_EQ(bimdf_error(one_edge("0 2 1 0 0 1 0")),
            "bad.bimdf:6: edge 0: the second node id (or -1 for an outer edge): node id 2 is out "
            "of range [0, 2)");
}

TEST(ValidationBimdf, NonNumericNanAndInfiniteParameters) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 A abc 1")),
            "bad.bimdf:6: expected edge 0: cost A target (a number), got 'abc'");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 A nan 1")),
            "bad.bimdf:6: edge 0: cost: target must be a finite number, got nan");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 Q 1 inf")),
            "bad.bimdf:6: edge 0: cost: weight must be a finite number, got inf");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 Q 1 1e999")),
            "bad.bimdf:6: edge 0: cost: weight must be a finite number, got inf");
}

TEST(ValidationBimdf, NonConvexWeights) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 A 1 -2")),
            "bad.bimdf:6: edge 0: cost: weight must be >= 0 (a negative weight makes the cost "
            "non-convex), got -2");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 + 2 A 1 1 Q 0 -0.5")),
            "bad.bimdf:6: edge 0: cost: term 1: weight must be >= 0 (a negative weight makes the "
            "cost non-convex), got -0.5");
}

TEST(ValidationBimdf, NonConvexPiecewise) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 5 P 0 4 0 2 3 3.5")),
            "bad.bimdf:6: edge 0: cost: piecewise-linear cost is not convex at x = 1: slope 2 "
            "before it, 1 after it (slopes must not decrease)");
}

TEST(ValidationBimdf, LowerAboveUpper) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 3 1 0")),
            "bad.bimdf:6: edge 0: lower bound 3 is greater than upper bound 1");
}

TEST(ValidationBimdf, HeadTailLoop) {
  EXPECT_EQ(bimdf_error(one_edge("1 1 1 0 0 1 0")),
            "bad.bimdf:6: edge 0: head-tail loop at node 1 has no effect on conservation; "
            "expected head-head or tail-tail");
}

TEST(ValidationBimdf, UnboundedEdgeWithoutMinimum) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 inf L -1")),
            "bad.bimdf:6: edge 0: cost: cost decreases without limit as the flow grows (slope -1 "
            "at +inf) but the upper bound is infinite: the cost has no minimum");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 -inf 3 L 1")),
            "bad.bimdf:6: edge 0: cost: cost decreases without limit as the flow falls (slope 1 "
            "at -inf) but the lower bound is infinite: the cost has no minimum");
}

TEST(ValidationBimdf, OverflowProneMagnitudes) {
  EXPECT_EQ(bimdf_error("# t\n1\n2199023255552\n0\n"),
            "bad.bimdf:3: node 0: demand must be within +-2^40 (1099511627776), got 2199023255552");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 2199023255552 0")),
            "bad.bimdf:6: edge 0: upper bound must be within +-2^40 (1099511627776) or inf, got "
            "2199023255552");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 99999999999999999999 inf 0")),
            "bad.bimdf:6: expected edge 0: the lower bound (an integer or inf), got "
            "'99999999999999999999'");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 A 1 1e16")),
            "bad.bimdf:6: edge 0: cost: weight must be <= 1e15, got 10000000000000000");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 A 1e13 1")),
            "bad.bimdf:6: edge 0: cost: target must be within +-2^40 (the flow range), got "
            "10000000000000");
}

TEST(ValidationBimdf, ScaleFactorDomain) {
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 -1 1 S 1 1 0.1")),
            "bad.bimdf:6: edge 0: cost: a scale-factor cost is only defined for flow > -eps "
            "(-0.10000000000000001), so the lower bound must be > -eps, got -1");
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 S 1 1 0")),
            "bad.bimdf:6: edge 0: cost: eps must be a finite number > 0, got 0");
}

TEST(ValidationBimdf, OuterEdgeSyntax) {
  EXPECT_EQ(bimdf_error(one_edge("0 -1 1 0 0 1 0")),
            "bad.bimdf:6: edge 0: an outer edge (second node -1) needs '-' as its second head "
            "flag, got '0'");
}

TEST(ValidationBimdf, DeeplyNestedSumsAreRejectedNotOverflowed) {
  std::string cost;
  for (int i = 0; i < 100; ++i) cost += "+ 1 ";
  EXPECT_EQ(bimdf_error(one_edge("0 1 1 0 0 1 " + cost + "0")),
            "bad.bimdf:6: edge 0: cost sums nested deeper than 64");
}

TEST(ValidationBimdf, InfeasibleIsNotAnInputError) {
  // Odd demand at a node whose only edge is a head-head loop: no flow exists, but the problem
  // is well-formed and must load (solving it answers "infeasible").
  const Problem p = parse_bimdf("# t\n1\n1\n1\n0 0 1 1 0 inf 0\n", "odd.bimdf");
  EXPECT_EQ(p.num_edges(), 1);
}

TEST(ValidationJson, Syntax) {
  EXPECT_EQ(json_error("{\"nodes\": [\n{},\n}"),
            "bad.json:3: invalid JSON: syntax error while parsing value - unexpected '}'; "
            "expected '[', '{', or a literal");
  EXPECT_EQ(json_error("[1]"), "bad.json: /: expected a JSON object with \"nodes\" and \"edges\"");
}

TEST(ValidationJson, Structure) {
  EXPECT_EQ(json_error(R"({"nodes": [], "edges": [], "egdes": []})"),
            "bad.json: /egdes: unknown key \"egdes\" (expected one of: format, version, nodes, "
            "edges, comment)");
  EXPECT_EQ(json_error(R"({"nodes": []})"),
            "bad.json: /edges: missing: expected an array of edges");
  EXPECT_EQ(json_error(json_edge(R"({"lower": 0})")),
            "bad.json: /edges/0/ends: missing: expected one or two ends");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[0, "up"]]})")),
            "bad.json: /edges/0/ends/0/1: expected \"head\" or \"tail\", got \"up\"");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[0, "head"], [0, "tail"], [1, "head"]]})")),
            "bad.json: /edges/0/ends: expected an array of one or two ends, got "
            "[[0,\"head\"],[0,\"tail\"],[1,\"head\"]]");
}

TEST(ValidationJson, NodeReferences) {
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[5, "head"]]})")),
            "bad.json: /edges/0/ends/0/0: node id 5 is out of range [0, 2)");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [["z", "head"]]})")),
            "bad.json: /edges/0/ends/0/0: unknown node name \"z\"");
  EXPECT_EQ(json_error(R"({"nodes": [{"name": "a"}, {"name": "a"}], "edges": []})"),
            "bad.json: /nodes/1/name: duplicate node name \"a\"");
}

TEST(ValidationJson, Numbers) {
  EXPECT_EQ(json_error(R"({"nodes": [{"demand": 1.5}], "edges": []})"),
            "bad.json: /nodes/0/demand: expected a demand (an integer), got 1.5");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[0, "head"]], "upper": "lots"})")),
            "bad.json: /edges/0/upper: expected an integer or \"inf\", got \"lots\"");
  EXPECT_EQ(json_error(json_edge(
                R"({"ends": [[0, "head"]], "cost": {"kind": "abs", "target": "1", "weight": 1}})")),
            "bad.json: /edges/0/cost/target: expected target (a number), got \"1\"");
  EXPECT_EQ(
      json_error(json_edge(
          R"({"ends": [[0, "head"]], "cost": {"kind": "abs", "target": 1e400, "weight": 1}})")),
      "bad.json: invalid JSON: number overflow parsing '1e400'");
}

TEST(ValidationJson, Costs) {
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[0, "head"]], "cost": {"kind": "cubic"}})")),
            "bad.json: /edges/0/cost/kind: unknown cost kind \"cubic\" (expected zero, linear, "
            "abs, asym_abs, quad, piecewise, scale_factor or sum)");
  EXPECT_EQ(json_error(json_edge(
                R"({"ends": [[0, "head"]], "cost": {"kind": "abs", "target": 1, "wieght": 1}})")),
            "bad.json: /edges/0/cost/wieght: unknown key \"wieght\" (expected one of: kind, "
            "target, weight)");
  EXPECT_EQ(
      json_error(json_edge(R"({"ends": [[0, "head"]], "cost": {"kind": "quad", "target": 1}})")),
      "bad.json: /edges/0/cost/weight: missing: a quad cost needs \"weight\"");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[0, "head"]], "upper": 3,
      "cost": {"kind": "asym_abs", "target": 1, "weight_below": -1, "weight_above": 1}})")),
            "bad.json: /edges/0/cost: edge 0: weight_below must be >= 0 (a negative "
            "weight_below makes the cost non-convex), got -1");
  EXPECT_EQ(
      json_error(json_edge(
          R"({"ends": [[0, "head"]], "cost": {"kind": "piecewise", "first": 0, "values": [0, 1, 1]}})")),
      "bad.json: /edges/0/cost: edge 0: piecewise-linear cost is not convex at x = 1: "
      "slope 1 before it, 0 after it (slopes must not decrease)");
}

TEST(ValidationJson, ModelRules) {
  EXPECT_EQ(json_error(json_edge(
                R"({"ends": [[0, "head"], [1, "tail"]], "lower": 2, "upper": 1, "name": "e"})")),
            "bad.json: /edges/0/lower: edge 0 ('e'): lower bound 2 is greater than upper bound 1");
  EXPECT_EQ(json_error(json_edge(R"({"ends": [[1, "head"], [1, "tail"]]})")),
            "bad.json: /edges/0/ends: edge 0: head-tail loop at node 1 has no effect on "
            "conservation; expected head-head or tail-tail");
  EXPECT_EQ(
      json_error(json_edge(R"({"ends": [[0, "head"]], "cost": {"kind": "linear", "slope": -2}})")),
      "bad.json: /edges/0/cost: edge 0: cost decreases without limit as the flow grows "
      "(slope -2 at +inf) but the upper bound is infinite: the cost has no minimum");
  EXPECT_EQ(json_error(R"({"nodes": [{"demand": 2199023255552}], "edges": []})"),
            "bad.json: /nodes/0/demand: node 0: demand must be within +-2^40 (1099511627776), got "
            "2199023255552");
}

TEST(ValidationModel, ValidateReportsFieldAndIndex) {
  Problem p;
  p.add_node();
  p.add_edge({0, true}, End{0, true}, 0, 1, Cost::zero());
  p.add_edge({0, true}, End{3, true}, 0, 1, Cost::zero());
  const auto issue = validate(p);
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->where, ProblemIssue::Where::Edge);
  EXPECT_EQ(issue->index, 1);
  EXPECT_EQ(issue->field, "ends");
  EXPECT_EQ(issue->message, "node id 3 is out of range [0, 1)");
  p.lower[0] = kInfinity;
  EXPECT_EQ(validate(p)->message, "lower bound must be finite or -inf, got +inf");
  p.cost.pop_back();
  EXPECT_EQ(validate(p)->message, "per-edge arrays have different lengths");
}

}  // namespace
}  // namespace bimdf
