// Sharp edges and feature corners (features.hpp).
#include <algorithm>
#include <cmath>
#include <map>

#include "bimdf/error.hpp"
#include "layout/feature_flags.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::layout {
namespace {

using detail::Vec3;

// The edge between a and b as a half-edge of `top`, or −1.
int find_half_edge(const SurfaceTopology& top, int a, int b) {
  for (int h : top.outgoing(a))
    if (top.to(h) == b) return h;
  // At a border vertex the last edge of the fan is only reachable as an incoming half-edge.
  for (int h : top.outgoing(b))
    if (top.to(h) == a) return h;
  return -1;
}

// Corners: vertices where the curve edges (flagged) end, meet or turn by more than the angle.
std::vector<int> find_corners(const SurfaceTopology& top, const std::vector<bool>& curve,
                              double corner_angle_deg) {
  const TriangleMesh& m = top.mesh();
  std::vector<std::vector<int>> curve_neighbours(m.num_vertices());
  for (int e = 0; e < top.num_edges(); ++e) {
    if (!curve[e]) continue;
    const int h = top.edge_half_edge(e);
    curve_neighbours[top.from(h)].push_back(top.to(h));
    curve_neighbours[top.to(h)].push_back(top.from(h));
  }
  const double limit = std::cos(corner_angle_deg * M_PI / 180);
  std::vector<int> corners;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const auto& n = curve_neighbours[v];
    if (n.empty()) continue;
    bool corner = n.size() != 2;
    if (!corner) {
      const Vec3 in = detail::normalized(detail::sub(m.vertices[v], m.vertices[n[0]]));
      const Vec3 out = detail::normalized(detail::sub(m.vertices[n[1]], m.vertices[v]));
      corner = detail::dot(in, out) < limit;
    }
    if (corner) corners.push_back(v);
  }
  return corners;
}

Features finish(const SurfaceTopology& top, std::vector<bool> sharp,
                const FeatureOptions& options) {
  Features f;
  std::vector<bool> curve = sharp;
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e);
    if (top.opposite(h) < 0) {
      curve[e] = true;
      ++f.border_edges;
    } else if (sharp[e]) {
      f.sharp_edges.push_back({std::min(top.from(h), top.to(h)), std::max(top.from(h), top.to(h))});
    }
  }
  std::sort(f.sharp_edges.begin(), f.sharp_edges.end());
  f.corners = find_corners(top, curve, options.corner_angle_deg);
  return f;
}

// Erodes sharp edges with a dangling end `steps` times, then grows them back as many times
// along the originally sharp edges that touch the remaining curves or the border.
std::vector<bool> erode_dilate(const SurfaceTopology& top, const std::vector<bool>& sharp,
                               int steps) {
  const int E = top.num_edges(), V = top.mesh().num_vertices();
  const auto ends = [&](int e) {
    const int h = top.edge_half_edge(e);
    return std::array<int, 2>{top.from(h), top.to(h)};
  };
  std::vector<bool> border(E), kept = sharp;
  for (int e = 0; e < E; ++e) border[e] = top.opposite(top.edge_half_edge(e)) < 0;
  std::vector<int> degree(V);
  const auto count_degrees = [&] {
    std::fill(degree.begin(), degree.end(), 0);
    for (int e = 0; e < E; ++e)
      if (kept[e] || border[e])
        for (int v : ends(e)) ++degree[v];
  };
  for (int s = 0; s < steps; ++s) {
    count_degrees();
    for (int e = 0; e < E; ++e)
      if (kept[e] && (degree[ends(e)[0]] == 1 || degree[ends(e)[1]] == 1)) kept[e] = false;
  }
  for (int s = 0; s < steps; ++s) {
    count_degrees();
    for (int e = 0; e < E; ++e)
      if (sharp[e] && !kept[e] && (degree[ends(e)[0]] > 0 || degree[ends(e)[1]] > 0))
        kept[e] = true;
  }
  return kept;
}

}  // namespace

std::vector<bool> feature_edge_flags(const SurfaceTopology& top, const Features& features) {
  std::vector<bool> flag(top.num_edges(), false);
  for (int e = 0; e < top.num_edges(); ++e) flag[e] = top.opposite(top.edge_half_edge(e)) < 0;
  for (const auto& [a, b] : features.sharp_edges) {
    const int h = find_half_edge(top, a, b);
    if (h >= 0) flag[top.edge(h)] = true;
  }
  return flag;
}

Features detect_features(const TriangleMesh& mesh, const FeatureOptions& options) {
  const SurfaceTopology top(mesh);
  const double limit = std::cos(options.sharp_angle_deg * M_PI / 180);
  std::vector<bool> sharp(top.num_edges(), false);
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e), g = top.opposite(h);
    if (g < 0 || options.sharp_angle_deg >= 180) continue;
    const Vec3 a = detail::normalized(detail::triangle_normal(mesh, h / 3));
    const Vec3 b = detail::normalized(detail::triangle_normal(mesh, g / 3));
    sharp[e] = detail::dot(a, b) < limit;
  }
  return finish(top, erode_dilate(top, sharp, options.erode_dilate), options);
}

Features features_from_edges(const TriangleMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                             const FeatureOptions& options, const std::string& source) {
  const SurfaceTopology top(mesh);
  std::vector<bool> sharp(top.num_edges(), false);
  for (const auto& [a, b] : edges) {
    const int h = a >= 0 && b >= 0 && a < mesh.num_vertices() && b < mesh.num_vertices()
                      ? find_half_edge(top, a, b)
                      : -1;
    if (h < 0)
      throw InputError(source, "",
                       "feature edge " + std::to_string(a) + "-" + std::to_string(b) +
                           " is not an edge of the mesh");
    sharp[top.edge(h)] = true;
  }
  return finish(top, std::move(sharp), options);
}

}  // namespace bimdf::layout
