// collapse_inverted_quads (diagonal_collapse.hpp).
#include "mesh/diagonal_collapse.hpp"

#include <algorithm>
#include <utility>

#include "mesh/quad_cleanup.hpp"
#include "mesh/quad_quality.hpp"

namespace bimdf::detail {
namespace {

// A bound on the passes over the inverted quads: each pass collapses at least one quad, and a
// collapse can only turn a quad over that the next pass then sees; in practice two suffice.
constexpr int kMaxPasses = 8;

}  // namespace

int collapse_inverted_quads(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber,
                            std::vector<int>& merged) {
  const int nv = mesh.num_vertices();
  renumber.resize(nv);
  for (int v = 0; v < nv; ++v) renumber[v] = v;
  merged.clear();
  keep_border(mesh, may_go);
  std::vector<std::vector<int>> quads_at(nv);
  for (int q = 0; q < mesh.num_quads(); ++q)
    for (int v : mesh.quads[q]) quads_at[v].push_back(q);
  std::vector<char> quad_gone(mesh.num_quads(), 0), vertex_gone(nv, 0), took(nv, 0);
  // The vertices joined to v by an edge of one of its quads.
  const auto neighbours = [&](int v) {
    std::vector<int> out;
    for (int q : quads_at[v]) {
      const std::array<int, 4>& r = mesh.quads[q];
      const int k = static_cast<int>(std::find(r.begin(), r.end(), v) - r.begin());
      out.push_back(r[(k + 1) % 4]);
      out.push_back(r[(k + 3) % 4]);
    }
    return out;
  };
  // The worst scaled Jacobian of the quads at a and b but `skip`, with b read as a.
  const auto worst_merged = [&](int a, int b, int skip) {
    double worst = 2;
    for (int v : {a, b})
      for (int q : quads_at[v]) {
        if (q == skip) continue;
        std::array<int, 4> quad = mesh.quads[q];
        std::replace(quad.begin(), quad.end(), b, a);
        worst = std::min(worst, scaled_jacobian(mesh, quad));
      }
    return worst;
  };
  int collapsed = 0;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    std::vector<std::pair<double, int>> inverted;
    for (int q = 0; q < mesh.num_quads(); ++q)
      if (!quad_gone[q]) {
        const double s = scaled_jacobian(mesh, mesh.quads[q]);
        if (s < 0) inverted.push_back({s, q});
      }
    std::sort(inverted.begin(), inverted.end());
    const int before_pass = collapsed;
    for (const auto& [unused, q] : inverted) {
      const std::array<int, 4> quad = mesh.quads[q];
      if (quad_gone[q] || !(scaled_jacobian(mesh, quad) < 0)) continue;
      double best = -2;
      int keep = -1, drop = -1;
      for (int k = 0; k < 4; ++k) {
        const int a = quad[k], b = quad[(k + 2) % 4], c = quad[(k + 1) % 4], d = quad[(k + 3) % 4];
        if (!may_go[b] || quads_at[c].size() < 3 || quads_at[d].size() < 3) continue;
        bool manifold = true;
        for (int p : quads_at[a])
          if (p != q && std::count(quads_at[b].begin(), quads_at[b].end(), p)) manifold = false;
        const std::vector<int> around_b = neighbours(b);
        for (int u : neighbours(a))
          if (u != c && u != d && std::count(around_b.begin(), around_b.end(), u)) manifold = false;
        if (!manifold) continue;
        double before = 2;
        for (int v : {a, b})
          for (int p : quads_at[v]) before = std::min(before, scaled_jacobian(mesh, mesh.quads[p]));
        const double after = worst_merged(a, b, q);
        if (after > before && after > best) best = after, keep = a, drop = b;
      }
      if (keep < 0) continue;
      quad_gone[q] = 1;
      vertex_gone[drop] = 1;
      took[keep] = 1;
      for (int v : quad) std::erase(quads_at[v], q);
      for (int p : quads_at[drop]) {
        std::replace(mesh.quads[p].begin(), mesh.quads[p].end(), drop, keep);
        quads_at[keep].push_back(p);
      }
      quads_at[drop].clear();
      ++collapsed;
    }
    if (collapsed == before_pass) break;
  }
  if (collapsed == 0) return 0;
  drop_gone(mesh, vertex_gone, quad_gone, renumber);
  for (int v = 0; v < nv; ++v)
    if (took[v] && !vertex_gone[v]) merged.push_back(renumber[v]);
  return collapsed;
}

int collapse_inverted_quads(const quant::Layout& layout, quant::Tessellation& t,
                            std::vector<int>& merged) {
  std::vector<int> renumber;
  const int collapsed = collapse_inverted_quads(t.mesh, off_features(layout, t), renumber, merged);
  if (collapsed > 0) follow_renumbering(t, renumber);
  return collapsed;
}

}  // namespace bimdf::detail
