// collapse_inverted_quads (diagonal_collapse.hpp).
#include "mesh/diagonal_collapse.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "mesh/quad_cleanup.hpp"
#include "mesh/quad_quality.hpp"

namespace bimdf::detail {
namespace {

// A bound on the passes over the inverted quads: each pass collapses at least one quad, and a
// collapse can only turn a quad over that the next pass then sees; in practice two suffice.
constexpr int kMaxPasses = 8;

// Whether merging corner b of quad q into its opposite corner a keeps the mesh manifold: a and
// b share no other quad and no neighbour but q's two other corners, each of which keeps two
// quads. `quads_at`: the quads at each vertex.
bool keeps_manifold(const QuadMesh& mesh, const std::vector<std::vector<int>>& quads_at, int q,
                    int a, int b) {
  const std::array<int, 4>& quad = mesh.quads[q];
  const int k = static_cast<int>(std::find(quad.begin(), quad.end(), a) - quad.begin());
  const int c = quad[(k + 1) % 4], d = quad[(k + 3) % 4];
  if (quad[(k + 2) % 4] != b || quads_at[c].size() < 3 || quads_at[d].size() < 3) return false;
  for (int p : quads_at[a])
    if (p != q && std::count(quads_at[b].begin(), quads_at[b].end(), p)) return false;
  // The vertices joined to v by an edge of one of its quads.
  const auto neighbours = [&](int v) {
    std::vector<int> out;
    for (int p : quads_at[v]) {
      const std::array<int, 4>& r = mesh.quads[p];
      const int i = static_cast<int>(std::find(r.begin(), r.end(), v) - r.begin());
      out.push_back(r[(i + 1) % 4]);
      out.push_back(r[(i + 3) % 4]);
    }
    return out;
  };
  const std::vector<int> around_b = neighbours(b);
  for (int u : neighbours(a))
    if (u != c && u != d && std::count(around_b.begin(), around_b.end(), u)) return false;
  return true;
}

// Merges b into a (quad q goes) in `mesh` and `quads_at`, marking what is gone.
void merge_corners(QuadMesh& mesh, std::vector<std::vector<int>>& quads_at, int q, int a, int b,
                   std::vector<char>& quad_gone, std::vector<char>& vertex_gone) {
  quad_gone[q] = 1;
  vertex_gone[b] = 1;
  for (int v : mesh.quads[q]) std::erase(quads_at[v], q);
  for (int p : quads_at[b]) {
    std::replace(mesh.quads[p].begin(), mesh.quads[p].end(), b, a);
    quads_at[a].push_back(p);
  }
  quads_at[b].clear();
}

}  // namespace

bool collapse_diagonal(QuadMesh& mesh, int q, int keep, std::vector<int>& renumber) {
  const std::array<int, 4> quad = mesh.quads.at(q);
  const auto at = std::find(quad.begin(), quad.end(), keep);
  if (at == quad.end()) throw std::invalid_argument("collapse_diagonal: keep is not a corner");
  const int drop = quad[(at - quad.begin() + 2) % 4];
  std::vector<std::vector<int>> quads_at = quads_at_vertices(mesh);
  if (!keeps_manifold(mesh, quads_at, q, keep, drop)) return false;
  std::vector<char> quad_gone(mesh.num_quads(), 0), vertex_gone(mesh.num_vertices(), 0);
  merge_corners(mesh, quads_at, q, keep, drop, quad_gone, vertex_gone);
  drop_gone(mesh, vertex_gone, quad_gone, renumber);
  return true;
}

int collapse_inverted_quads(QuadMesh& mesh, std::vector<char> may_go, std::vector<int>& renumber,
                            std::vector<int>& merged) {
  const int nv = mesh.num_vertices();
  renumber.resize(nv);
  for (int v = 0; v < nv; ++v) renumber[v] = v;
  merged.clear();
  keep_border(mesh, may_go);
  std::vector<std::vector<int>> quads_at = quads_at_vertices(mesh);
  std::vector<char> quad_gone(mesh.num_quads(), 0), vertex_gone(nv, 0), took(nv, 0);
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
        const int a = quad[k], b = quad[(k + 2) % 4];
        if (!may_go[b] || !keeps_manifold(mesh, quads_at, q, a, b)) continue;
        double before = 2;
        for (int v : {a, b})
          for (int p : quads_at[v]) before = std::min(before, scaled_jacobian(mesh, mesh.quads[p]));
        const double after = worst_merged(a, b, q);
        if (after > before && after > best) best = after, keep = a, drop = b;
      }
      if (keep < 0) continue;
      merge_corners(mesh, quads_at, q, keep, drop, quad_gone, vertex_gone);
      took[keep] = 1;
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
