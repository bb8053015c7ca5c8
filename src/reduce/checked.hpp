// Overflow checks for the integer sums the reductions form (demands adjusted by flows, bounds
// shifted by guesses). Inputs are limited to ±2^40 (problem.hpp), so sums over a real network
// stay far below 2^62; the check makes the rare hostile case an error instead of a wrong answer.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace bimdf::detail {

// Largest magnitude an intermediate integer may take: leaves headroom for one more addition
// of two such values without leaving int64.
inline constexpr int64_t kMaxIntermediate = int64_t{1} << 62;

// `value` as int64, or std::overflow_error naming `what` when |value| > kMaxIntermediate.
inline int64_t narrow_checked(__int128 value, const std::string& what) {
  if (value > kMaxIntermediate || value < -kMaxIntermediate)
    throw std::overflow_error(what + " exceeds 2^62 in magnitude; the problem's values are too "
                                     "large to solve with 64-bit integers");
  return static_cast<int64_t>(value);
}

}  // namespace bimdf::detail
