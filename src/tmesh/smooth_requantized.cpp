// smooth_requantized (smooth_requantized.hpp): a quant::Layout built directly from the T-mesh
// (no boundary walk needed: patches and arcs are the charts and subsides already), a
// quant::Tessellation around the collapsed mesh, and SurfaceSmoother with per-vertex charts.
#include "tmesh/smooth_requantized.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/quad_quality.hpp"
#include "mesh/smoothing.hpp"

namespace bimdf::tmesh {
namespace {

using Vec3 = std::array<double, 3>;

// A border corner of a single quad flatter than 179° counts as straight (see movable_vertices).
const double kFlatCosine = std::cos(179.0 * std::numbers::pi / 180);

double distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The point of polyline `chain` (mesh vertices) closest to p.
Vec3 closest_on_chain(const QuadMesh& mesh, const std::vector<int>& chain, const Vec3& p) {
  Vec3 best = mesh.vertices[chain.front()];
  double best_d2 = -1;
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    const Vec3& a = mesh.vertices[chain[i]];
    const Vec3& b = mesh.vertices[chain[i + 1]];
    double ab2 = 0, t = 0;
    for (int d = 0; d < 3; ++d)
      ab2 += (b[d] - a[d]) * (b[d] - a[d]), t += (p[d] - a[d]) * (b[d] - a[d]);
    t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
    // Exactly b when clamped there (a + 1·(b − a) can differ in the last bit): callers test
    // whether the point landed on an end of the chain.
    Vec3 q = b;
    if (t < 1)
      for (int d = 0; d < 3; ++d) q[d] = a[d] + t * (b[d] - a[d]);
    double d2 = 0;
    for (int d = 0; d < 3; ++d) d2 += (q[d] - p[d]) * (q[d] - p[d]);
    if (best_d2 < 0 || d2 < best_d2) best = q, best_d2 = d2;
  }
  return best;
}

// Every vertex except those of flat border corners: a quad alone at a border vertex whose two
// border edges there continue each other (an input vertex of border valence 2 on a straight
// border, kept by the layout) has a corner of ~180° wherever its vertices slide. Its vertices
// would have a worst quad of ~0 throughout, and SurfaceSmoother accepts any move that does
// not make a vertex's worst quad worse, so they would flatten their other quads too.
std::vector<int> movable_vertices(const QuadMesh& mesh) {
  std::map<std::pair<int, int>, int> edge_quads;
  std::vector<std::vector<int>> vertex_quads(mesh.num_vertices());
  for (int f = 0; f < mesh.num_quads(); ++f)
    for (int a = 0; a < 4; ++a) {
      const int u = mesh.quads[f][a], v = mesh.quads[f][(a + 1) % 4];
      ++edge_quads[{std::min(u, v), std::max(u, v)}];
      vertex_quads[u].push_back(f);
    }
  std::vector<char> frozen(mesh.num_vertices(), 0);
  for (int c = 0; c < mesh.num_vertices(); ++c) {
    if (vertex_quads[c].size() != 1) continue;
    const auto& q = mesh.quads[vertex_quads[c][0]];
    const int a = static_cast<int>(std::find(q.begin(), q.end(), c) - q.begin());
    const Vec3& x = mesh.vertices[c];
    const Vec3& p = mesh.vertices[q[(a + 3) % 4]];
    const Vec3& n = mesh.vertices[q[(a + 1) % 4]];
    const double lp = distance(p, x), ln = distance(n, x);
    double cosine = 0;
    for (int d = 0; d < 3; ++d) cosine += (p[d] - x[d]) * (n[d] - x[d]);
    if (lp > 0 && ln > 0 && cosine / (lp * ln) > kFlatCosine) continue;
    for (int v : q) frozen[v] = 1;
  }
  std::vector<int> moving;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (!frozen[v]) moving.push_back(v);
  return moving;
}

bool has_geometry(const TMesh& tmesh) {
  if (tmesh.patch_grid.size() != tmesh.patch_sides.size() ||
      tmesh.arc_chain.size() != tmesh.arc_ends.size() ||
      tmesh.vertex_mesh_vertex.size() != tmesh.vertices.size())
    return false;
  for (const PatchGrid& g : tmesh.patch_grid)
    if (g.empty()) return false;
  for (int m : tmesh.vertex_mesh_vertex)
    if (m < 0) return false;
  for (const auto& chain : tmesh.arc_chain)
    if (chain.size() < 2) return false;
  return true;
}

}  // namespace

quant::Layout requantization_layout(const QuadMesh& input, const TMesh& tmesh,
                                    const TMeshIncidence& incidence,
                                    const std::vector<std::array<int, 2>>& feature_edges,
                                    const std::vector<int>& feature_corners) {
  if (!has_geometry(tmesh))
    throw std::invalid_argument("the T-mesh has no patch grids or arc chains to smooth on");
  quant::Layout layout;
  const int nv = input.num_vertices(), nq = input.num_quads();
  layout.mesh.vertices = input.vertices;
  layout.mesh.faces.reserve(size_t(2) * nq);
  std::unordered_map<int64_t, int> quad_of_edge;  // directed edge u → v: its quad
  double edge_sum = 0;
  for (int f = 0; f < nq; ++f) {
    const auto& q = input.quads[f];
    layout.mesh.faces.push_back({q[0], q[1], q[2]});
    layout.mesh.faces.push_back({q[0], q[2], q[3]});
    for (int a = 0; a < 4; ++a) quad_of_edge[int64_t{q[a]} * nv + q[(a + 1) % 4]] = f;
    for (const auto& t : {layout.mesh.faces[2 * f], layout.mesh.faces[2 * f + 1]})
      for (int a = 0; a < 3; ++a)
        edge_sum += distance(input.vertices[t[a]], input.vertices[t[(a + 1) % 3]]);
  }
  if (nq > 0) layout.average_edge_length = edge_sum / (6.0 * nq);

  // Charts: the triangles of each patch's grid cells (the cell's bottom edge, walked from
  // (i, j) to (i + 1, j), belongs to its quad).
  const int np = tmesh.num_patches();
  layout.face_chart.assign(layout.mesh.faces.size(), -1);
  layout.charts.resize(np);
  for (int p = 0; p < np; ++p) {
    const PatchGrid& g = tmesh.patch_grid[p];
    for (int j = 0; j < g.height; ++j)
      for (int i = 0; i < g.width; ++i) {
        const auto it = quad_of_edge.find(int64_t{g.at(i, j)} * nv + g.at(i + 1, j));
        if (it == quad_of_edge.end())
          throw std::invalid_argument("patch " + std::to_string(p) + ": grid cell (" +
                                      std::to_string(i) + ", " + std::to_string(j) +
                                      ") is not a quad of the mesh");
        for (int t : {2 * it->second, 2 * it->second + 1}) {
          layout.face_chart[t] = p;
          layout.charts[p].faces.push_back(t);
        }
      }
  }

  // Subsides = arcs, their chain in the walking direction of charts[0] (the patch of half-arc
  // 2a, or of 2a + 1 when 2a is a border half-arc).
  const int na = tmesh.num_arcs();
  layout.subsides.resize(na);
  std::vector<int> primary(na);  // the half-arc whose direction the subside's chain follows
  for (int a = 0; a < na; ++a) {
    quant::Subside& s = layout.subsides[a];
    primary[a] = incidence.half_arc_patch[2 * a] >= 0 ? 2 * a : 2 * a + 1;
    const int other = TMesh::opposite(primary[a]);
    s.charts = {incidence.half_arc_patch[primary[a]], incidence.half_arc_patch[other]};
    s.sides = {incidence.half_arc_side[primary[a]], incidence.half_arc_side[other]};
    s.vertices = tmesh.arc_chain[a];
    if (primary[a] & 1) std::reverse(s.vertices.begin(), s.vertices.end());
    for (size_t i = 0; i + 1 < s.vertices.size(); ++i)
      s.length += distance(input.vertices[s.vertices[i]], input.vertices[s.vertices[i + 1]]);
  }
  for (int p = 0; p < np; ++p) {
    quant::Chart& chart = layout.charts[p];
    chart.sides.resize(4);
    for (int k = 0; k < 4; ++k) {
      const std::vector<int>& side = tmesh.patch_sides[p][k];
      chart.corners.push_back(tmesh.vertex_mesh_vertex[tmesh.half_arc_tail(side.front())]);
      for (int h : side) {
        const int a = TMesh::arc_of(h);
        chart.sides[k].subsides.push_back(a);
        chart.sides[k].reversed.push_back(h != primary[a]);
        chart.sides[k].length += layout.subsides[a].length;
        chart.subsides.push_back(a);
      }
    }
  }

  std::set<std::pair<int, int>> features;
  for (const auto& e : feature_edges) features.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  for (int a = 0; a < na; ++a)
    if (a < static_cast<int>(tmesh.arc_feature.size()) && tmesh.arc_feature[a])
      for (size_t i = 0; i + 1 < tmesh.arc_chain[a].size(); ++i) {
        const int u = tmesh.arc_chain[a][i], v = tmesh.arc_chain[a][i + 1];
        features.insert({std::min(u, v), std::max(u, v)});
      }
  for (const auto& [u, v] : features) layout.feature_edges.push_back({u, v});
  layout.feature_corners = feature_corners;
  return layout;
}

SmoothedQuads smooth_requantized(const QuadMesh& input, const TMesh& tmesh,
                                 const TMeshIncidence& incidence,
                                 const std::vector<std::array<int, 2>>& feature_edges,
                                 const std::vector<int>& feature_corners, CollapsedMesh& result,
                                 const quant::SmoothingOptions& options,
                                 const std::vector<std::vector<int>>& more_charts) {
  if ((options.iterations <= 0 && options.quality_rounds <= 0) || !has_geometry(tmesh)) return {};
  const quant::Layout layout =
      requantization_layout(input, tmesh, incidence, feature_edges, feature_corners);
  // Curves are what SurfaceSmoother slides along: border subsides and those on features.
  std::set<std::pair<int, int>> features;
  for (const auto& e : layout.feature_edges) features.insert({e[0], e[1]});
  const int na = tmesh.num_arcs();
  std::vector<char> curve(na, 0);
  for (int a = 0; a < na; ++a) {
    const quant::Subside& s = layout.subsides[a];
    bool on_feature = !features.empty();
    for (size_t i = 0; on_feature && i + 1 < s.vertices.size(); ++i)
      on_feature = features.count({std::min(s.vertices[i], s.vertices[i + 1]),
                                   std::max(s.vertices[i], s.vertices[i + 1])}) > 0;
    curve[a] = s.on_border() || on_feature;
  }
  std::vector<char> is_feature_corner(input.num_vertices(), 0);
  for (int m : feature_corners) is_feature_corner[m] = 1;
  std::vector<int> curves_at(tmesh.num_vertices(), 0);
  for (int a = 0; a < na; ++a)
    if (curve[a]) ++curves_at[tmesh.arc_ends[a][0]], ++curves_at[tmesh.arc_ends[a][1]];

  quant::Tessellation t;
  t.mesh = std::move(result.mesh);
  const int nv = t.mesh.num_vertices();
  t.origin.resize(nv);
  std::vector<std::vector<int>> vertex_charts(nv);
  for (int v = 0; v < nv; ++v) {
    const CollapsedVertex& o = result.origin[v];
    quant::VertexOrigin& origin = t.origin[v];
    // A T-mesh vertex on a curve or a feature corner decides (the smoother pins it or lets it
    // slide along its curves), the most constrained one first; then a point of a curve arc.
    int anchor = -1;
    for (int r : o.tmesh_vertices) {
      const int m = tmesh.vertex_mesh_vertex[r];
      if (m < 0 || (!is_feature_corner[m] && curves_at[r] == 0)) continue;
      const auto rank = [&](int x) {
        return std::pair{is_feature_corner[tmesh.vertex_mesh_vertex[x]], curves_at[x]};
      };
      if (anchor < 0 || rank(r) > rank(anchor)) anchor = r;
    }
    if (anchor >= 0) {
      origin.mesh_vertex = tmesh.vertex_mesh_vertex[anchor];
      t.mesh.vertices[v] = input.vertices[origin.mesh_vertex];
      continue;
    }
    const auto on_curve =
        std::find_if(o.arcs.begin(), o.arcs.end(), [&](int a) { return curve[a]; });
    if (on_curve != o.arcs.end()) {
      origin.subside = *on_curve;
      // The closest point to the mean of everything merged into it — unless that is an end of
      // the curve arc, where the vertex at that end sits (a curve edge much shorter than its
      // neighbours): then its own point on the arc, or the quad between them is degenerate
      // and no move along so short a curve opens it.
      const std::vector<int>& chain = tmesh.arc_chain[*on_curve];
      Vec3 at = closest_on_chain(input, chain, t.mesh.vertices[v]);
      if (at == input.vertices[chain.front()] || at == input.vertices[chain.back()])
        for (const auto& [a, p] : o.arc_points)
          if (a == *on_curve) at = closest_on_chain(input, chain, p);
      t.mesh.vertices[v] = at;
      continue;
    }
    if (!o.tmesh_vertices.empty())
      origin.mesh_vertex = tmesh.vertex_mesh_vertex[o.tmesh_vertices.front()];
    else if (!o.arcs.empty())
      origin.subside = o.arcs.front();
    else
      origin.chart = o.patches.front();
    vertex_charts[v] = o.patches;
    if (!more_charts.empty()) {
      for (int p : o.patches)
        vertex_charts[v].insert(vertex_charts[v].end(), more_charts[p].begin(),
                                more_charts[p].end());
      std::sort(vertex_charts[v].begin(), vertex_charts[v].end());
      vertex_charts[v].erase(std::unique(vertex_charts[v].begin(), vertex_charts[v].end()),
                             vertex_charts[v].end());
    }
  }
  const std::vector<int> moving = movable_vertices(t.mesh);
  SmoothedQuads outcome;
  {
    quant::SurfaceSmoother smoother(layout, t, &vertex_charts);
    const std::vector<Vec3> placed = t.mesh.vertices;
    smoother.run(options, moving);
    smoother.reembed_tangled(options, moving, &placed);
    smoother.polish(options, moving);
    // Sorted corners of the input's own inverted quads (few; often none).
    std::set<std::array<int, 4>> inverted_input;
    for (std::array<int, 4> c : input.quads) {
      if (bimdf::detail::scaled_jacobian(input, c) >= 0) continue;
      std::sort(c.begin(), c.end());
      inverted_input.insert(c);
    }
    for (int f = 0; f < t.mesh.num_quads(); ++f) {
      const auto& q = t.mesh.quads[f];
      if (bimdf::detail::degenerate(t.mesh, q)) {
        ++outcome.degenerate;
        outcome.degenerate_quads.push_back(f);
        continue;
      }
      if (bimdf::detail::scaled_jacobian(t.mesh, q) >= 0) continue;
      ++outcome.inverted;
      // A quad inverted in the input, repeated at the same corners, is the input's fault: its
      // halves would keep the bad corner (bull's).
      std::array<int, 4> corners;
      for (int a = 0; a < 4; ++a) corners[a] = t.origin[q[a]].mesh_vertex;
      std::sort(corners.begin(), corners.end());
      if (!inverted_input.count(corners)) outcome.to_split.push_back(f);
    }
  }
  result.mesh = std::move(t.mesh);
  return outcome;
}

}  // namespace bimdf::tmesh
