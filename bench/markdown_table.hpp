// Cells of a Markdown table row, as the shared data's READMEs write them: "| a | b |" gives
// {"", "a", "b"} (the leading empty cell comes from the first '|'), each cell trimmed of spaces.
// Header-only: the benchmarks and the tests (through bimdf_milp's include path) read the same
// reference tables.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace bimdf::bench {

inline std::vector<std::string> markdown_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream row(line);
  for (std::string cell; std::getline(row, cell, '|');) {
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    cells.push_back(cell);
  }
  return cells;
}

}  // namespace bimdf::bench
