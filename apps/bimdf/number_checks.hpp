// Checks of the CLI's floating-point options. CLI11's own (PositiveNumber, Range) let NaN
// through — every comparison with NaN is false — and quote their bounds in full, so that
// `--scale 0` was answered with a 300-digit upper bound. These accept finite numbers only and
// say what was expected in the option's own terms, e.g.
//   --scale: expected a positive number, got 0
//   --alpha: expected a number from 0 to 1, got nan
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>

namespace bimdf::cli {

CLI::Validator positive_number();                           // finite and > 0
CLI::Validator non_negative_number();                       // finite and ≥ 0
CLI::Validator number_from(double lowest, double highest);  // finite, in [lowest, highest]
CLI::Validator finite_number();                             // any finite number

// Integer options: the text must be a whole number in decimal (no "1e3", no "1.5").
CLI::Validator positive_whole_number();                             // ≥ 1
CLI::Validator whole_number_from(int64_t lowest, int64_t highest);  // in [lowest, highest]

}  // namespace bimdf::cli
