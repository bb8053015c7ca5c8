#include "bimdf/cost.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "bimdf/problem.hpp"

namespace bimdf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Targets must lie within the flow range; weights and slopes are limited so that a cost at any
// admissible flow (|x| ≤ 2^40) stays far from double overflow even after summing a whole
// network.
constexpr double kMaxTarget = static_cast<double>(kMaxMagnitude);
constexpr double kMaxCoefficient = 1e15;

constexpr std::array<std::string_view, kNumCostKinds> kKindNames = {
    "zero", "linear", "abs", "asym_abs", "quad", "piecewise", "scale_factor", "sum"};

}  // namespace

std::string_view cost_kind_name(CostKind kind) { return kKindNames[static_cast<int>(kind)]; }

std::optional<CostKind> cost_kind_from_name(std::string_view name) {
  for (int k = 0; k < kNumCostKinds; ++k)
    if (kKindNames[k] == name) return static_cast<CostKind>(k);
  return std::nullopt;
}

Cost Cost::zero(int64_t guess) {
  Cost c;
  c.guess_ = guess;
  return c;
}

Cost Cost::linear(double slope) {
  Cost c;
  c.kind_ = CostKind::Linear;
  c.a_ = slope;
  return c;
}

Cost Cost::abs_deviation(double target, double weight) {
  Cost c;
  c.kind_ = CostKind::AbsDeviation;
  c.t_ = target;
  c.a_ = weight;
  return c;
}

Cost Cost::asym_abs_deviation(double target, double weight_below, double weight_above) {
  Cost c;
  c.kind_ = CostKind::AsymAbsDeviation;
  c.t_ = target;
  c.a_ = weight_below;
  c.b_ = weight_above;
  return c;
}

Cost Cost::quad_deviation(double target, double weight) {
  Cost c;
  c.kind_ = CostKind::QuadDeviation;
  c.t_ = target;
  c.a_ = weight;
  return c;
}

Cost Cost::piecewise_linear(int64_t first, std::vector<double> values) {
  Cost c;
  c.kind_ = CostKind::PiecewiseLinear;
  c.guess_ = first;
  c.values_ = std::move(values);
  return c;
}

Cost Cost::scale_factor(double target, double weight, double eps) {
  Cost c;
  c.kind_ = CostKind::ScaleFactor;
  c.t_ = target;
  c.a_ = weight;
  c.b_ = eps;
  return c;
}

Cost Cost::sum(std::vector<Cost> terms) {
  Cost c;
  c.kind_ = CostKind::Sum;
  c.terms_ = std::move(terms);
  return c;
}

double Cost::operator()(int64_t x_int) const {
  const double x = static_cast<double>(x_int);
  switch (kind_) {
    case CostKind::Zero:
      return 0.0;
    case CostKind::Linear:
      return a_ * x;
    case CostKind::AbsDeviation:
      return a_ * std::abs(x - t_);
    case CostKind::AsymAbsDeviation:
      return x < t_ ? a_ * (t_ - x) : b_ * (x - t_);
    case CostKind::QuadDeviation:
      return a_ * (x - t_) * (x - t_);
    case CostKind::PiecewiseLinear: {
      const int64_t n = static_cast<int64_t>(values_.size());
      if (n == 0) return 0.0;
      if (n == 1) return values_[0];
      // Offsets are exact: first and x are both within ±2^40 for validated problems, but the
      // subtraction is done in double to stay defined for any input.
      const double i = x - static_cast<double>(guess_);
      if (i <= 0) return values_[0] + i * (values_[1] - values_[0]);
      if (i >= static_cast<double>(n - 1))
        return values_[n - 1] +
               (i - static_cast<double>(n - 1)) * (values_[n - 1] - values_[n - 2]);
      return values_[static_cast<size_t>(i)];
    }
    case CostKind::ScaleFactor: {
      const double num = x + b_;
      const double den = t_ + b_;
      if (num <= 0 || den <= 0) return kInf;
      return a_ * std::max(num / den, den / num);
    }
    case CostKind::Sum: {
      double s = 0.0;
      for (const Cost& t : terms_) s += t(x_int);
      return s;
    }
  }
  return 0.0;
}

double Cost::slope_at_plus_infinity() const {
  switch (kind_) {
    case CostKind::Zero:
      return 0.0;
    case CostKind::Linear:
      return a_;
    case CostKind::AbsDeviation:
      return a_;
    case CostKind::AsymAbsDeviation:
      return b_;
    case CostKind::QuadDeviation:
      return a_ > 0 ? kInf : 0.0;
    case CostKind::PiecewiseLinear: {
      const size_t n = values_.size();
      return n < 2 ? 0.0 : values_[n - 1] - values_[n - 2];
    }
    case CostKind::ScaleFactor:
      return a_ > 0 ? a_ / (t_ + b_) : 0.0;
    case CostKind::Sum: {
      double s = 0.0;
      for (const Cost& t : terms_) s += t.slope_at_plus_infinity();
      return s;
    }
  }
  return 0.0;
}

double Cost::slope_at_minus_infinity() const {
  switch (kind_) {
    case CostKind::Zero:
      return 0.0;
    case CostKind::Linear:
      return a_;
    case CostKind::AbsDeviation:
      return -a_;
    case CostKind::AsymAbsDeviation:
      return -a_;
    case CostKind::QuadDeviation:
      return a_ > 0 ? -kInf : 0.0;
    case CostKind::PiecewiseLinear:
      return values_.size() < 2 ? 0.0 : values_[1] - values_[0];
    case CostKind::ScaleFactor:
      // Undefined below −eps; validation keeps ScaleFactor edges away from −∞.
      return -kInf;
    case CostKind::Sum: {
      double s = 0.0;
      for (const Cost& t : terms_) s += t.slope_at_minus_infinity();
      return s;
    }
  }
  return 0.0;
}

double Cost::anchor() const {
  switch (kind_) {
    case CostKind::Zero:
      return static_cast<double>(guess_);
    case CostKind::Linear:
      return 0.0;
    case CostKind::PiecewiseLinear:
      return static_cast<double>(guess_);
    case CostKind::Sum: {
      if (terms_.empty()) return 0.0;
      double s = 0.0;
      for (const Cost& t : terms_) s += t.anchor();
      return s / static_cast<double>(terms_.size());
    }
    default:
      return t_;
  }
}

int64_t Cost::argmin(int64_t lower, int64_t upper) const {
  // Generic for every convex kind: the forward difference d(x) = c(x+1) − c(x) is
  // non-decreasing, so the minimizers form the integer interval [a, b] where a is the first x
  // with d(x) ≥ 0 and b the first x ≥ a with d(x) > 0. NaN differences (both values +∞, left
  // of a ScaleFactor's domain) count as "still descending". Both searches gallop outwards from
  // the anchor, where the minimum nearly always lies, before bisecting: a handful of
  // evaluations instead of a bisection over the whole range ±kMaxMagnitude (~80; it was 9% of
  // an exact solve, chained costs being sums of many terms).
  const int64_t lo = std::max(lower, -kMaxMagnitude);
  const int64_t hi = std::min(upper, kMaxMagnitude);
  if (lo >= hi) return lo;
  const Cost& c = *this;
  const double anchor_value = anchor();
  // The first x in [from, hi) where pred(d(x)) holds, or hi if none; pred is monotone.
  auto first_where = [&](int64_t from, auto pred) {
    if (from >= hi) return hi;
    auto holds = [&](int64_t x) { return pred(c(x + 1) - c(x)); };
    const double guess = std::isfinite(anchor_value) ? std::floor(anchor_value) : 0.0;
    const int64_t s = static_cast<int64_t>(
        std::clamp(guess, static_cast<double>(from), static_cast<double>(hi - 1)));
    int64_t l, h;  // invariant: the answer lies in [l, h]
    if (holds(s)) {
      l = from, h = s;
      for (int64_t step = 1; h > from; step *= 2) {
        const int64_t probe = std::max(from, s - step);
        if (!holds(probe)) {
          l = probe + 1;
          break;
        }
        h = probe;
      }
    } else {
      l = s + 1, h = hi;
      for (int64_t step = 1; l < hi; step *= 2) {
        const int64_t probe = std::min(hi - 1, s + step);
        if (holds(probe)) {
          h = probe;
          break;
        }
        l = probe + 1;
      }
    }
    while (l < h) {
      const int64_t mid = l + (h - l) / 2;
      if (holds(mid))
        h = mid;
      else
        l = mid + 1;
    }
    return l;
  };
  const int64_t a = first_where(lo, [](double d) { return d >= 0; });
  const int64_t b = first_where(a, [](double d) { return d > 0; });
  const double anchor_point =
      std::clamp(anchor_value, static_cast<double>(a), static_cast<double>(b));
  const double fl = std::floor(anchor_point);
  // Closest integer to the anchor, ties towards the smaller.
  const int64_t best = static_cast<int64_t>(anchor_point - fl > 0.5 ? fl + 1 : fl);
  return std::clamp(best, a, b);
}

bool operator==(const Cost& x, const Cost& y) {
  if (x.kind_ != y.kind_) return false;
  switch (x.kind_) {
    case CostKind::Zero:
      return x.guess_ == y.guess_;
    case CostKind::Linear:
      return x.a_ == y.a_;
    case CostKind::AbsDeviation:
    case CostKind::QuadDeviation:
      return x.t_ == y.t_ && x.a_ == y.a_;
    case CostKind::AsymAbsDeviation:
    case CostKind::ScaleFactor:
      return x.t_ == y.t_ && x.a_ == y.a_ && x.b_ == y.b_;
    case CostKind::PiecewiseLinear:
      return x.guess_ == y.guess_ && x.values_ == y.values_;
    case CostKind::Sum:
      return x.terms_ == y.terms_;
  }
  return false;
}

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::optional<std::string> check_target(double t) {
  if (!std::isfinite(t)) return "target must be a finite number, got " + fmt(t);
  if (std::abs(t) > kMaxTarget)
    return "target must be within +-2^40 (the flow range), got " + fmt(t);
  return std::nullopt;
}

std::optional<std::string> check_weight(const char* name, double w) {
  if (!std::isfinite(w)) return std::string(name) + " must be a finite number, got " + fmt(w);
  if (w < 0)
    return std::string(name) + " must be >= 0 (a negative " + name +
           " makes the cost non-convex), got " + fmt(w);
  if (w > kMaxCoefficient) return std::string(name) + " must be <= 1e15, got " + fmt(w);
  return std::nullopt;
}

// Parameter checks that do not depend on the bounds.
std::optional<std::string> check_parameters(const Cost& c) {
  switch (c.kind()) {
    case CostKind::Zero:
      if (c.guess() < -kMaxMagnitude || c.guess() > kMaxMagnitude)
        return "guess must be within +-2^40, got " + std::to_string(c.guess());
      return std::nullopt;
    case CostKind::Linear:
      if (!std::isfinite(c.slope())) return "slope must be a finite number, got " + fmt(c.slope());
      if (std::abs(c.slope()) > kMaxCoefficient)
        return "slope must be within +-1e15, got " + fmt(c.slope());
      return std::nullopt;
    case CostKind::AbsDeviation:
    case CostKind::QuadDeviation:
      if (auto e = check_target(c.target())) return e;
      return check_weight("weight", c.weight());
    case CostKind::AsymAbsDeviation:
      if (auto e = check_target(c.target())) return e;
      if (auto e = check_weight("weight_below", c.weight_below())) return e;
      return check_weight("weight_above", c.weight_above());
    case CostKind::ScaleFactor:
      if (auto e = check_target(c.target())) return e;
      if (auto e = check_weight("weight", c.weight())) return e;
      if (!std::isfinite(c.eps()) || c.eps() <= 0)
        return "eps must be a finite number > 0, got " + fmt(c.eps());
      if (!(c.target() + c.eps() > 0))
        return "target + eps must be > 0 for a scale-factor cost, got " + fmt(c.target()) + " + " +
               fmt(c.eps());
      return std::nullopt;
    case CostKind::PiecewiseLinear: {
      const auto& v = c.values();
      if (v.empty()) return std::string("piecewise-linear cost needs at least one value");
      if (c.first() < -kMaxMagnitude || c.first() > kMaxMagnitude ||
          static_cast<int64_t>(v.size()) > kMaxMagnitude - c.first())
        return "piecewise-linear values must lie at integers within +-2^40, first is " +
               std::to_string(c.first());
      for (size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i]))
          return "value " + std::to_string(i) + " must be a finite number, got " + fmt(v[i]);
        if (std::abs(v[i]) > kMaxCoefficient)
          return "value " + std::to_string(i) + " must be within +-1e15, got " + fmt(v[i]);
      }
      for (size_t i = 1; i + 1 < v.size(); ++i) {
        const double left = v[i] - v[i - 1], right = v[i + 1] - v[i];
        // A relative tolerance absorbs the rounding of values that were computed in double.
        const double tol =
            1e-12 * std::max({std::abs(v[i - 1]), std::abs(v[i]), std::abs(v[i + 1]), 1.0});
        if (right < left - tol)
          return "piecewise-linear cost is not convex at x = " +
                 std::to_string(c.first() + static_cast<int64_t>(i)) + ": slope " + fmt(left) +
                 " before it, " + fmt(right) + " after it (slopes must not decrease)";
      }
      return std::nullopt;
    }
    case CostKind::Sum:
      for (size_t i = 0; i < c.terms().size(); ++i)
        if (auto e = check_parameters(c.terms()[i])) return "term " + std::to_string(i) + ": " + *e;
      return std::nullopt;
  }
  return std::nullopt;
}

bool contains_scale_factor(const Cost& c) {
  if (c.kind() == CostKind::ScaleFactor) return true;
  for (const Cost& t : c.terms())
    if (contains_scale_factor(t)) return true;
  return false;
}

// The smallest eps of all ScaleFactor terms: the cost is defined for x > −min_eps.
double min_scale_factor_eps(const Cost& c) {
  if (c.kind() == CostKind::ScaleFactor) return c.eps();
  double m = kInf;
  for (const Cost& t : c.terms()) m = std::min(m, min_scale_factor_eps(t));
  return m;
}

std::string bound_str(int64_t v) {
  if (v == kInfinity) return "inf";
  if (v == -kInfinity) return "-inf";
  return std::to_string(v);
}

}  // namespace

std::optional<std::string> validate_cost(const Cost& cost, int64_t lower, int64_t upper) {
  if (auto e = check_parameters(cost)) return e;
  if (contains_scale_factor(cost)) {
    const double eps = min_scale_factor_eps(cost);
    if (lower == -kInfinity || !(static_cast<double>(lower) + eps > 0))
      return "a scale-factor cost is only defined for flow > -eps (" + fmt(-eps) +
             "), so the lower bound must be > -eps, got " + bound_str(lower);
  }
  if (upper == kInfinity && cost.slope_at_plus_infinity() < 0)
    return "cost decreases without limit as the flow grows (slope " +
           fmt(cost.slope_at_plus_infinity()) +
           " at +inf) but the upper bound is infinite: the cost has no minimum";
  if (lower == -kInfinity && cost.slope_at_minus_infinity() > 0)
    return "cost decreases without limit as the flow falls (slope " +
           fmt(cost.slope_at_minus_infinity()) +
           " at -inf) but the lower bound is infinite: the cost has no minimum";
  return std::nullopt;
}

}  // namespace bimdf
