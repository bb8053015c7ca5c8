// Cost functions: evaluation of every kind at integers, slopes at infinity, the integer
// minimizer against brute force (with its documented tie-breaking), and one test per
// validation error asserting the message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "bimdf/cost.hpp"
#include "bimdf/problem.hpp"
#include "random_problem.hpp"

namespace bimdf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Cost, EvaluatesEveryKind) {
  EXPECT_EQ(Cost::zero(7)(-3), 0.0);
  EXPECT_EQ(Cost::zero(7).guess(), 7);
  EXPECT_EQ(Cost::linear(-1.5)(4), -6.0);
  EXPECT_EQ(Cost::abs_deviation(2.5, 2)(0), 5.0);
  EXPECT_EQ(Cost::abs_deviation(2.5, 2)(4), 3.0);
  EXPECT_EQ(Cost::asym_abs_deviation(3, 2, 5)(1), 4.0);  // below: 2·(3 − 1)
  EXPECT_EQ(Cost::asym_abs_deviation(3, 2, 5)(4), 5.0);  // above: 5·(4 − 3)
  EXPECT_EQ(Cost::asym_abs_deviation(3, 2, 5)(3), 0.0);
  EXPECT_EQ(Cost::quad_deviation(1.5, 4)(3), 9.0);  // 4·1.5²
  // Scale factor: w·max((x+ε)/(t+ε), (t+ε)/(x+ε)), +∞ at x ≤ −ε.
  const Cost s = Cost::scale_factor(3, 2, 1);
  EXPECT_DOUBLE_EQ(s(7), 2.0 * 8 / 4);
  EXPECT_DOUBLE_EQ(s(1), 2.0 * 4 / 2);
  EXPECT_DOUBLE_EQ(s(3), 2.0);
  EXPECT_EQ(s(-1), kInf);
  EXPECT_EQ(s(-5), kInf);
}

TEST(Cost, PiecewiseLinearInterpolatesAndExtrapolates) {
  // Values at −1, 0, 1, 2: slopes −2, 0, 3.
  const Cost c = Cost::piecewise_linear(-1, {5, 3, 3, 6});
  EXPECT_EQ(c(-1), 5.0);
  EXPECT_EQ(c(1), 3.0);
  EXPECT_EQ(c(2), 6.0);
  EXPECT_EQ(c(-4), 11.0);  // first slope continued: 5 + 3·2
  EXPECT_EQ(c(5), 15.0);   // last slope continued: 6 + 3·3
  EXPECT_EQ(c.slope_at_minus_infinity(), -2.0);
  EXPECT_EQ(c.slope_at_plus_infinity(), 3.0);
  const Cost flat = Cost::piecewise_linear(4, {2.5});
  EXPECT_EQ(flat(-100), 2.5);
  EXPECT_EQ(flat(100), 2.5);
  EXPECT_EQ(flat.slope_at_plus_infinity(), 0.0);
}

TEST(Cost, SumsAddTheirTermsNestedOrNot) {
  const Cost inner = Cost::sum({Cost::abs_deviation(1, 1), Cost::linear(2)});
  const Cost c = Cost::sum({inner, Cost::quad_deviation(0, 0.5), Cost::zero(3)});
  for (int64_t x = -3; x <= 3; ++x)
    EXPECT_DOUBLE_EQ(c(x), std::abs(x - 1.0) + 2.0 * x + 0.5 * x * x) << x;
  EXPECT_EQ(c.slope_at_plus_infinity(), kInf);
  EXPECT_EQ(inner.slope_at_plus_infinity(), 3.0);
  EXPECT_EQ(inner.slope_at_minus_infinity(), 1.0);
}

TEST(Cost, SlopesAtInfinity) {
  EXPECT_EQ(Cost::zero().slope_at_plus_infinity(), 0.0);
  EXPECT_EQ(Cost::linear(-2).slope_at_minus_infinity(), -2.0);
  EXPECT_EQ(Cost::abs_deviation(0, 3).slope_at_plus_infinity(), 3.0);
  EXPECT_EQ(Cost::abs_deviation(0, 3).slope_at_minus_infinity(), -3.0);
  EXPECT_EQ(Cost::asym_abs_deviation(0, 2, 5).slope_at_minus_infinity(), -2.0);
  EXPECT_EQ(Cost::asym_abs_deviation(0, 2, 5).slope_at_plus_infinity(), 5.0);
  EXPECT_EQ(Cost::quad_deviation(0, 1).slope_at_minus_infinity(), -kInf);
  EXPECT_EQ(Cost::quad_deviation(0, 0).slope_at_plus_infinity(), 0.0);
  EXPECT_GT(Cost::scale_factor(3, 2, 1).slope_at_plus_infinity(), 0.0);
}

// The minimizer agrees with enumeration, and among equal minima it is the one closest to the
// anchor, ties towards the smaller value (cost.hpp).
TEST(Cost, ArgminMatchesBruteForceAndItsTieRule) {
  std::mt19937_64 rng(5);
  testing::RandomProblemOptions opt;
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const int64_t lo = static_cast<int64_t>(rng() % 9) - 3;
    const int64_t up = lo + static_cast<int64_t>(rng() % 9);
    const Cost c = testing::random_cost(rng, opt, lo, up);
    double best = kInf;
    for (int64_t x = lo; x <= up; ++x) best = std::min(best, c(x));
    int64_t expected = lo;
    double expected_distance = kInf;
    const double tol = 1e-12 * std::max(1.0, std::fabs(best));
    for (int64_t x = lo; x <= up; ++x) {
      if (c(x) > best + tol) continue;
      const double d = std::fabs(static_cast<double>(x) - c.anchor());
      if (d < expected_distance) expected = x, expected_distance = d;
    }
    const int64_t got = c.argmin(lo, up);
    ASSERT_GE(got, lo);
    ASSERT_LE(got, up);
    ASSERT_LE(c(got), best + tol) << "bounds [" << lo << ", " << up << "]";
    // The tie rule is only meaningful where minima are exactly equal.
    if (c(expected) == c(got)) {
      EXPECT_EQ(got, expected) << "bounds [" << lo << ", " << up << "]";
    }
    ++checked;
  }
  EXPECT_EQ(checked, 20000);
}

TEST(Cost, ArgminWithInfiniteBounds) {
  EXPECT_EQ(Cost::abs_deviation(7.2, 1).argmin(-kInfinity, kInfinity), 7);
  EXPECT_EQ(Cost::quad_deviation(-4.5, 1).argmin(0, kInfinity), 0);
  EXPECT_EQ(Cost::quad_deviation(-4.5, 1).argmin(-kInfinity, kInfinity), -5);  // tie: smaller
  EXPECT_EQ(Cost::linear(2).argmin(-3, kInfinity), -3);
  EXPECT_EQ(Cost::linear(-2).argmin(-kInfinity, 9), 9);
  EXPECT_EQ(Cost::zero(12).argmin(-kInfinity, kInfinity), 12);
  EXPECT_EQ(Cost::zero(12).argmin(0, 5), 5);
  EXPECT_EQ(Cost::asym_abs_deviation(3.5, 1, 1).argmin(-kInfinity, kInfinity), 3);
  EXPECT_EQ(Cost::piecewise_linear(10, {4, 1, 1, 5}).argmin(-kInfinity, kInfinity), 11);
  EXPECT_EQ(Cost::scale_factor(6, 1, 0.1).argmin(0, kInfinity), 6);
}

// The search starts at the anchor and gallops outwards (cost.cpp); here the minimizer lies far
// from it (sums whose anchor is the mean of distant targets) and the bounds are wide or
// infinite. A convex function's local minimum is global, so checking the neighbours suffices.
TEST(Cost, ArgminFarFromTheAnchorOverWideBounds) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> target(-1e9, 1e9), weight(0.001, 10);
  for (int i = 0; i < 5000; ++i) {
    std::vector<Cost> terms;
    const int k = 1 + static_cast<int>(rng() % 4);
    for (int j = 0; j < k; ++j) {
      // Parameters drawn into locals, last first (gcc's order of evaluating call arguments,
      // which is the compiler's choice): the same costs under every compiler.
      switch (rng() % 3) {
        case 0: {
          const double w = weight(rng), x = target(rng);
          terms.push_back(Cost::abs_deviation(x, w));
          break;
        }
        case 1: {
          const double w = weight(rng), x = target(rng);
          terms.push_back(Cost::quad_deviation(x, w));
          break;
        }
        default: {
          const double above = weight(rng), below = weight(rng), x = target(rng);
          terms.push_back(Cost::asym_abs_deviation(x, below, above));
        }
      }
    }
    const Cost c = k == 1 ? terms[0] : Cost::sum(terms);
    int64_t lo = rng() % 2 ? -kInfinity : static_cast<int64_t>(target(rng));
    int64_t up = rng() % 2 ? kInfinity : static_cast<int64_t>(target(rng));
    if (lo > up) std::swap(lo, up);
    const int64_t got = c.argmin(lo, up);
    ASSERT_GE(got, lo);
    ASSERT_LE(got, up);
    auto distance = [&](int64_t x) { return std::fabs(static_cast<double>(x) - c.anchor()); };
    if (got > lo) {
      ASSERT_LE(c(got), c(got - 1)) << "case " << i;
      if (c(got) == c(got - 1)) {
        EXPECT_GT(distance(got - 1), distance(got)) << "case " << i;
      }
    }
    if (got < up) {
      ASSERT_LE(c(got), c(got + 1)) << "case " << i;
      if (c(got) == c(got + 1)) {
        EXPECT_GE(distance(got + 1), distance(got)) << "case " << i;
      }
    }
  }
}

TEST(Cost, KindNamesRoundTrip) {
  for (int k = 0; k < kNumCostKinds; ++k) {
    const CostKind kind = static_cast<CostKind>(k);
    EXPECT_EQ(cost_kind_from_name(cost_kind_name(kind)), kind);
  }
  EXPECT_EQ(cost_kind_name(CostKind::AsymAbsDeviation), "asym_abs");
  EXPECT_FALSE(cost_kind_from_name("absolute").has_value());
}

// --- validate_cost: one test per error class -------------------------------------------------

std::string error_of(const Cost& c, int64_t lo = 0, int64_t up = 10) {
  const auto e = validate_cost(c, lo, up);
  return e ? *e : "(valid)";
}

TEST(CostValidation, AcceptsEveryKindWithinLimits) {
  EXPECT_EQ(error_of(Cost::zero(3)), "(valid)");
  EXPECT_EQ(error_of(Cost::linear(-1)), "(valid)");
  EXPECT_EQ(error_of(Cost::abs_deviation(2.5, 1)), "(valid)");
  EXPECT_EQ(error_of(Cost::asym_abs_deviation(2.5, 0, 1)), "(valid)");
  EXPECT_EQ(error_of(Cost::quad_deviation(2.5, 0)), "(valid)");
  EXPECT_EQ(error_of(Cost::piecewise_linear(0, {1, 0, 0, 2})), "(valid)");
  EXPECT_EQ(error_of(Cost::scale_factor(2, 1, 0.1)), "(valid)");
  EXPECT_EQ(error_of(Cost::sum({Cost::abs_deviation(1, 1), Cost::zero()})), "(valid)");
}

TEST(CostValidation, NegativeWeightIsNonConvex) {
  EXPECT_EQ(error_of(Cost::abs_deviation(1, -1)),
            "weight must be >= 0 (a negative weight makes the cost non-convex), got -1");
  EXPECT_EQ(
      error_of(Cost::asym_abs_deviation(1, 1, -2)),
      "weight_above must be >= 0 (a negative weight_above makes the cost non-convex), got -2");
}

TEST(CostValidation, NonFiniteNumbers) {
  EXPECT_EQ(error_of(Cost::quad_deviation(std::nan(""), 1)),
            "target must be a finite number, got nan");
  EXPECT_EQ(error_of(Cost::abs_deviation(1, kInf)), "weight must be a finite number, got inf");
  EXPECT_EQ(error_of(Cost::linear(-kInf)), "slope must be a finite number, got -inf");
  EXPECT_EQ(error_of(Cost::piecewise_linear(0, {1, std::nan("")})),
            "value 1 must be a finite number, got nan");
}

TEST(CostValidation, OverflowProneMagnitudes) {
  EXPECT_EQ(error_of(Cost::abs_deviation(1e13, 1)),
            "target must be within +-2^40 (the flow range), got 10000000000000");
  EXPECT_EQ(error_of(Cost::quad_deviation(1, 1e16)),
            "weight must be <= 1e15, got 10000000000000000");
  EXPECT_EQ(error_of(Cost::linear(2e15)), "slope must be within +-1e15, got 2000000000000000");
  EXPECT_EQ(error_of(Cost::zero(int64_t{1} << 41)),
            "guess must be within +-2^40, got 2199023255552");
}

TEST(CostValidation, NonConvexPiecewise) {
  EXPECT_EQ(error_of(Cost::piecewise_linear(5, {0, 2, 1})),
            "piecewise-linear cost is not convex at x = 6: slope 2 before it, -1 after it (slopes "
            "must not decrease)");
  EXPECT_EQ(error_of(Cost::piecewise_linear(0, {})),
            "piecewise-linear cost needs at least one value");
}

TEST(CostValidation, ScaleFactorDomain) {
  EXPECT_EQ(error_of(Cost::scale_factor(2, 1, 0)), "eps must be a finite number > 0, got 0");
  EXPECT_EQ(error_of(Cost::scale_factor(-3, 1, 1)),
            "target + eps must be > 0 for a scale-factor cost, got -3 + 1");
  EXPECT_EQ(error_of(Cost::scale_factor(2, 1, 0.5), -1, 10),
            "a scale-factor cost is only defined for flow > -eps (-0.5), so the lower bound must "
            "be > -eps, got -1");
}

TEST(CostValidation, UnboundedEdgeNeedsAMinimum) {
  EXPECT_EQ(error_of(Cost::linear(-1), 0, kInfinity),
            "cost decreases without limit as the flow grows (slope -1 at +inf) but the upper "
            "bound is infinite: the cost has no minimum");
  EXPECT_EQ(error_of(Cost::piecewise_linear(0, {0, 1}), -kInfinity, 0),
            "cost decreases without limit as the flow falls (slope 1 at -inf) but the lower "
            "bound is infinite: the cost has no minimum");
  EXPECT_EQ(error_of(Cost::abs_deviation(1, 1), -kInfinity, kInfinity), "(valid)");
}

TEST(CostValidation, SumNamesTheBadTerm) {
  EXPECT_EQ(error_of(Cost::sum({Cost::zero(), Cost::quad_deviation(1, -2)})),
            "term 1: weight must be >= 0 (a negative weight makes the cost non-convex), got -2");
}

}  // namespace
}  // namespace bimdf
