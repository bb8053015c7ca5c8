// Platform-independent random numbers for the generators: std::mt19937_64 is specified bit for
// bit by the standard, its distributions are not, so the mappings to ranges are our own.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace bimdf::detail {

class RandomSource {
 public:
  explicit RandomSource(uint64_t seed) : engine_(seed) {}

  // Uniform in [0, n) (n ≥ 1; the modulo bias is below 2^-40 for the sizes used here).
  int64_t below(int64_t n) { return static_cast<int64_t>(engine_() % static_cast<uint64_t>(n)); }
  // Uniform in [lo, hi].
  int64_t between(int64_t lo, int64_t hi) { return lo + below(hi - lo + 1); }
  // Uniform in [0, 1).
  double real() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double real(double lo, double hi) { return lo + (hi - lo) * real(); }
  bool chance(double p) { return real() < p; }
  // Standard normal (Box–Muller).
  double normal() {
    const double u = 1.0 - real(), v = real();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace bimdf::detail
