// Instance generators: deterministic, valid, of about the requested size, feasible, and of the
// promised structure (every edge kind for "random"; valences 3–6 gadgets for "quadwild").
#include <gtest/gtest.h>

#include "bimdf/generate.hpp"
#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"
#include "bimdf/summary.hpp"

namespace bimdf {
namespace {

TEST(Generate, SameSeedSameProblemOtherSeedOtherProblem) {
  for (const std::string& family : generator_family_names()) {
    EXPECT_EQ(generate_problem(family, 3000, 7), generate_problem(family, 3000, 7)) << family;
    EXPECT_NE(generate_problem(family, 3000, 7), generate_problem(family, 3000, 8)) << family;
  }
}

TEST(Generate, ValidOfTheRequestedSizeAndFeasible) {
  for (const std::string& family : generator_family_names())
    for (int64_t size : {300, 3000}) {
      const Problem p = generate_problem(family, size, 1);
      EXPECT_FALSE(validate(p).has_value()) << family;
      EXPECT_GE(p.num_edges(), size * 8 / 10) << family << " " << size;
      EXPECT_LE(p.num_edges(), size * 12 / 10) << family << " " << size;
      Solver solver(p);
      EXPECT_EQ(solver.run(), SolveStatus::Optimal) << family << " " << size;
    }
}

TEST(Generate, RandomHasEveryEdgeAndCostKind) {
  const ProblemSummary s = summarize(generate_problem("random", 2000, 3));
  for (int k = 0; k < kNumEdgeKinds; ++k) EXPECT_GT(s.edge_kinds[k], 0) << k;
  for (int k = 0; k < kNumCostKinds; ++k) EXPECT_GT(s.cost_kinds[k], 0) << k;
  EXPECT_GT(s.nodes_with_demand, 0);
}

TEST(Generate, QuadWildLikeHasTheReferenceModelsShape) {
  const ProblemSummary s = summarize(generate_problem("quadwild", 5000, 3));
  // Only the kinds QuadWild's model uses: tail–tail loops and edges, head–head, head–tail.
  EXPECT_EQ(s.edge_kinds[static_cast<int>(EdgeKind::LoopHeads)], 0);
  EXPECT_EQ(s.edge_kinds[static_cast<int>(EdgeKind::OuterHead)], 0);
  EXPECT_GT(s.edge_kinds[static_cast<int>(EdgeKind::LoopTails)], 0);
  EXPECT_GT(s.edge_kinds[static_cast<int>(EdgeKind::HeadTail)], 0);
  EXPECT_EQ(s.cost_kinds[static_cast<int>(CostKind::Linear)], 0);
  EXPECT_GT(s.cost_kinds[static_cast<int>(CostKind::QuadDeviation)], 0);
  EXPECT_GT(s.cost_kinds[static_cast<int>(CostKind::AbsDeviation)], 0);
  EXPECT_EQ(s.nodes_with_demand, 0);
}

TEST(Generate, RejectsUnknownFamiliesAndSizes) {
  EXPECT_THROW(generate_problem("grid", 10, 1), std::invalid_argument);
  EXPECT_THROW(generate_problem("random", 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace bimdf
