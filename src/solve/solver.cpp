// The public solvers (bimdf/solve.hpp): option setters over the shared driver (driver.hpp).
#include <stdexcept>

#include "bimdf/solve.hpp"
#include "solve/driver.hpp"

namespace bimdf {
namespace {

detail::ApproximateOptions approximate_options(int max_deviation, ParityRepairMode parity,
                                               DoubleCoverMode cover, bool unchained) {
  detail::ApproximateOptions o;
  o.unchained = unchained;
  o.max_deviation = max_deviation;
  o.parity = parity == ParityRepairMode::SpanningTreeTJoin ? detail::ParityMode::SpanningTreeTJoin
                                                           : detail::ParityMode::RoundToEven;
  o.cover = cover == DoubleCoverMode::Asymmetric ? detail::DoubleCoverKind::Asymmetric
                                                 : detail::DoubleCoverKind::Symmetric;
  return o;
}

int checked_max_deviation(int u) {
  if (u < 0) throw std::invalid_argument("max_deviation must be >= 0");
  return u;
}

}  // namespace

ApproximateSolver::ApproximateSolver(const Problem& problem) : problem_(problem) {}
ApproximateSolver& ApproximateSolver::max_deviation(int u) {
  max_deviation_ = checked_max_deviation(u);
  return *this;
}
ApproximateSolver& ApproximateSolver::parity_repair(ParityRepairMode mode) {
  parity_ = mode;
  return *this;
}
ApproximateSolver& ApproximateSolver::double_cover(DoubleCoverMode mode) {
  cover_ = mode;
  return *this;
}
ApproximateSolver& ApproximateSolver::collapse_chains(bool enable) {
  collapse_chains_ = enable;
  return *this;
}
ApproximateSolver& ApproximateSolver::approximate_unchained(bool enable) {
  approximate_unchained_ = enable;
  return *this;
}
SolveStatus ApproximateSolver::run() {
  detail::SolverConfig config;
  config.component.collapse_chains = collapse_chains_;
  config.component.approximate =
      approximate_options(max_deviation_, parity_, cover_, approximate_unchained_);
  solution_ = detail::solve_problem(problem_, config);
  if (solution_.status == SolveStatus::Optimal) solution_.status = SolveStatus::Feasible;
  return solution_.status;
}

Solver::Solver(const Problem& problem) : problem_(problem) {}
Solver& Solver::max_deviation(int u) {
  max_deviation_ = checked_max_deviation(u);
  return *this;
}
Solver& Solver::parity_repair(ParityRepairMode mode) {
  parity_ = mode;
  return *this;
}
Solver& Solver::double_cover(DoubleCoverMode mode) {
  cover_ = mode;
  return *this;
}
Solver& Solver::collapse_chains(bool enable) {
  collapse_chains_ = enable;
  return *this;
}
Solver& Solver::approximate_unchained(bool enable) {
  approximate_unchained_ = enable;
  return *this;
}
Solver& Solver::max_rounds(int64_t rounds) {
  if (rounds < 1) throw std::invalid_argument("max_rounds must be >= 1");
  max_rounds_ = rounds;
  return *this;
}
Solver& Solver::time_limit(double seconds) {
  if (!(seconds > 0)) throw std::invalid_argument("time_limit must be > 0 seconds");
  time_limit_s_ = seconds;
  return *this;
}
Solver& Solver::threads(int count) {
  if (count < 1) throw std::invalid_argument("threads must be >= 1");
  threads_ = count;
  return *this;
}
Solver& Solver::lower_bound(bool enable) {
  lower_bound_ = enable;
  return *this;
}
Solver& Solver::matching(MatchingBackend backend) {
  matching_ = backend;
  return *this;
}
Solver& Solver::progress(std::function<void(const SolveProgress&)> callback) {
  progress_ = std::move(callback);
  return *this;
}
SolveStatus Solver::run() {
  detail::SolverConfig config;
  config.component.collapse_chains = collapse_chains_;
  config.component.approximate =
      approximate_options(max_deviation_, parity_, cover_, approximate_unchained_);
  config.component.exact = true;
  config.component.lower_bound = lower_bound_;
  if (max_rounds_ > 0) config.component.refine.max_rounds = max_rounds_;
  config.component.refine.matching = matching_;
  if (time_limit_s_ > 0) config.time_limit_s = time_limit_s_;
  config.threads = threads_;
  config.progress = progress_;
  solution_ = detail::solve_problem(problem_, config);
  return solution_.status;
}

}  // namespace bimdf
