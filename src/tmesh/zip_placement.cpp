// ZipPlacement (tmesh/zip_placement.hpp): the line of every zipped two-gon, both sides'
// parameters along it, and the shifts patches along it see.
#include "tmesh/zip_placement.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace bimdf::tmesh::detail {

ZipPlacement::ZipPlacement(const TMesh& tmesh, const std::vector<int64_t>& arc_length,
                           const std::vector<Zip>& zips)
    : tmesh_(tmesh),
      length_(arc_length),
      arc_zip_(tmesh.num_arcs(), -1),
      arc_side_(tmesh.num_arcs(), 0),
      arc_position_(tmesh.num_arcs(), 0),
      arc_forward_(tmesh.num_arcs(), 1) {
  const auto has_chain = [&](int h) {
    const int a = TMesh::arc_of(h);
    return a < static_cast<int>(tmesh.arc_chain.size()) && tmesh.arc_chain[a].size() >= 2;
  };
  for (const Zip& zip : zips) {
    // Both sides from the path's tail, as the half-arcs running that way.
    std::array<std::vector<int>, 2> sides{zip[0], {}};
    for (auto h = zip[1].rbegin(); h != zip[1].rend(); ++h) sides[1].push_back(TMesh::opposite(*h));
    if (!std::all_of(zip[0].begin(), zip[0].end(), has_chain) ||
        !std::all_of(zip[1].begin(), zip[1].end(), has_chain))
      continue;
    Line line;
    for (int h : sides[0]) {
      std::vector<int> chain = tmesh.arc_chain[TMesh::arc_of(h)];
      if (h & 1) std::reverse(chain.begin(), chain.end());
      line.chain.insert(line.chain.end(), chain.begin() + (line.chain.empty() ? 0 : 1),
                        chain.end());
    }
    for (int s = 0; s < 2; ++s) {
      // Per position, the least and greatest parameter of its points (a zero arc puts two).
      std::vector<std::pair<double, double>> range;
      int64_t position = 0;
      double input = 0;
      for (int h : sides[s]) {
        const int a = TMesh::arc_of(h);
        const int64_t x = arc_length[a];
        const double m = static_cast<double>(tmesh.arc_chain[a].size() - 1);
        arc_zip_[a] = static_cast<int>(lines_.size());
        arc_side_[a] = s;
        arc_position_[a] = position;
        arc_forward_[a] = (h & 1) == 0;
        range.resize(position + x + 1, {1e300, -1e300});
        for (int64_t q = 0; q <= x; ++q) {
          const double first = x > 0 ? input + m * double(q) / double(x) : input;
          const double last = x > 0 ? first : input + m;
          auto& r = range[position + q];
          r.first = std::min(r.first, first), r.second = std::max(r.second, last);
        }
        position += x, input += m;
      }
      for (const auto& [lo, hi] : range) line.parameter[s].push_back((lo + hi) / 2);
    }
    lines_.push_back(std::move(line));
  }
}

bool ZipPlacement::inside(int a, int64_t k) const {
  const int64_t position =
      arc_forward_[a] ? arc_position_[a] + k : arc_position_[a] + length_[a] - k;
  return position > 0 &&
         position + 1 < static_cast<int64_t>(lines_[arc_zip_[a]].parameter[0].size());
}

double ZipPlacement::mean_parameter(int zip, int64_t position) const {
  const Line& line = lines_[zip];
  const size_t k = std::min<size_t>(position, line.parameter[0].size() - 1);
  return (line.parameter[0][k] + line.parameter[1][std::min(k, line.parameter[1].size() - 1)]) / 2;
}

std::array<double, 3> ZipPlacement::arc_point(const QuadMesh& mesh, int a, int64_t k) const {
  const Line& line = lines_[arc_zip_[a]];
  const int64_t position =
      arc_forward_[a] ? arc_position_[a] + k : arc_position_[a] + length_[a] - k;
  const double t = std::clamp(mean_parameter(arc_zip_[a], position), 0.0,
                              static_cast<double>(line.chain.size() - 1));
  const size_t edge = std::min(static_cast<size_t>(t), line.chain.size() - 2);
  const double f = t - static_cast<double>(edge);
  const auto& p = mesh.vertices[line.chain[edge]];
  const auto& q = mesh.vertices[line.chain[edge + 1]];
  return {p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2])};
}

double ZipPlacement::shift(int h, int64_t q) const {
  const int a = TMesh::arc_of(h);
  if (arc_zip_[a] < 0) return 0;
  // Whether h runs from the path's tail towards its head.
  const bool along = ((h & 1) == 0) == static_cast<bool>(arc_forward_[a]);
  const int64_t position = along ? arc_position_[a] + q : arc_position_[a] + length_[a] - q;
  const std::vector<double>& own = lines_[arc_zip_[a]].parameter[arc_side_[a]];
  const double delta =
      mean_parameter(arc_zip_[a], position) - own[std::min<size_t>(position, own.size() - 1)];
  return along ? delta : -delta;
}

}  // namespace bimdf::tmesh::detail
