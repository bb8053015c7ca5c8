// Reading and writing problems and solutions (formats documented in docs/formats.md).
//
// Two problem formats:
//   * `.bimdf`: libSatsuma's whitespace-separated text format, read as its writer produces it
//     (hexadecimal floats, 2147483647 as an infinite upper bound) and in decimal; `inf` is
//     accepted too. bimdf adds a few extensions (more cost kinds, outer edges, `inf`), which
//     the writer uses only when the problem needs them.
//   * JSON: bimdf's own, readable by people and scripts, with optional node and edge names.
// Readers validate the whole problem (validate() in problem.hpp) and throw InputError naming
// the source, the line (text) or JSON path, the node or edge and what was expected.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bimdf/error.hpp"
#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"

namespace bimdf {

enum class ProblemFormat { Bimdf, Json };

// Guesses the format of a problem text: JSON if its first non-blank character is '{'.
ProblemFormat detect_problem_format(std::string_view text);

// Parses a problem from text. `source` names it in error messages.
Problem parse_bimdf(std::string_view text, const std::string& source = "<string>");
Problem parse_json_problem(std::string_view text, const std::string& source = "<string>");
Problem parse_problem(std::string_view text, const std::string& source = "<string>");

// Reads a problem file in either format, chosen by content (see detect_problem_format).
// Throws InputError also when the file cannot be read.
Problem read_problem_file(const std::string& path);

struct BimdfWriteOptions {
  // Write only what libSatsuma's reader accepts: ∞ as 2147483647, bounds and demands within
  // 32 bits, cost kinds 0/A/Q/S/+ only, no outer edges. Throws InputError (with the edge) when
  // the problem cannot be expressed so. When false, the bimdf extensions are used as needed.
  bool libsatsuma_compatible = false;
};
// Decimal, shortest round-trip representation of every double (re-reading gives the same bits).
void write_bimdf(std::ostream& out, const Problem& problem, const BimdfWriteOptions& options = {});
std::string to_bimdf(const Problem& problem, const BimdfWriteOptions& options = {});

// JSON problem text (pretty-printed, names included when present).
std::string to_json_problem(const Problem& problem);

std::string to_json_solution(const Solution& solution);

// Reads a flow: a JSON solution object (its "flow"), a JSON array of integers, or whitespace-
// separated integers. Throws InputError with the position of the first bad value.
std::vector<int64_t> parse_flow(std::string_view text, const std::string& source = "<string>");
std::vector<int64_t> read_flow_file(const std::string& path);

// Reads a whole file into a string; throws InputError naming the path when it cannot.
std::string read_text_file(const std::string& path);

}  // namespace bimdf
