// Convex per-edge cost functions of a Bi-MDF problem (paper §3.1, DESIGN §2).
//
// A Cost is a small value type holding one of the cost kinds below. Every kind is convex on the
// integers where it is defined, can evaluate itself at an integer flow value, and can report an
// integer minimizer within an edge's bounds. Costs are evaluated in double; any integer scaling
// for combinatorial solvers happens later, in one place of the solver.
//
// Kinds and their parameters (all doubles must be finite; see validate_cost for the ranges):
//   Zero             c(x) = 0; `guess` is the flow the solver starts from (an integer).
//   Linear           c(x) = slope·x.
//   AbsDeviation     c(x) = weight·|x − target|,                          weight ≥ 0.
//   AsymAbsDeviation c(x) = weight_below·(target − x) for x < target,
//                           weight_above·(x − target) for x ≥ target,     both weights ≥ 0.
//   QuadDeviation    c(x) = weight·(x − target)²,                         weight ≥ 0.
//   PiecewiseLinear  c(first + i) = values[i] for 0 ≤ i < values.size(), linear between those
//                    integers and extended beyond both ends with the slope of the outermost
//                    segment (constant if only one value is given). Second differences must
//                    be ≥ 0 (convexity).
//   ScaleFactor      c(x) = weight·max((x+eps)/(target+eps), (target+eps)/(x+eps)), libSatsuma's
//                    scale-factor cost; defined (and convex) for x > −eps only, +∞ elsewhere.
//                    weight ≥ 0, eps > 0, target + eps > 0.
//   Sum              c(x) = Σ terms[i](x), a sum of any of the above (nested sums allowed).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bimdf {

enum class CostKind {
  Zero,
  Linear,
  AbsDeviation,
  AsymAbsDeviation,
  QuadDeviation,
  PiecewiseLinear,
  ScaleFactor,
  Sum,
};

// Number of cost kinds, for tables indexed by CostKind.
inline constexpr int kNumCostKinds = 8;

// Stable lower-case name of a kind, as used in the JSON format ("zero", "linear", "abs",
// "asym_abs", "quad", "piecewise", "scale_factor", "sum").
std::string_view cost_kind_name(CostKind kind);
// Inverse of cost_kind_name; nullopt for an unknown name.
std::optional<CostKind> cost_kind_from_name(std::string_view name);

class Cost {
 public:
  // The zero cost with guess 0.
  Cost() = default;

  static Cost zero(int64_t guess = 0);
  static Cost linear(double slope);
  static Cost abs_deviation(double target, double weight);
  static Cost asym_abs_deviation(double target, double weight_below, double weight_above);
  static Cost quad_deviation(double target, double weight);
  static Cost piecewise_linear(int64_t first, std::vector<double> values);
  static Cost scale_factor(double target, double weight, double eps = 0.1);
  static Cost sum(std::vector<Cost> terms);

  CostKind kind() const { return kind_; }

  // Parameters; each is meaningful only for the kinds named in the header comment.
  int64_t guess() const { return guess_; }                       // Zero
  double slope() const { return a_; }                            // Linear
  double target() const { return t_; }                           // Abs, AsymAbs, Quad, ScaleFactor
  double weight() const { return a_; }                           // Abs, Quad, ScaleFactor
  double weight_below() const { return a_; }                     // AsymAbs
  double weight_above() const { return b_; }                     // AsymAbs
  double eps() const { return b_; }                              // ScaleFactor
  int64_t first() const { return guess_; }                       // PiecewiseLinear
  const std::vector<double>& values() const { return values_; }  // PiecewiseLinear
  const std::vector<Cost>& terms() const { return terms_; }      // Sum

  // c(x). +infinity where the cost is undefined (ScaleFactor at x ≤ −eps).
  double operator()(int64_t x) const;

  // lim_{x→+∞} c(x+1) − c(x) and lim_{x→−∞} c(x) − c(x−1): the cost has a minimum on a
  // half-line [l, +∞) exactly when the first is ≥ 0, on (−∞, u] when the second is ≤ 0.
  // ±infinity for strictly quadratic growth.
  double slope_at_plus_infinity() const;
  double slope_at_minus_infinity() const;

  // An integer minimizer of c on [lower, upper] (either may be ±kInfinity, see problem.hpp).
  // When several integers attain the minimum, the one closest to the cost's anchor is returned
  // (Zero: its guess; deviation kinds: the target; Linear: 0; PiecewiseLinear: `first`; Sum:
  // the mean of its terms' anchors), ties broken towards the smaller value. Requires
  // lower ≤ upper and a cost that attains its minimum there (validate_cost checks both).
  int64_t argmin(int64_t lower, int64_t upper) const;

  // The point a flat minimum is resolved towards (see argmin).
  double anchor() const;

  friend bool operator==(const Cost& a, const Cost& b);

 private:
  CostKind kind_ = CostKind::Zero;
  int64_t guess_ = 0;  // Zero: guess; PiecewiseLinear: first
  double t_ = 0;       // target
  double a_ = 0;       // slope, weight, weight_below
  double b_ = 0;       // weight_above, eps
  std::vector<double> values_;
  std::vector<Cost> terms_;
};

// Checks the parameters of `cost` for use on an edge with bounds [lower, upper]: finite
// numbers within magnitude limits, non-negative weights, convex piecewise values, a defined
// ScaleFactor on the whole interval, and a minimum that exists when a bound is infinite.
// Returns nullopt when valid, else a message saying what was expected, naming the offending
// parameter (e.g. "weight must be >= 0 (a negative weight makes the cost non-convex), got -1").
std::optional<std::string> validate_cost(const Cost& cost, int64_t lower, int64_t upper);

}  // namespace bimdf
