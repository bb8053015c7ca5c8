// remove_inverted_quads (inverted_cleanup.hpp).
#include "mesh/inverted_cleanup.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "mesh/diagonal_collapse.hpp"
#include "mesh/quad_cleanup.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::quant {
namespace {

// Smooths (relaxation and untangling, as tessellate's first phase) and polishes the vertices
// within two rings of `merged`, and returns them. A merged vertex inside the charts may move on
// every chart its quads now lie in; one on a curve keeps sliding along it. Untangling matters:
// polishing alone never accepts a move while a quad at the vertex is turned over.
std::vector<int> settle_around(const Layout& layout, const SmoothingOptions& smoothing,
                               Tessellation& t, const std::vector<int>& merged) {
  const std::vector<char> off = bimdf::detail::off_features(layout, t);
  const int nv = t.mesh.num_vertices();
  const std::vector<std::vector<int>> quads_at = bimdf::detail::quads_at_vertices(t.mesh);
  std::vector<std::vector<int>> vertex_charts(nv);
  std::vector<char> in_region(nv, 0);
  std::vector<int> region;
  const auto add = [&](int v) {
    if (!in_region[v]) in_region[v] = 1, region.push_back(v);
  };
  for (int v : merged) {
    const VertexOrigin& o = t.origin[v];
    const bool free_subside = o.subside >= 0 && off[v] && !layout.subsides[o.subside].on_border();
    if (o.chart >= 0 || free_subside) {
      for (int q : quads_at[v]) vertex_charts[v].push_back(t.mesh.quad_patch[q]);
      std::sort(vertex_charts[v].begin(), vertex_charts[v].end());
      vertex_charts[v].erase(std::unique(vertex_charts[v].begin(), vertex_charts[v].end()),
                             vertex_charts[v].end());
    }
    add(v);
  }
  for (int ring = 0; ring < 2; ++ring) {
    const std::vector<int> from = region;
    for (int v : from)
      for (int q : quads_at[v])
        for (int u : t.mesh.quads[q]) add(u);
  }
  SurfaceSmoother smoother(layout, t, &vertex_charts);
  if (smoothing.iterations > 0) smoother.run(smoothing, region);
  smoother.polish(smoothing, region);
  return region;
}

std::vector<int> inverted_quads(const QuadMesh& mesh) {
  std::vector<int> out;
  for (int q = 0; q < mesh.num_quads(); ++q)
    if (bimdf::detail::scaled_jacobian(mesh, mesh.quads[q]) < 0) out.push_back(q);
  return out;
}

// The worst scaled Jacobian of the quads with a corner among `vertices`.
double worst_at(const QuadMesh& mesh, const std::vector<int>& vertices) {
  std::vector<char> in(mesh.num_vertices(), 0);
  for (int v : vertices) in[v] = 1;
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& q : mesh.quads)
    if (in[q[0]] || in[q[1]] || in[q[2]] || in[q[3]])
      worst = std::min(worst, bimdf::detail::scaled_jacobian(mesh, q));
  return worst;
}

}  // namespace

int remove_inverted_quads(const Layout& layout, const SmoothingOptions& smoothing,
                          Tessellation& t) {
  std::vector<int> merged;
  int collapsed = bimdf::detail::collapse_inverted_quads(layout, t, merged);
  if (smoothing.quality_rounds <= 0) return collapsed;
  if (collapsed > 0) settle_around(layout, smoothing, t, merged);
  // Trial collapses, one inverted quad at a time; the list is made again after each kept one
  // (the indices shift), and a quad no trial helped is not tried again.
  std::vector<std::array<int, 4>> given_up;
  for (;;) {
    const std::vector<int> inverted = inverted_quads(t.mesh);
    std::vector<char> may_go = bimdf::detail::off_features(layout, t);
    bimdf::detail::keep_border(t.mesh, may_go);
    bool kept = false;
    for (int q : inverted) {
      const std::array<int, 4> quad = t.mesh.quads[q];
      if (std::find(given_up.begin(), given_up.end(), quad) != given_up.end()) continue;
      for (int k = 0; k < 4 && !kept; ++k) {
        const int keep = quad[k], drop = quad[(k + 2) % 4];
        if (!may_go[drop]) continue;
        Tessellation trial = t;
        std::vector<int> renumber;
        if (!bimdf::detail::collapse_diagonal(trial.mesh, q, keep, renumber)) continue;
        bimdf::detail::follow_renumbering(trial, renumber);
        const std::vector<int> region = settle_around(layout, smoothing, trial, {renumber[keep]});
        // Before: the same vertices (but the one that went) in t, the inverted quad included.
        std::vector<char> in_region(trial.mesh.num_vertices(), 0);
        for (int v : region) in_region[v] = 1;
        std::vector<int> old_region;
        for (int v = 0; v < static_cast<int>(renumber.size()); ++v)
          if (renumber[v] >= 0 && in_region[renumber[v]]) old_region.push_back(v);
        if (inverted_quads(trial.mesh).size() < inverted.size() &&
            worst_at(trial.mesh, region) > worst_at(t.mesh, old_region)) {
          t = std::move(trial);
          ++collapsed;
          kept = true;
          // The quads given up keep their vertices, under their new numbers.
          std::vector<std::array<int, 4>> renumbered;
          for (std::array<int, 4> g : given_up) {
            for (int& v : g) v = renumber[v];
            if (std::count(g.begin(), g.end(), -1) == 0) renumbered.push_back(g);
          }
          given_up = std::move(renumbered);
        }
      }
      if (kept) break;
      given_up.push_back(quad);
    }
    if (!kept) break;
  }
  return collapsed;
}

}  // namespace bimdf::quant
