// Solver::progress: one report per component's approximation and per refinement round, whose
// objectives are the ones the solution reports (the approximation's and the final one), whose
// round numbers count up to the solution's rounds, whose last round proves optimality exactly
// when the status is Optimal, every component reporting — the same reports for any thread
// count, calls never overlapping — and whose exceptions cancel the solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "bimdf/flow.hpp"
#include "bimdf/io.hpp"
#include "bimdf/solve.hpp"
#include "random_problem.hpp"
#include "test_helpers.hpp"

namespace bimdf {
namespace {

using Event = SolveProgress::Event;

const std::string kBunny =
    std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf";

// Every report of one run, and whether two calls ever overlapped (with `linger`, each call
// lasts a little, so that overlapping workers would be caught).
struct Recorder {
  std::vector<SolveProgress> events;
  std::atomic<bool> inside{false};
  bool overlapped = false;

  std::function<void(const SolveProgress&)> callback(bool linger) {
    return [this, linger](const SolveProgress& p) {
      if (inside.exchange(true)) overlapped = true;
      events.push_back(p);
      if (linger) std::this_thread::sleep_for(std::chrono::microseconds(50));
      inside = false;
    };
  }
};

bool same_report(const SolveProgress& a, const SolveProgress& b) {
  return a.event == b.event && a.component == b.component && a.components == b.components &&
         a.round == b.round && a.objective == b.objective && a.improved == b.improved;
}

// The reports of one run checked against its solution; returns them per component. `where`
// names the problem in failure messages.
std::map<int, std::vector<SolveProgress>> check_reports(const Recorder& rec, const Solution& s,
                                                        const std::string& where) {
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
      // Improving rounds lower the objective; a round that does not leaves it, and ends.
      if (events[i].improved) {
        EXPECT_LT(events[i].objective, events[i - 1].objective) << at;
      } else {
        EXPECT_TRUE(testing::relatively_close(events[i].objective, events[i - 1].objective)) << at;
        EXPECT_EQ(i + 1, events.size()) << at << ": a round after the proof";
      }
    }
    rounds += static_cast<int64_t>(events.size()) - 1;
    all_proven = all_proven && events.size() > 1 && !events.back().improved;
    final_sum += events.back().objective;
  }
  if (s.status == SolveStatus::Optimal) {
    EXPECT_EQ(static_cast<int64_t>(by_component.size()),
              std::get<int64_t>(s.stats.at("components")))
        << where << ": a component did not report";
  }
  EXPECT_TRUE(testing::relatively_close(approximate_sum,
                                        std::get<double>(s.stats.at("approximate_objective"))))
      << where << ": " << approximate_sum;
  EXPECT_TRUE(testing::relatively_close(final_sum, s.objective))
      << where << ": " << final_sum << " vs " << s.objective;
  EXPECT_EQ(rounds, std::get<int64_t>(s.stats.at("refinement_rounds"))) << where;
  EXPECT_EQ(all_proven, s.status == SolveStatus::Optimal) << where;
  return by_component;
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
    std::map<int, std::map<int, std::vector<SolveProgress>>> per_threads;
    for (int threads : {1, 3}) {
      Recorder rec;
      Solver solver(p);
      solver.threads(threads).progress(rec.callback(threads > 1));
      if (solver.run() != SolveStatus::Optimal) continue;  // infeasible
      const std::string where =
          "problem " + std::to_string(i) + ", " + std::to_string(threads) + " threads";
      per_threads[threads] = check_reports(rec, solver.solution(), where);
      if (threads > 1) continue;
      ++optimal;
      several_components += per_threads[1].size() > 1;
      several_rounds += std::get<int64_t>(solver.solution().stats.at("refinement_rounds_max")) > 2;
    }
    if (per_threads.size() < 2) continue;
    // Component by component, the reports do not depend on the thread count.
    ASSERT_EQ(per_threads[1].size(), per_threads[3].size()) << "problem " << i;
    for (const auto& [component, events] : per_threads[1]) {
      const std::vector<SolveProgress>& other = per_threads[3][component];
      ASSERT_EQ(events.size(), other.size()) << "problem " << i << ", component " << component;
      for (size_t e = 0; e < events.size(); ++e)
        EXPECT_TRUE(same_report(events[e], other[e]))
            << "problem " << i << ", component " << component << ", report " << e;
    }
  }
  EXPECT_GT(optimal, testing::scaled(200) / 2);
  EXPECT_GT(several_components, testing::scaled(200) / 8);
  // Problems that take three rounds or more are rarer: 14 of the 200, 1 of the first 40.
  EXPECT_GE(several_rounds, testing::scaled(200) / 40);
}

TEST(Progress, StoppedByARoundLimitTheLastRoundStillImproves) {
  const Problem p = read_problem_file(kBunny);
  Recorder rec;
  Solver solver(p);
  solver.max_rounds(1).progress(rec.callback(false));
  ASSERT_EQ(solver.run(), SolveStatus::Feasible);
  const auto by_component = check_reports(rec, solver.solution(), "npm_bunny, 1 round");
  // Its large component is stopped after an improving round, its small one proven optimal.
  ASSERT_EQ(by_component.size(), 2u);
  ASSERT_EQ(by_component.at(0).size(), 2u);
  EXPECT_TRUE(by_component.at(0).back().improved);
  EXPECT_FALSE(by_component.at(1).back().improved);
}

TEST(Progress, AnExceptionFromTheCallbackCancelsTheSolve) {
  // One worker: the approximation, round 1 (which throws), and nothing more — the bunny's
  // other component is never begun.
  const Problem bunny = read_problem_file(kBunny);
  int calls = 0;
  Solver solver(bunny);
  solver.progress([&](const SolveProgress& event) {
    ++calls;
    if (event.event == Event::RefinementRound) throw std::runtime_error("stop, said the user");
  });
  try {
    solver.run();
    ADD_FAILURE() << "run() returned although the callback threw";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "stop, said the user");
  }
  EXPECT_EQ(calls, 2);

  // Several workers on many components: the call that throws is the last one made, and its
  // exception itself — not a SolverError naming a component around it — is what run() throws.
  std::mt19937_64 rng(29);
  const testing::RandomProblemOptions sparse{
      .min_nodes = 40, .max_nodes = 60, .min_edges = 20, .max_edges = 40};
  int cancelled = 0;
  for (int i = 0; i < testing::scaled(40); ++i) {
    Problem p = testing::random_problem(rng, sparse);
    testing::plant_feasible_demands(p, rng);
    int made = 0, thrown_at = -1;
    Solver many(p);
    many.threads(3).progress([&](const SolveProgress& event) {
      ++made;
      std::this_thread::sleep_for(std::chrono::microseconds(50));
      if (event.component == 1 && event.event == Event::RefinementRound) {
        thrown_at = made;
        throw SolverError("cancelled by the test");
      }
    });
    try {
      many.run();
      EXPECT_EQ(thrown_at, -1) << "problem " << i << ": run() returned after a throw";
    } catch (const SolverError& e) {
      EXPECT_STREQ(e.what(), "cancelled by the test") << "problem " << i;
      EXPECT_EQ(made, thrown_at) << "problem " << i << ": calls after the throwing one";
      ++cancelled;
    }
  }
  EXPECT_GT(cancelled, testing::scaled(40) / 2);
}

}  // namespace
}  // namespace bimdf
