#include "shared_layouts.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "markdown_table.hpp"

namespace bimdf::testing {

std::vector<Reference> references() {
  std::vector<Reference> refs;
  std::ifstream in(kLayouts / "README.md");
  std::map<std::string, double> exact_noalign, exact_align;  // expected.tsv: more digits
  std::ifstream tsv(kLayouts / "expected.tsv");
  std::string line;
  std::getline(tsv, line);
  while (std::getline(tsv, line)) {
    std::istringstream row(line);
    std::string mesh;
    int patches;
    double a, b;
    if (row >> mesh >> patches >> a >> b) exact_noalign[mesh] = a, exact_align[mesh] = b;
  }
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = bench::markdown_cells(line);
    if (cells.size() < 14 || !exact_noalign.count(cells[1])) continue;
    Reference r;
    r.mesh = cells[1];
    r.patches = std::stoi(cells[2]);
    r.noalign_opt = exact_noalign[r.mesh];
    r.noalign_iso = std::stod(cells[5]);
    r.noalign_reg = std::stod(cells[6]);
    r.align_opt = exact_align[r.mesh];
    r.align_iso = std::stod(cells[9]);
    r.align_reg = std::stod(cells[10]);
    r.align_energy = std::stod(cells[11]);
    std::sscanf(cells[12].c_str(), "%d/%d", &r.aligned, &r.pairs);
    r.noalign_quads = std::stoi(cells[7]);
    r.align_quads = std::stoi(cells[13]);
    refs.push_back(r);
  }
  return refs;
}

}  // namespace bimdf::testing
