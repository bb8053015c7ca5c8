// The independent check of a half-arc quantization (paper §4.3's three validity conditions and
// the non-zero paths; tmesh/half_arc.hpp) and the half-arc lengths a quantization of the cut
// T-mesh gives: kept apart from the model and the cut, so that a bug there cannot hide here.
#include <array>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/tmesh/half_arc.hpp"

namespace bimdf::tmesh {

std::vector<int64_t> half_arc_lengths(const TMesh& tmesh, const InflatedTMesh& inflated,
                                      const std::vector<int64_t>& arc_length) {
  if (arc_length.size() != inflated.arc_origin.size())
    throw std::invalid_argument("half_arc_lengths: " + std::to_string(arc_length.size()) +
                                " lengths for " + std::to_string(inflated.arc_origin.size()) +
                                " arcs of the inflated T-mesh");
  std::vector<int64_t> out(tmesh.num_half_arcs());
  for (int a = 0; a < tmesh.num_arcs(); ++a) out[2 * a] = out[2 * a + 1] = arc_length[a];
  for (const TwoGon& g : inflated.two_gons)
    for (size_t i = 0; i < g.left.size(); ++i)
      out[TMesh::opposite(g.left[i])] = arc_length[TMesh::arc_of(g.right[i])];
  return out;
}

std::string check_half_arc_quantization(const TMesh& tmesh, const std::vector<TwoGon>& two_gons,
                                        const std::vector<int64_t>& half_arc_length) {
  const auto& H = half_arc_length;
  if (static_cast<int>(H.size()) != tmesh.num_half_arcs())
    return "expected " + std::to_string(tmesh.num_half_arcs()) + " half-arc lengths, got " +
           std::to_string(H.size());
  std::vector<char> on_side(tmesh.num_half_arcs(), 0), cut(tmesh.num_arcs(), 0);
  for (const auto& sides : tmesh.patch_sides)
    for (const auto& side : sides)
      for (int h : side) on_side[h] = 1;
  std::set<std::vector<int>> relaxed;  // the arcs of each relaxed path
  for (const TwoGon& g : two_gons) {
    for (int m : g.paths) {
      if (m < 0 || m >= static_cast<int>(tmesh.nonzero_paths.size()))
        return "no non-zero path " + std::to_string(m);
      relaxed.insert(arcs_along(tmesh.nonzero_paths[m]));
    }
    for (int h : g.left) {
      if (h < 0 || h >= tmesh.num_half_arcs()) return "no half-arc " + std::to_string(h);
      cut[TMesh::arc_of(h)] = 1;
    }
  }
  // A border half-arc has no length of its own: its arc's is the other half's.
  const auto length = [&](int h) { return on_side[h] ? H[h] : H[TMesh::opposite(h)]; };
  for (int h = 0; h < tmesh.num_half_arcs(); ++h)
    if (on_side[h] && H[h] < 0)
      return "half-arc " + std::to_string(h) + ": negative length " + std::to_string(H[h]);
  for (int a = 0; a < tmesh.num_arcs(); ++a)
    if (!cut[a] && length(2 * a) != length(2 * a + 1))
      return "arc " + std::to_string(a) + ": its half-arcs have lengths " +
             std::to_string(length(2 * a)) + " and " + std::to_string(length(2 * a + 1)) +
             " but it lies on no relaxed path";
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k = 0; k < 2; ++k) {
      int64_t x = 0, y = 0;
      for (int h : tmesh.patch_sides[p][k]) x += H[h];
      for (int h : tmesh.patch_sides[p][k + 2]) y += H[h];
      if (x != y)
        return "patch " + std::to_string(p) + ": sides " + std::to_string(k) + " and " +
               std::to_string(k + 2) + " have lengths " + std::to_string(x) + " and " +
               std::to_string(y);
    }
  for (const TwoGon& g : two_gons) {
    const int n = static_cast<int>(g.left.size());
    // Prefix sums of either side along the line: sum[c][i] over its first i half-arcs.
    std::array<std::vector<int64_t>, 2> sum{std::vector<int64_t>(n + 1, 0),
                                            std::vector<int64_t>(n + 1, 0)};
    for (int i = 0; i < n; ++i) {
      sum[0][i + 1] = sum[0][i] + H[g.left[i]];
      sum[1][i + 1] = sum[1][i] + H[TMesh::opposite(g.left[i])];
    }
    const std::string line = "the line of path " + std::to_string(g.paths.front());
    if (sum[0][n] != sum[1][n])
      return line + ": its sides have lengths " + std::to_string(sum[0][n]) + " and " +
             std::to_string(sum[1][n]);
    if (g.paths.size() == 1 && sum[0][n] < 1) return line + ": it has length 0";
    if (g.paths.size() == 2 && sum[0][g.left_end] < 1)
      return "path " + std::to_string(g.paths[0]) + ": its left side has length 0";
    if (g.paths.size() == 2 && sum[1][n] - sum[1][g.right_start] < 1)
      return "path " + std::to_string(g.paths[1]) + ": its right side has length 0";
  }
  for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m) {
    if (relaxed.count(arcs_along(tmesh.nonzero_paths[m]))) continue;
    int64_t sum = 0;
    for (int h : tmesh.nonzero_paths[m]) sum += length(h);
    if (sum == 0) return "non-zero path " + std::to_string(m) + " has length 0";
  }
  return "";
}

}  // namespace bimdf::tmesh
