// Solver::progress: one report per component's approximation and per refinement round, whose
// objectives are the ones the solution reports (the approximation's and the final one), whose
// round numbers count up to the solution's rounds, whose last round proves optimality exactly
// when the status is Optimal — with any thread count, calls never overlapping — and whose
// exceptions end run().
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include "bimdf/flow.hpp"
#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"
#include "random_problem.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

bool close(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max(1.0, std::fabs(b)); }

using Event = SolveProgress::Event;

// Every report of one run, and whether two calls ever overlapped.
struct Recorder {
  std::vector<SolveProgress> events;
  std::atomic<bool> inside{false};
  bool overlapped = false;

  std::function<void(const SolveProgress&)> callback() {
    return [this](const SolveProgress& p) {
      if (inside.exchange(true)) overlapped = true;
      events.push_back(p);
      inside = false;
    };
  }
};

// The reports of one run checked against its solution; returns the number of components that
// reported. `where` names the problem in failure messages.
int check_reports(const Recorder& rec, const Solution& s, const std::string& where) {
  EXPECT_FALSE(rec.overlapped) << where;
  std::map<int, std::vector<SolveProgress>> by_component;
  double elapsed = 0;
  for (const SolveProgress& p : rec.events) {
    EXPECT_GE(p.elapsed_s, elapsed) << where << ": elapsed time runs backwards";
    elapsed = p.elapsed_s;
    EXPECT_EQ(p.components, std::get<int64_t>(s.stats.at("components"))) << where;
    EXPECT_TRUE(p.component >= 0 && p.component < p.components) << where;
    by_component[p.component].push_back(p);
  }
  double approximate_sum = 0, final_sum = 0;
  int64_t rounds = 0;
  bool all_proven = true;
  for (const auto& [component, events] : by_component) {
    const std::string at = where + ", component " + std::to_string(component);
    EXPECT_EQ(events.front().event, Event::Approximated) << at;
    EXPECT_EQ(events.front().round, 0) << at;
    approximate_sum += events.front().objective;
    for (size_t i = 1; i < events.size(); ++i) {
      EXPECT_EQ(events[i].event, Event::RefinementRound) << at;
      EXPECT_EQ(events[i].round, static_cast<int64_t>(i)) << at;
      // Improving rounds lower the objective; a round that does not leaves it.
      if (events[i].improved) {
        EXPECT_LT(events[i].objective, events[i - 1].objective) << at;
      } else {
        EXPECT_TRUE(close(events[i].objective, events[i - 1].objective)) << at;
      }
    }
    for (size_t i = 1; i + 1 < events.size(); ++i) EXPECT_TRUE(events[i].improved) << at;
    rounds += static_cast<int64_t>(events.size()) - 1;
    all_proven = all_proven && events.size() > 1 && !events.back().improved;
    final_sum += events.back().objective;
  }
  EXPECT_TRUE(close(approximate_sum, std::get<double>(s.stats.at("approximate_objective"))))
      << where << ": " << approximate_sum;
  EXPECT_TRUE(close(final_sum, s.objective)) << where << ": " << final_sum << " vs " << s.objective;
  EXPECT_EQ(rounds, std::get<int64_t>(s.stats.at("refinement_rounds"))) << where;
  EXPECT_EQ(all_proven, s.status == SolveStatus::Optimal) << where;
  return static_cast<int>(by_component.size());
}

TEST(Progress, ReportsMatchTheSolutionWithAnyThreadCount) {
  std::mt19937_64 rng(23);
  // Sparse problems have several components, dense ones need several rounds.
  const testing::RandomProblemOptions sparse{
      .min_nodes = 30, .max_nodes = 60, .min_edges = 20, .max_edges = 40};
  const testing::RandomProblemOptions dense{
      .min_nodes = 10, .max_nodes = 40, .min_edges = 30, .max_edges = 120};
  int optimal = 0, several_components = 0, several_rounds = 0;
  for (int i = 0; i < testing::scaled(200); ++i) {
    Problem p = testing::random_problem(rng, i % 2 ? sparse : dense);
    testing::plant_feasible_demands(p, rng);
    for (int threads : {1, 3}) {
      Recorder rec;
      Solver solver(p);
      solver.threads(threads).progress(rec.callback());
      if (solver.run() != SolveStatus::Optimal) continue;  // infeasible
      const std::string where =
          "problem " + std::to_string(i) + ", " + std::to_string(threads) + " threads";
      const int components = check_reports(rec, solver.solution(), where);
      optimal += threads == 1;
      several_components += threads == 1 && components > 1;
      several_rounds += threads == 1 &&
                        std::get<int64_t>(solver.solution().stats.at("refinement_rounds_max")) > 2;
    }
  }
  EXPECT_GT(optimal, testing::scaled(200) / 2);
  EXPECT_GT(several_components, testing::scaled(200) / 8);
  EXPECT_GT(several_rounds, testing::scaled(200) / 20);
}

TEST(Progress, StoppedByARoundLimitTheLastRoundStillImproves) {
  const Problem p =
      read_problem_file(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf");
  Recorder rec;
  Solver solver(p);
  solver.max_rounds(1).progress(rec.callback());
  ASSERT_EQ(solver.run(), SolveStatus::Feasible);
  check_reports(rec, solver.solution(), "npm_bunny, 1 round");
  // Its large component is stopped after an improving round, its small one proven optimal.
  std::vector<SolveProgress> large;
  for (const SolveProgress& p : rec.events)
    if (p.component == 0) large.push_back(p);
  ASSERT_EQ(large.size(), 2u);
  EXPECT_TRUE(large.back().improved);
}

TEST(Progress, AnExceptionFromTheCallbackEndsRun) {
  const Problem p =
      read_problem_file(std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf");
  for (int threads : {1, 2}) {
    int calls = 0;
    Solver solver(p);
    solver.threads(threads).progress([&](const SolveProgress& event) {
      ++calls;
      if (event.event == Event::RefinementRound) throw std::runtime_error("stop, said the user");
    });
    try {
      solver.run();
      ADD_FAILURE() << "run() returned although the callback threw";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "stop, said the user");
    }
    // One worker: the approximation, then round 1, and the other component is never begun;
    // with two, the other component may report (and throw) too.
    if (threads == 1) {
      EXPECT_EQ(calls, 2);
    } else {
      EXPECT_TRUE(calls >= 2 && calls <= 4) << calls;
    }
  }
}

}  // namespace
}  // namespace bimdf
