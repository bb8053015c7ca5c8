// The .bimdf text format: libSatsuma's files (hex floats, 2147483647 = infinity), decimal files,
// bimdf's extensions, and exact round-trips.
#include <gtest/gtest.h>

#include <random>

#include "bimdf/io.hpp"
#include "random_problem.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

using testing::input_error_of;

// The example instance from libSatsuma's study note §3.1 (decimal, as a person writes it).
constexpr const char* kNoteExample = R"(# example: boundary node 0 with free tail-tail loop
4
0
0
0
0
5
0 0 0 0 0 2147483647 0
0 1 1 1 1 2147483647 Q 4 1
1 2 0 0 0 2147483647 A 0.7 1
1 3 0 0 0 2147483647 A 0.4 1
2 3 1 1 0 2147483647 + 2 A 0.2 1 Q 1 0.5
)";

TEST(BimdfFormat, ReadsDecimalLibsatsumaFile) {
  const Problem p = parse_bimdf(kNoteExample, "note.bimdf");
  ASSERT_EQ(p.num_nodes(), 4);
  ASSERT_EQ(p.num_edges(), 5);
  EXPECT_EQ(p.demand, std::vector<int64_t>(4, 0));
  EXPECT_EQ(p.edge_kind(0), EdgeKind::LoopTails);
  EXPECT_EQ(p.edge_kind(1), EdgeKind::HeadHead);
  EXPECT_EQ(p.edge_kind(2), EdgeKind::TailTail);
  EXPECT_EQ(p.lower[1], 1);
  for (int e = 0; e < 5; ++e) EXPECT_EQ(p.upper[e], kInfinity) << e;
  EXPECT_EQ(p.cost[0], Cost::zero());
  EXPECT_EQ(p.cost[1], Cost::quad_deviation(4, 1));
  EXPECT_EQ(p.cost[2], Cost::abs_deviation(0.7, 1));
  EXPECT_EQ(p.cost[4], Cost::sum({Cost::abs_deviation(0.2, 1), Cost::quad_deviation(1, 0.5)}));
  // The note's optimum: x = (2, 4, 2, 2, 2) costs 0 + 0 + 1.3 + 1.6 + 2.3 = 5.2.
  const std::vector<int64_t> x = {2, 4, 2, 2, 2};
  double total = 0;
  for (int e = 0; e < 5; ++e) total += p.cost[e](x[e]);
  EXPECT_NEAR(total, 5.2, 1e-12);
}

TEST(BimdfFormat, ReadsHexFloatsAsLibsatsumaWritesThem) {
  const Problem p = parse_bimdf(
      "# libSatsuma BiMDF file\n2\n0\n0\n1\n0 1 1 0 0 2147483647 A 0x1.8p+1 "
      "0x1.978d4f2adda3ap-2\n");
  EXPECT_EQ(p.cost[0].target(), 3.0);
  EXPECT_EQ(p.cost[0].weight(), 0x1.978d4f2adda3ap-2);
  EXPECT_EQ(p.upper[0], kInfinity);
}

TEST(BimdfFormat, InfinityMarkers) {
  // `inf` is accepted; 2147483647 means infinity in libSatsuma files but is a plain number in
  // files carrying bimdf's header.
  const Problem a = parse_bimdf("1\n0\n1\n0 0 1 1 -inf inf 0\n");
  EXPECT_EQ(a.lower[0], -kInfinity);
  EXPECT_EQ(a.upper[0], kInfinity);
  const Problem b = parse_bimdf("# bimdf-format 1\n1\n0\n1\n0 0 1 1 0 2147483647 0\n");
  EXPECT_EQ(b.upper[0], 2147483647);
  const Problem c = parse_bimdf("1\n0\n1\n0 0 1 1 0 2147483647 0\n");
  EXPECT_EQ(c.upper[0], kInfinity);
}

TEST(BimdfFormat, ToleratesMissingFinalNewlineAndComments) {
  const Problem p = parse_bimdf("2 # nodes\n0 0\n1\n0 1 1 0 0 5 Q 1 2");
  EXPECT_EQ(p.num_edges(), 1);
  EXPECT_EQ(p.upper[0], 5);
  EXPECT_EQ(p.cost[0], Cost::quad_deviation(1, 2));
}

TEST(BimdfFormat, ReadsExtensions) {
  const Problem p = parse_bimdf(
      "3\n1 0 -1\n5\n"
      "0 -1 1 - 0 inf Z 4\n"
      "1 -1 0 - 0 3 L 2.5\n"
      "0 1 1 0 -inf inf B 1 2 3\n"
      "1 2 1 0 0 inf P -1 4 4 1 0 0\n"
      "2 2 0 0 0 inf S 2 1 0.1\n");
  EXPECT_TRUE(p.is_outer(0));
  EXPECT_EQ(p.edge_kind(0), EdgeKind::OuterHead);
  EXPECT_EQ(p.edge_kind(1), EdgeKind::OuterTail);
  EXPECT_EQ(p.cost[0], Cost::zero(4));
  EXPECT_EQ(p.cost[1], Cost::linear(2.5));
  EXPECT_EQ(p.cost[2], Cost::asym_abs_deviation(1, 2, 3));
  EXPECT_EQ(p.cost[3], Cost::piecewise_linear(-1, {4, 1, 0, 0}));
  EXPECT_EQ(p.cost[4], Cost::scale_factor(2, 1, 0.1));
}

TEST(BimdfFormat, RandomProblemsRoundTripExactly) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 3000; ++i) {
    const Problem p = testing::random_problem(rng);
    const std::string text = to_bimdf(p);
    const Problem q = parse_bimdf(text, "roundtrip");
    ASSERT_EQ(p, q) << text;
    ASSERT_EQ(to_bimdf(q), text);
  }
}

TEST(BimdfFormat, LibsatsumaCompatibleOutput) {
  std::mt19937_64 rng(11);
  testing::RandomProblemOptions options;
  options.all_cost_kinds = false;
  options.outer_edges = false;
  BimdfWriteOptions compatible;
  compatible.libsatsuma_compatible = true;
  for (int i = 0; i < 1000; ++i) {
    const Problem p = testing::random_problem(rng, options);
    const std::string text = to_bimdf(p, compatible);
    EXPECT_EQ(text.find("inf"), std::string::npos);
    EXPECT_EQ(text.rfind("# libSatsuma BiMDF file\n", 0), 0u);
    ASSERT_EQ(parse_bimdf(text), p) << text;
  }
}

TEST(BimdfFormat, LibsatsumaCompatibleOutputRefusesWhatLibsatsumaCannotRead) {
  BimdfWriteOptions compatible;
  compatible.libsatsuma_compatible = true;
  Problem p;
  p.add_node();
  p.add_edge({0, true}, std::nullopt, 0, 1, Cost::zero());
  EXPECT_EQ(input_error_of([&] { to_bimdf(p, compatible); }),
            "<bimdf writer>: edge 0: outer edges (a single end) cannot be written in "
            "libSatsuma-compatible .bimdf");
  Problem q;
  q.add_node();
  q.add_edge({0, true}, End{0, true}, 0, 2147483647, Cost::zero());
  EXPECT_EQ(input_error_of([&] { to_bimdf(q, compatible); }),
            "<bimdf writer>: edge 0: value 2147483647 is outside libSatsuma's 32-bit range");
  q.upper[0] = 3;
  q.cost[0] = Cost::linear(1);
  EXPECT_EQ(input_error_of([&] { to_bimdf(q, compatible); }),
            "<bimdf writer>: edge 0: a linear cost cannot be written in libSatsuma-compatible "
            ".bimdf");
}

TEST(BimdfFormat, ExtendedOutputKeepsFiniteLibsatsumaInfinityValue) {
  Problem p;
  p.add_node();
  p.add_edge({0, true}, End{0, true}, 0, 2147483647, Cost::zero());
  EXPECT_EQ(parse_bimdf(to_bimdf(p)).upper[0], 2147483647);
}

}  // namespace
}  // namespace bimdf
