// remove_inverted_quads (inverted_cleanup.hpp).
#include "mesh/inverted_cleanup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/closest_point.hpp"
#include "mesh/diagonal_collapse.hpp"
#include "mesh/quad_cleanup.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::quant {
namespace {

// Smooths (relaxation and untangling, as tessellate's first phase) and polishes the vertices
// within two rings of `merged`, and returns them. A merged vertex inside the charts may move on
// every chart its quads now lie in; one on a curve keeps sliding along it, unless `released`
// marks it: released vertices (wherever they are) move on their quads' charts too. Untangling
// matters: polishing alone never accepts a move while a quad at the vertex is turned over.
std::vector<int> settle_around(const Layout& layout, const SmoothingOptions& smoothing,
                               Tessellation& t, const std::vector<int>& merged,
                               const std::vector<char>& released) {
  const std::vector<char> off = bimdf::detail::off_features(layout, t);
  const int nv = t.mesh.num_vertices();
  const std::vector<std::vector<int>> quads_at = bimdf::detail::quads_at_vertices(t.mesh);
  std::vector<std::vector<int>> vertex_charts(nv);
  std::vector<char> in_region(nv, 0);
  std::vector<int> region;
  const auto add = [&](int v) {
    if (!in_region[v]) in_region[v] = 1, region.push_back(v);
  };
  const auto free_on_own_charts = [&](int v) {
    vertex_charts[v].clear();
    for (int q : quads_at[v]) vertex_charts[v].push_back(t.mesh.quad_patch[q]);
    std::sort(vertex_charts[v].begin(), vertex_charts[v].end());
    vertex_charts[v].erase(std::unique(vertex_charts[v].begin(), vertex_charts[v].end()),
                           vertex_charts[v].end());
  };
  for (int v = 0; v < nv; ++v)
    if (released[v]) free_on_own_charts(v);
  for (int v : merged) {
    const VertexOrigin& o = t.origin[v];
    const bool free_subside = o.subside >= 0 && off[v] && !layout.subsides[o.subside].on_border();
    if (o.chart >= 0 || free_subside) free_on_own_charts(v);
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

// Flat quads (corners together, or a scaled Jacobian of exactly 0) are not counted as inverted;
// a trial that swaps an inverted quad for a flat one is no better (measured: mannequin-devil's
// tip gave one without this).
int flat_quads(const QuadMesh& mesh) {
  int flat = 0;
  for (const auto& q : mesh.quads) flat += bimdf::detail::degenerate(mesh, q);
  return flat;
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

// Lets vertices of feature curves leave them where an inverted quad has them as corners, on a
// copy: first the quad's own corners inside curves (not feature corners), then those of the
// quads around them, then — last resort, for needles at a tip — those quads' feature corners
// too. The freed vertices move on their quads' charts; the copy is smoothed and polished as
// after a collapse and kept if it has fewer inverted quads and a better worst quad around.
// Border vertices and vertices already freed stay as they are. Only inverted quads with a
// corner marked in `near` are looked at, when it is given. Returns how many vertices were
// freed; `released` marks them (they keep moving freely in later settles).
int release_from_features(const Layout& layout, const SmoothingOptions& smoothing, Tessellation& t,
                          std::vector<char>& released, const std::vector<char>* near = nullptr) {
  std::vector<char> on_curve = bimdf::detail::off_features(layout, t);
  for (char& c : on_curve) c = !c;
  std::vector<char> inner(t.mesh.num_vertices(), 1);
  bimdf::detail::keep_border(t.mesh, inner);
  std::vector<char> feature_corner(layout.mesh.num_vertices(), 0);
  for (int v : layout.feature_corners) feature_corner[v] = 1;
  const auto may_leave = [&](int v, bool corners_too) {
    const VertexOrigin& o = t.origin[v];
    return on_curve[v] && inner[v] && !released[v] &&
           (o.subside >= 0 ||
            (o.mesh_vertex >= 0 && (corners_too || !feature_corner[o.mesh_vertex])));
  };
  const std::vector<std::vector<int>> quads_at = bimdf::detail::quads_at_vertices(t.mesh);
  int freed_in_all = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int q : inverted_quads(t.mesh)) {
      if (near && std::none_of(t.mesh.quads[q].begin(), t.mesh.quads[q].end(),
                               [&](int v) { return (*near)[v] != 0; }))
        continue;
      // `t` changes only when a trial is kept, and then the tiers stop: one list serves them.
      const std::vector<int> now = inverted_quads(t.mesh);
      if (std::find(now.begin(), now.end(), q) == now.end()) continue;
      size_t tried = 0;  // vertices freed by the last tier tried (each tier's are a superset)
      for (int tier = 0; tier < 3; ++tier) {
        std::vector<int> around(t.mesh.quads[q].begin(), t.mesh.quads[q].end());
        if (tier > 0)
          for (int c : t.mesh.quads[q])
            for (int f : quads_at[c])
              around.insert(around.end(), t.mesh.quads[f].begin(), t.mesh.quads[f].end());
        std::vector<char> trial_released = released;
        std::vector<int> freed;
        for (int v : around)
          if (may_leave(v, tier == 2) && !trial_released[v])
            trial_released[v] = 1, freed.push_back(v);
        if (freed.size() == tried) continue;  // nothing new to free: the same trial again
        tried = freed.size();
        Tessellation trial = t;
        const std::vector<int> region =
            settle_around(layout, smoothing, trial, freed, trial_released);
        if (inverted_quads(trial.mesh).size() < now.size() &&
            flat_quads(trial.mesh) <= flat_quads(t.mesh) &&
            worst_at(trial.mesh, region) > worst_at(t.mesh, region)) {
          t = std::move(trial);
          released = std::move(trial_released);
          freed_in_all += static_cast<int>(freed.size());
          changed = true;
          break;
        }
      }
    }
  }
  return freed_in_all;
}

}  // namespace

int remove_inverted_quads(const Layout& layout, const SmoothingOptions& smoothing,
                          Tessellation& t) {
  std::vector<int> merged;
  int collapsed = bimdf::detail::collapse_inverted_quads(layout, t, merged);
  if (smoothing.quality_rounds <= 0) return collapsed;
  if (collapsed > 0)
    settle_around(layout, smoothing, t, merged, std::vector<char>(t.mesh.num_vertices(), 0));
  // Trial collapses, one inverted quad at a time; the list is made again after each kept one
  // (the indices shift), and a quad no trial helped is not tried again.
  std::vector<std::array<int, 4>> given_up;
  std::vector<char> released(t.mesh.num_vertices(), 0);
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
        std::vector<char> trial_released(trial.mesh.num_vertices(), 0);
        for (int v = 0; v < static_cast<int>(renumber.size()); ++v)
          if (renumber[v] >= 0 && released[v]) trial_released[renumber[v]] = 1;
        const std::vector<int> region =
            settle_around(layout, smoothing, trial, {renumber[keep]}, trial_released);
        // Before: the same vertices (but the one that went) in t, the inverted quad included.
        std::vector<char> in_region(trial.mesh.num_vertices(), 0);
        for (int v : region) in_region[v] = 1;
        std::vector<int> old_region;
        for (int v = 0; v < static_cast<int>(renumber.size()); ++v)
          if (renumber[v] >= 0 && in_region[renumber[v]]) old_region.push_back(v);
        const auto better = [&] {
          return inverted_quads(trial.mesh).size() < inverted.size() &&
                 flat_quads(trial.mesh) <= flat_quads(t.mesh) &&
                 worst_at(trial.mesh, region) > worst_at(t.mesh, old_region);
        };
        // Where the merge leaves a quad inverted at a feature curve, the curve's vertices
        // there may have to leave it too.
        int freed = 0;
        if (!better())
          freed = release_from_features(layout, smoothing, trial, trial_released, &in_region);
        if (better()) {
          t = std::move(trial);
          released = std::move(trial_released);
          t.released_from_features += freed;
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
  t.released_from_features += release_from_features(layout, smoothing, t, released);
  // How far the mesh left the features: each freed vertex's distance to the nearest feature
  // edge, the largest, in average edge lengths.
  for (int v = 0; v < t.mesh.num_vertices() && layout.average_edge_length > 0; ++v) {
    if (!released[v]) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : layout.feature_edges) {
      const bimdf::detail::Vec3 q = bimdf::detail::closest_point_on_segment(
          t.mesh.vertices[v], layout.mesh.vertices[a], layout.mesh.vertices[b]);
      nearest = std::min(nearest, bimdf::detail::norm(bimdf::detail::sub(q, t.mesh.vertices[v])));
    }
    if (std::isfinite(nearest))
      t.released_max_offset = std::max(t.released_max_offset, nearest / layout.average_edge_length);
  }
  return collapsed;
}

}  // namespace bimdf::quant
