// The approximate solver against the brute-force oracle: on random tiny problems covering every
// edge kind, bound kind, demands, loops and cost kind it must return a verified feasible flow
// exactly when one exists and "infeasible" (with a proof) exactly when none does. Also the
// reported approximation error, targeted regressions for the reference implementation's
// failures, and every shared real instance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "bimdf/flow.hpp"
#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"
#include "brute_force.hpp"
#include "random_problem.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

using testing::brute_force;
using testing::BruteForceResult;

struct SuiteReport {
  int instances = 0, feasible = 0, infeasible = 0, failures = 0, outside_window = 0;
  std::map<std::string, int> paths;  // how answers were reached: cover, phase 1, proof kind
  std::vector<double> relative_errors;
  std::string first_failures;
};

// Runs the solver on one instance and compares with the oracle; failures are described.
void compare(const Problem& p, ApproximateSolver& solver, SuiteReport& report,
             const std::string& label) {
  const BruteForceResult truth = brute_force(p);
  ++report.instances;
  std::string failure;
  try {
    const SolveStatus status = solver.run();
    const Solution& s = solver.solution();
    if (status == SolveStatus::Feasible) {
      ++report.feasible;
      const std::string path = std::get<std::string>(s.stats.at("approximation_path"));
      ++report.paths[path.empty() ? "no edges" : path.substr(0, path.find(" ("))];
      const FlowCheck check = check_flow(p, s.flow);
      if (!check.feasible())
        failure = "returned an infeasible flow";
      else if (std::fabs(check.objective - s.objective) > 1e-9 * (1 + std::fabs(s.objective)))
        failure = "reported objective differs from the flow's";
      else if (!truth.feasible)
        ++report.outside_window;  // a real flow the windowed oracle could not see
      else if (s.objective < truth.optimum - 1e-9 * (1 + std::fabs(truth.optimum)) &&
               truth.exhaustive)
        failure = "objective below the brute-force optimum";
      else if (truth.feasible)
        report.relative_errors.push_back((s.objective - truth.optimum) /
                                         std::max(std::fabs(truth.optimum), 1e-9));
    } else if (status == SolveStatus::Infeasible) {
      ++report.infeasible;
      if (s.stats.count("infeasible_reason")) {
        const std::string why = std::get<std::string>(s.stats.at("infeasible_reason"));
        ++report.paths["infeasible: " + why.substr(0, why.find(':'))];
      }
      if (truth.feasible) failure = "reported infeasible, but the oracle found a flow";
      if (!s.stats.count("infeasible_reason")) failure = "infeasible without a reason";
    } else {
      failure = "unexpected status";
    }
  } catch (const std::exception& e) {
    failure = std::string("threw: ") + e.what();
  }
  if (failure.empty()) return;
  if (++report.failures <= 5)
    report.first_failures += label + ": " + failure + " (oracle: " +
                             (truth.feasible ? "feasible, optimum " + std::to_string(truth.optimum)
                                             : std::string("infeasible")) +
                             ")\n" + to_bimdf(p) + "\n";
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1))];
}

SuiteReport run_suite(uint64_t seed, int count, ParityRepairMode parity, DoubleCoverMode cover,
                      int max_deviation) {
  std::mt19937_64 rng(seed);
  testing::RandomProblemOptions opt;
  opt.max_nodes = 4;
  opt.max_edges = 6;
  SuiteReport report;
  for (int i = 0; i < testing::scaled(count); ++i) {
    Problem p = testing::random_problem(rng, opt);
    if (i % 2) testing::plant_feasible_demands(p, rng);
    ApproximateSolver solver(p);
    solver.parity_repair(parity).double_cover(cover).max_deviation(max_deviation);
    compare(p, solver, report, "seed " + std::to_string(seed) + " instance " + std::to_string(i));
  }
  return report;
}

void expect_clean(const SuiteReport& r, const std::string& name) {
  EXPECT_EQ(r.failures, 0) << r.first_failures;
  // Both answers must actually occur, or the suite tests nothing.
  EXPECT_GT(r.feasible, r.instances / 4) << name;
  EXPECT_GT(r.infeasible, r.instances / 20) << name;
  std::cout << "[ suite    ] " << name << ": " << r.instances << " instances, " << r.feasible
            << " feasible, " << r.infeasible << " infeasible, " << r.failures << " failures, "
            << r.outside_window << " flows outside the oracle's window; relative error median "
            << percentile(r.relative_errors, 0.5) << ", p95 " << percentile(r.relative_errors, 0.95)
            << ", max " << percentile(r.relative_errors, 1.0) << "\n";
  for (const auto& [path, n] : r.paths) std::cout << "[ suite    ]   " << path << ": " << n << "\n";
}

TEST(ApproximateRandom, TenThousandTinyInstancesAgreeWithBruteForce) {
  expect_clean(
      run_suite(1, 10000, ParityRepairMode::SpanningTreeTJoin, DoubleCoverMode::Asymmetric, 5),
      "tjoin+asymmetric U=5");
}

TEST(ApproximateRandom, OtherStartingModesAgreeWithBruteForce) {
  expect_clean(run_suite(2, 2000, ParityRepairMode::RoundToEven, DoubleCoverMode::Asymmetric, 5),
               "round-to-even+asymmetric U=5");
  expect_clean(
      run_suite(3, 2000, ParityRepairMode::SpanningTreeTJoin, DoubleCoverMode::Symmetric, 5),
      "tjoin+symmetric U=5");
  expect_clean(
      run_suite(4, 2000, ParityRepairMode::SpanningTreeTJoin, DoubleCoverMode::Asymmetric, 0),
      "tjoin+asymmetric U=0");
}

// --- Targeted cases ------------------------------------------------------------------------

Problem parse(const std::string& text) { return parse_bimdf("# bimdf-format 1\n" + text); }

Solution solve_approx(const Problem& p) {
  ApproximateSolver solver(p);
  solver.run();
  return solver.solution();
}

std::string reason(const Solution& s) {
  return std::get<std::string>(s.stats.at("infeasible_reason"));
}

TEST(Approximate, HonoursNonZeroDemands) {
  // 0 →(x0) 1 →(x1) 2, demands: 1 receives 1 net, 2 receives 2 net: x1 = 2, x0 = 3.
  const Problem p = parse("3\n-3 1 2\n2\n0 1 0 1 0 inf A 1 1\n1 2 0 1 0 inf A 1 1\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_EQ(s.flow, (std::vector<int64_t>{3, 2}));
  EXPECT_DOUBLE_EQ(s.objective, 3.0);
}

TEST(Approximate, RespectsFiniteUpperBoundsAboveTheGuess) {
  // Target 7 but upper 4: the tail capacity must be u − g − D, not u − D.
  const Problem p = parse("2\n0 0\n3\n0 1 0 1 0 4 A 7 1\n1 0 0 1 0 inf Q 0 1\n0 0 0 0 0 inf 0\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_TRUE(check_flow(p, s.flow).feasible());
  EXPECT_LE(s.flow[0], 4);
}

TEST(Approximate, OneSignedNodesAreFeasible) {
  // Node 0 has only tails, node 1 only heads: the flow must leave 0 and enter 1 twice over.
  const Problem p =
      parse("3\n-2 2 0\n3\n0 2 0 1 0 3 A 3 1\n2 1 0 1 0 3 A 0 1\n0 1 0 1 0 3 Q 2 1\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_TRUE(check_flow(p, s.flow).feasible());
}

TEST(Approximate, FixedEdgesMoveIntoDemands) {
  const Problem p = parse("2\n0 0\n2\n0 1 0 1 3 3 A 0 1\n1 0 0 1 0 inf A 0 1\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_EQ(s.flow, (std::vector<int64_t>{3, 3}));
}

TEST(Approximate, OddParityIsProvenInfeasible) {
  // Node 0 has demand 1 and only a head–head loop, which moves it by 2 at a time.
  const Problem p = parse("1\n1\n1\n0 0 1 1 0 inf A 0 1\n");
  const Solution s = solve_approx(p);
  EXPECT_EQ(s.status, SolveStatus::Infeasible);
  EXPECT_TRUE(s.flow.empty());
  EXPECT_TRUE(std::isnan(s.objective));
  EXPECT_EQ(reason(s),
            "parity: node 0 belongs to a set of nodes whose total demand must be changed by an odd "
            "amount, but every edge that can carry a different flow changes it by an even amount");
}

TEST(Approximate, ChainWithDisjointBoundsIsProvenInfeasible) {
  // 0 → 1 → 2 → 0 through pass-through node 1 with bounds [0,2] and [3,5].
  const Problem p = parse("3\n0 0 0\n3\n0 1 0 1 0 2 A 0 1\n1 2 0 1 3 5 A 0 1\n2 0 0 1 0 inf 0\n");
  const Solution s = solve_approx(p);
  EXPECT_EQ(s.status, SolveStatus::Infeasible);
  EXPECT_EQ(reason(s).rfind("chain: edge 0 lies on a chain of nodes with demand 0", 0), 0u)
      << reason(s);
}

TEST(Approximate, UnreachableDemandIsProvenInfeasibleByTheRelaxation) {
  // Node 1 needs 4 units in but its only edge carries at most 2.
  const Problem p = parse("2\n-4 4\n2\n0 1 0 1 0 2 A 0 1\n0 0 0 0 0 inf 0\n");
  const Solution s = solve_approx(p);
  EXPECT_EQ(s.status, SolveStatus::Infeasible);
  EXPECT_EQ(reason(s).rfind("relaxation: the LP relaxation of the component containing node 0", 0),
            0u)
      << reason(s);
}

TEST(Approximate, SolvesAProblemWhoseCoversFailAroundThePerEdgeMinimizers) {
  // Node 1 needs all its head capacity, split unevenly over odd capacities: around the per-edge
  // minimizers neither split of the asymmetric cover works (found by the random suite; it
  // needed phase 1 before the guess was centered on the LP relaxation).
  const Problem p = parse(
      "3\n0 1 -2\n6\n0 2 0 0 -inf inf Z 3\n2 2 0 0 -1 inf A 2.9337839208570893 0.5\n"
      "2 1 0 1 0 3 B 2.513455666464448 8.850749053790251e-07 4.269927609896415\n"
      "1 -1 1 - -inf inf P -2 3 7.73652035663294 7.030368660051876 10.824216963470814\n"
      "0 1 1 0 1 inf + 3 0 B 4 0.00012176066443943212 8.046513755965858 "
      "B 0 0.00019676102968396765 3.105173527682347e-05\n"
      "2 -1 0 - 3 3 S 4.028953459074041 5 0.919426373335953\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_TRUE(check_flow(p, s.flow).feasible());
}

TEST(Approximate, PhaseOneProvesIntegerInfeasibilityTheRelaxationMisses) {
  // A perfect matching as a flow: every node needs exactly one unit over head–head edges of
  // capacity 1. Node 0 joins three triangles; removing it leaves three odd components, so no
  // perfect matching exists (Tutte), although the fractional one (½ around each triangle) does
  // and the total demand is even.
  std::string text = "10\n1 1 1 1 1 1 1 1 1 1\n12\n";
  for (int t = 0; t < 3; ++t) {
    const int a = 1 + 3 * t;
    text += "0 " + std::to_string(a) + " 1 1 0 1 A 0 1\n";
    for (int i = 0; i < 3; ++i)
      text += std::to_string(a + i) + " " + std::to_string(a + (i + 1) % 3) + " 1 1 0 1 A 0 1\n";
  }
  const Solution s = solve_approx(parse(text));
  EXPECT_EQ(s.status, SolveStatus::Infeasible);
  EXPECT_EQ(reason(s).rfind("phase 1: the component containing node 0 has no flow", 0), 0u)
      << reason(s);
}

TEST(Approximate, OuterEdgesAndEmptyProblems) {
  // Two outer edges: one head at 0 (demand 2), one tail at 1 (demand −1): x0 = 2, x1 = 1.
  const Problem p = parse("2\n2 -1\n2\n0 -1 1 - 0 inf A 0 1\n1 -1 0 - 0 inf Q 5 1\n");
  const Solution s = solve_approx(p);
  ASSERT_EQ(s.status, SolveStatus::Feasible);
  EXPECT_EQ(s.flow, (std::vector<int64_t>{2, 1}));
  EXPECT_EQ(solve_approx(Problem{}).status, SolveStatus::Feasible);
  Problem lonely;
  lonely.add_node(2);
  EXPECT_EQ(solve_approx(lonely).status, SolveStatus::Infeasible);
}

// --- Shared real instances -----------------------------------------------------------------

TEST(ApproximateShared, EveryInstanceGetsAFeasibleFlowNoBetterThanTheOptimum) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(BIMDF_SHARED_DATA_DIR) / "instances";
  if (!fs::exists(dir / "expected.tsv"))
    GTEST_SKIP() << "shared data not found at " << dir << " (a clone without ../shared)";
  std::ifstream tsv(dir / "expected.tsv");
  std::string line;
  std::getline(tsv, line);
  int count = 0;
  std::vector<double> gaps;
  while (std::getline(tsv, line)) {
    std::istringstream row(line);
    std::string file;
    int nodes, edges;
    double optimum;
    if (!(row >> file >> nodes >> edges >> optimum)) continue;
    const Problem p = read_problem_file((dir / file).string());
    const Solution s = solve_approx(p);
    ASSERT_EQ(s.status, SolveStatus::Feasible) << file;
    EXPECT_TRUE(check_flow(p, s.flow).feasible()) << file;
    // The listed optima have 9 decimals.
    EXPECT_GE(s.objective, optimum - 1e-8) << file;
    gaps.push_back((s.objective - optimum) / optimum);
    ++count;
  }
  EXPECT_GE(count, 60);
  std::cout << "[ shared   ] " << count << " instances, approximation gap to the optimum: median "
            << percentile(gaps, 0.5) << ", max " << percentile(gaps, 1.0) << "\n";
}

}  // namespace
}  // namespace bimdf
