// bimdf's JSON problem, solution and flow formats.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "bimdf/io.hpp"
#include "random_problem.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

TEST(JsonFormat, ReadsNamesReferencesAndDefaults) {
  const Problem p = parse_json_problem(R"({
    "format": "bimdf-problem", "version": 1,
    "nodes": [{"name": "a", "demand": 2}, {"name": "b"}, {}],
    "edges": [
      {"ends": [["a", "head"], ["b", "tail"]], "name": "ab"},
      {"ends": [[2, "tail"], [2, "tail"]], "lower": 1, "upper": 4,
       "cost": {"kind": "sum", "terms": [{"kind": "abs", "target": 1.5, "weight": 2},
                                         {"kind": "quad", "target": 1, "weight": 0.5}]}},
      {"ends": [["b", "head"]], "lower": "-inf", "cost": {"kind": "quad", "target": 2, "weight": 1}},
      {"ends": [["a", "tail"]], "cost": {"kind": "scale_factor", "target": 2, "weight": 1}}
    ]})",
                                       "p.json");
  ASSERT_EQ(p.num_nodes(), 3);
  ASSERT_EQ(p.num_edges(), 4);
  EXPECT_EQ(p.demand, (std::vector<int64_t>{2, 0, 0}));
  EXPECT_EQ(p.node_name, (std::vector<std::string>{"a", "b", ""}));
  EXPECT_EQ(p.edge_name, (std::vector<std::string>{"ab", "", "", ""}));
  EXPECT_EQ(p.end_a[0], (End{0, true}));
  EXPECT_EQ(p.end_b[0], (End{1, false}));
  EXPECT_EQ(p.lower[0], 0);
  EXPECT_EQ(p.upper[0], kInfinity);
  EXPECT_EQ(p.cost[0], Cost::zero());
  EXPECT_EQ(p.edge_kind(1), EdgeKind::LoopTails);
  EXPECT_EQ(p.cost[1], Cost::sum({Cost::abs_deviation(1.5, 2), Cost::quad_deviation(1, 0.5)}));
  EXPECT_EQ(p.edge_kind(2), EdgeKind::OuterHead);
  EXPECT_EQ(p.lower[2], -kInfinity);
  EXPECT_EQ(p.edge_kind(3), EdgeKind::OuterTail);
  EXPECT_EQ(p.cost[3], Cost::scale_factor(2, 1, 0.1));  // eps defaults to libSatsuma's 0.1
}

TEST(JsonFormat, RandomProblemsRoundTripExactly) {
  std::mt19937_64 rng(3);
  testing::RandomProblemOptions options;
  options.names = true;
  for (int i = 0; i < 3000; ++i) {
    const Problem p = testing::random_problem(rng, options);
    const std::string text = to_json_problem(p);
    const Problem q = parse_json_problem(text, "roundtrip.json");
    ASSERT_EQ(p, q) << text;
    ASSERT_EQ(to_json_problem(q), text);
    // And across formats: JSON -> .bimdf -> JSON keeps everything but the names.
    Problem unnamed = p;
    unnamed.node_name.clear();
    unnamed.edge_name.clear();
    ASSERT_EQ(parse_bimdf(to_bimdf(q)), unnamed);
  }
}

TEST(JsonFormat, FormatIsDetectedByContent) {
  EXPECT_EQ(detect_problem_format("  \n{\"nodes\": []}"), ProblemFormat::Json);
  EXPECT_EQ(detect_problem_format("# x\n1\n0\n0\n"), ProblemFormat::Bimdf);
  const Problem p = parse_problem(R"({"nodes": [{"demand": 0}], "edges": []})");
  EXPECT_EQ(p.num_nodes(), 1);
}

TEST(JsonFormat, SolutionHasTheContractFields) {
  Solution s;
  s.status = SolveStatus::Optimal;
  s.objective = 1.25;
  s.flow = {1, -2, 3};
  s.stats["iterations"] = int64_t{4};
  s.stats["path"] = std::string("double cover");
  s.stats["seconds"] = 0.5;
  s.stats["verified"] = true;
  const auto j = nlohmann::json::parse(to_json_solution(s));
  EXPECT_EQ(j["status"], "optimal");
  EXPECT_EQ(j["objective"], 1.25);
  EXPECT_EQ(j["flow"], nlohmann::json::array({1, -2, 3}));
  EXPECT_EQ(j["stats"]["iterations"], 4);
  EXPECT_EQ(j["stats"]["path"], "double cover");
  EXPECT_EQ(j["stats"]["seconds"], 0.5);
  EXPECT_EQ(j["stats"]["verified"], true);
  EXPECT_EQ(parse_flow(to_json_solution(s)), s.flow);
}

TEST(JsonFormat, FlowsInThreeForms) {
  EXPECT_EQ(parse_flow("[1, 2, -3]"), (std::vector<int64_t>{1, 2, -3}));
  EXPECT_EQ(parse_flow("1 2\n-3\n"), (std::vector<int64_t>{1, 2, -3}));
  EXPECT_EQ(parse_flow(R"({"status": "feasible", "flow": [4]})"), (std::vector<int64_t>{4}));
  EXPECT_EQ(parse_flow(""), std::vector<int64_t>{});
  EXPECT_EQ(testing::input_error_of([] { parse_flow("1 2 x", "f.txt"); }),
            "f.txt:1: expected flow value 2 (an integer), got 'x'");
  EXPECT_EQ(testing::input_error_of([] { parse_flow("[1, 2.5]", "f.json"); }),
            "f.json: /1: expected an integer flow value, got 2.5");
  EXPECT_EQ(testing::input_error_of([] { parse_flow(R"({"x": 1})", "s.json"); }),
            "s.json: /flow: missing: expected the solution's flow array");
}

}  // namespace
}  // namespace bimdf
