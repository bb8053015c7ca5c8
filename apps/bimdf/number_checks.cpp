#include "number_checks.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <utility>

namespace bimdf::cli {

namespace {

// The option's text as a finite double, or nullopt when it is not one (a word, "nan", "inf",
// trailing characters).
std::optional<double> parse_finite(const std::string& text) {
  try {
    size_t used = 0;
    const double x = std::stod(text, &used);
    if (used == text.size() && std::isfinite(x)) return x;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// The option's text as an integer, or nullopt when it is not a whole decimal number that fits.
std::optional<int64_t> parse_whole(const std::string& text) {
  try {
    size_t used = 0;
    const long long x = std::stoll(text, &used, 10);
    if (used == text.size()) return int64_t{x};
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::string compact(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// A check that `parse` reads the text and `accept` takes the value; `description` is what
// --help shows after the type (FLOAT:POSITIVE, as CLI11's own).
template <typename T>
CLI::Validator number_check(std::optional<T> (*parse)(const std::string&), std::string expected,
                            std::string description, std::function<bool(T)> accept) {
  return CLI::Validator(
      [parse, expected, accept](std::string& text) -> std::string {
        const std::optional<T> x = parse(text);
        if (x && accept(*x)) return "";
        return "expected " + expected + ", got " + text;
      },
      std::move(description));
}

}  // namespace

CLI::Validator positive_number() {
  return number_check<double>(parse_finite, "a positive number", "POSITIVE",
                              [](double x) { return x > 0; });
}

CLI::Validator non_negative_number() {
  return number_check<double>(parse_finite, "a number >= 0", "NONNEGATIVE",
                              [](double x) { return x >= 0; });
}

CLI::Validator number_from(double lowest, double highest) {
  return number_check<double>(parse_finite,
                              "a number from " + compact(lowest) + " to " + compact(highest),
                              "in [" + compact(lowest) + " - " + compact(highest) + "]",
                              [=](double x) { return x >= lowest && x <= highest; });
}

CLI::Validator finite_number() {
  return number_check<double>(parse_finite, "a finite number", "FINITE",
                              [](double) { return true; });
}

CLI::Validator positive_whole_number() {
  return number_check<int64_t>(parse_whole, "a positive whole number", "POSITIVE",
                               [](int64_t x) { return x >= 1; });
}

CLI::Validator whole_number_from(int64_t lowest, int64_t highest) {
  const std::string range = std::to_string(lowest) + " to " + std::to_string(highest);
  return number_check<int64_t>(
      parse_whole, "a whole number from " + range,
      "in [" + std::to_string(lowest) + " - " + std::to_string(highest) + "]",
      [=](int64_t x) { return x >= lowest && x <= highest; });
}

}  // namespace bimdf::cli
