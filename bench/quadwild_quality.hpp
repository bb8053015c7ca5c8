// QuadWild's final meshes measured with our metric, one row per shared layout, from
// ../shared/data/layouts/quadwild_quality.tsv (columns: mesh quads singular_interior msj_min
// msj_mean msj_p05 inverted border_edges; 4 digits). Header-only: the remeshing benchmark
// prints it beside ours and the shared-layout tests hold ours to it.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace bimdf::bench {

struct QuadWildQuality {
  double min = 0, mean = 0, p5 = 0;  // scaled Jacobian over quads
  int inverted = 0;
};

// Keyed by mesh name; empty when `layouts_dir` has no quadwild_quality.tsv.
inline std::map<std::string, QuadWildQuality> read_quadwild_quality(
    const std::filesystem::path& layouts_dir) {
  std::map<std::string, QuadWildQuality> rows;
  std::ifstream tsv(layouts_dir / "quadwild_quality.tsv");
  std::string line;
  std::getline(tsv, line);  // header
  while (std::getline(tsv, line)) {
    std::istringstream row(line);
    std::string mesh;
    long long quads, singular;
    QuadWildQuality q;
    if (row >> mesh >> quads >> singular >> q.min >> q.mean >> q.p5 >> q.inverted) rows[mesh] = q;
  }
  return rows;
}

// Issue 24's rule: ours at least QuadWild's (mean and p5, its figures taken as given, to 4
// digits: a tie after rounding does not count), and the minimum at least QuadWild's or above 0.2.
inline bool at_least_quadwild(double min, double mean, double p5, const QuadWildQuality& qw) {
  return mean >= qw.mean && p5 >= qw.p5 && (min >= qw.min || min > 0.2);
}

}  // namespace bimdf::bench
