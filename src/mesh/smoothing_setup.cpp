#include "mesh/smoothing_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <unordered_map>
#include <utility>

#include "mesh/feature_subsides.hpp"
#include "mesh/quad_adjacency.hpp"

namespace bimdf::quant {
namespace {

// Two curves meeting at a vertex continue each other when the cosine of their turn there is
// at least this (turning by less than 30°).
const double kStraightCosine = std::cos(std::numbers::pi / 6);

// The cosine of the turn from polyline `in` (ending at a vertex) to `out` (starting there),
// each direction taken over up to 3 segments so that tiny mesh edges do not decide it.
double turning_cosine(const Layout& layout, const std::vector<int>& in,
                      const std::vector<int>& out) {
  const auto& x = layout.mesh.vertices;
  const detail::Vec3 a = detail::normalized(
      detail::sub(x[in.back()], x[in[in.size() - std::min<size_t>(in.size(), 4)]]));
  const detail::Vec3 b =
      detail::normalized(detail::sub(x[out[std::min<size_t>(out.size() - 1, 3)]], x[out.front()]));
  return detail::dot(a, b);
}

}  // namespace

// Per corner of each triangle of `mesh`: the sum of the (area-weighted) normals of the
// triangles of the same chart at that corner's vertex. Charts meet at features and borders,
// where the normal must not be blended across the crease.
std::vector<std::array<detail::Vec3, 3>> chart_corner_normals(const TriangleMesh& mesh,
                                                              const std::vector<int>& face_chart) {
  std::unordered_map<int64_t, detail::Vec3> sum;
  const auto key = [&](int f, int k) {
    const int chart = f < static_cast<int>(face_chart.size()) ? face_chart[f] : -1;
    return (static_cast<int64_t>(mesh.faces[f][k]) << 32) | static_cast<uint32_t>(chart);
  };
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const detail::Vec3 n = detail::triangle_normal(mesh, f);
    for (int k = 0; k < 3; ++k) {
      detail::Vec3& acc = sum[key(f, k)];
      for (int d = 0; d < 3; ++d) acc[d] += n[d];
    }
  }
  std::vector<std::array<detail::Vec3, 3>> normals(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) normals[f][k] = sum[key(f, k)];
  return normals;
}

SurfaceSmoother::Setup::Setup(const Layout& layout, Tessellation& t,
                              const std::vector<std::vector<int>>* vertex_charts)
    : layout(layout), t(t) {
  const QuadMesh& mesh = t.mesh;
  const int nv = mesh.num_vertices();
  const std::vector<char> on_feature = feature_subsides(layout);
  // Border and feature subsides are curves their vertices slide along; so are the joints
  // where two of them continue each other (curve_polylines[s] is subside s's polyline, the
  // joints' follow).
  const int num_subsides = static_cast<int>(layout.subsides.size());
  std::vector<char> subside_free(num_subsides, 0);
  std::vector<std::vector<int>> curve_polylines(num_subsides);
  std::vector<std::vector<int>> curves_ending_at(layout.mesh.num_vertices());
  for (int s = 0; s < num_subsides; ++s) {
    const Subside& sub = layout.subsides[s];
    subside_free[s] = !sub.on_border() && !on_feature[s];
    curve_polylines[s] = sub.vertices;
    if (subside_free[s]) continue;
    curves_ending_at[sub.vertices.front()].push_back(s);
    if (sub.vertices.back() != sub.vertices.front())
      curves_ending_at[sub.vertices.back()].push_back(s);
  }
  // Mesh vertices that stay: feature corners and the other ends of curves. A vertex where
  // exactly two curves meet almost straight is a T-junction or chart corner placed on a
  // feature line, not a corner of it: it slides along the two (joint_curve).
  std::vector<char> pinned(layout.mesh.num_vertices(), 0);
  std::vector<int> joint_curve(layout.mesh.num_vertices(), -1);
  std::vector<char> feature_corner(layout.mesh.num_vertices(), 0);
  for (int v : layout.feature_corners) feature_corner[v] = 1;
  for (int m = 0; m < layout.mesh.num_vertices(); ++m) {
    const std::vector<int>& ends = curves_ending_at[m];
    if (ends.empty() && !feature_corner[m]) continue;
    pinned[m] = 1;
    if (feature_corner[m] || ends.size() != 2) continue;
    // The chain through m: the first curve towards m, then the second away from it.
    std::vector<int> in = curve_polylines[ends[0]], out = curve_polylines[ends[1]];
    if (in.back() != m) std::reverse(in.begin(), in.end());
    if (out.front() != m) std::reverse(out.begin(), out.end());
    if (in.back() != m || out.front() != m || in.size() < 2 || out.size() < 2) continue;
    if (turning_cosine(layout, in, out) < kStraightCosine) continue;
    in.insert(in.end(), out.begin() + 1, out.end());
    pinned[m] = 0;
    joint_curve[m] = static_cast<int>(curve_polylines.size());
    curve_polylines.push_back(std::move(in));
  }
  std::vector<std::set<int>> charts_at(layout.mesh.num_vertices());
  for (int f = 0; f < layout.mesh.num_faces(); ++f)
    for (int v : layout.mesh.faces[f])
      if (layout.face_chart[f] >= 0) charts_at[v].insert(layout.face_chart[f]);
  // The charts each vertex may move on (empty: fixed or on a curve); the curve a vertex
  // slides along (an index into curve_polylines; −1: none).
  std::vector<std::vector<int>> charts(nv);
  std::vector<int> curve(nv, -1);
  for (int v = 0; v < nv; ++v) {
    const VertexOrigin& o = t.origin[v];
    if (o.subside >= 0 && !subside_free[o.subside]) curve[v] = o.subside;
    if (o.chart >= 0) charts[v] = {o.chart};
    if (o.subside >= 0 && subside_free[o.subside]) {
      const Subside& s = layout.subsides[o.subside];
      charts[v] = {s.charts[0], s.charts[1]};
    }
    if (o.mesh_vertex >= 0 && joint_curve[o.mesh_vertex] >= 0)
      curve[v] = joint_curve[o.mesh_vertex];
    else if (o.mesh_vertex >= 0 && !pinned[o.mesh_vertex])
      charts[v].assign(charts_at[o.mesh_vertex].begin(), charts_at[o.mesh_vertex].end());
    if (vertex_charts && !(*vertex_charts)[v].empty())
      charts[v] = (*vertex_charts)[v], curve[v] = -1;
  }
  std::vector<std::vector<std::array<int, 3>>> corners(nv);  // (next, opposite, previous)
  for (const auto& q : mesh.quads)
    for (int a = 0; a < 4; ++a)
      corners[q[a]].push_back({q[(a + 1) % 4], q[(a + 2) % 4], q[(a + 3) % 4]});
  std::vector<std::vector<int>> neighbours(nv);
  for (const auto& q : mesh.quads)
    for (int a = 0; a < 4; ++a) {
      neighbours[q[a]].push_back(q[(a + 1) % 4]);
      neighbours[q[(a + 1) % 4]].push_back(q[a]);
    }
  // Each edge was added once from each of its (at most two) quads: the mean is unaffected
  // for interior edges, and boundary vertices are fixed anyway.
  std::vector<std::vector<int>> vertex_quads = bimdf::detail::quads_at_vertices(mesh);
  this->curve_polylines = std::move(curve_polylines);
  this->charts = std::move(charts);
  this->curve = std::move(curve);
  this->corners = std::move(corners);
  this->neighbours = std::move(neighbours);
  this->vertex_quads = std::move(vertex_quads);
  trees.resize(layout.charts.size());
}

}  // namespace bimdf::quant
