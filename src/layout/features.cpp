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

// Drops the sharp edges of every triangle whose three edges are all sharp: a lone spike or dent
// (a scan's noise, a fold of the triangulation), which no curve passes through; left in, its
// three edges are a closed loop that erosion cannot shrink and whose corners become patch
// corners.
std::vector<bool> drop_spiky_triangles(const SurfaceTopology& top, std::vector<bool> sharp) {
  std::vector<bool> dropped(top.num_edges(), false);
  for (int f = 0; f < top.mesh().num_faces(); ++f) {
    const int e0 = top.edge(3 * f), e1 = top.edge(3 * f + 1), e2 = top.edge(3 * f + 2);
    if (sharp[e0] && sharp[e1] && sharp[e2]) dropped[e0] = dropped[e1] = dropped[e2] = true;
  }
  for (int e = 0; e < top.num_edges(); ++e)
    if (dropped[e]) sharp[e] = false;
  return sharp;
}

// Drops every connected set of sharp edges that has fewer than `min_edges` edges and does not
// touch the border. Erosion removes short open curves but cannot shrink a closed or branched
// one: a small loop, or a loop with a chord, around a bump of a scan. Left in, it becomes a
// tiny ring of patches that no separatrix may cut open.
std::vector<bool> drop_small_components(const SurfaceTopology& top, std::vector<bool> sharp,
                                        const std::vector<bool>& border, int min_edges) {
  const int E = top.num_edges(), V = top.mesh().num_vertices();
  std::vector<std::vector<int>> at(V);
  std::vector<bool> on_border(V, false);
  for (int e = 0; e < E; ++e) {
    const int h = top.edge_half_edge(e);
    for (int v : {top.from(h), top.to(h)}) {
      if (sharp[e]) at[v].push_back(e);
      if (border[e]) on_border[v] = true;
    }
  }
  std::vector<char> seen(E, 0);
  for (int start = 0; start < E; ++start) {
    if (!sharp[start] || seen[start]) continue;
    std::vector<int> component{start};
    seen[start] = 1;
    bool touches_border = false;
    for (size_t i = 0; i < component.size(); ++i) {
      const int h = top.edge_half_edge(component[i]);
      for (int v : {top.from(h), top.to(h)}) {
        touches_border = touches_border || on_border[v];
        for (int e : at[v])
          if (!seen[e]) seen[e] = 1, component.push_back(e);
      }
    }
    if (!touches_border && static_cast<int>(component.size()) < min_edges)
      for (int e : component) sharp[e] = false;
  }
  return sharp;
}

// Erodes sharp edges with a dangling end `steps` times, then grows the curves back as many
// times from the ends that erosion made: each step adds the originally sharp edges at the
// growth front (at first the dangling ends of what is left; then the far ends of the edges
// just added). Growing back only from ends restores the long curves' full length without
// restoring the short spurs that branch off them at a junction (a crease in a scan is a
// zigzag of triangle edges with such spurs, and each spur would end in a patch corner).
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
  count_degrees();
  std::vector<char> front(V, 0), next(V, 0);
  for (int v = 0; v < V; ++v) front[v] = degree[v] == 1;
  for (int s = 0; s < steps; ++s) {
    std::fill(next.begin(), next.end(), 0);
    for (int e = 0; e < E; ++e) {
      if (!sharp[e] || kept[e]) continue;
      const auto [a, b] = ends(e);
      if (!front[a] && !front[b]) continue;
      kept[e] = true;
      next[front[a] ? b : a] = 1;
    }
    front.swap(next);
  }
  return drop_small_components(top, std::move(kept), border, 2 * steps + 1);
}

}  // namespace

std::vector<bool> clean_sharp_edges(const SurfaceTopology& top, std::vector<bool> sharp,
                                    int steps) {
  if (steps <= 0) return sharp;
  return erode_dilate(top, drop_spiky_triangles(top, std::move(sharp)), steps);
}

std::vector<bool> feature_edge_flags(const SurfaceTopology& top, const Features& features) {
  std::vector<bool> flag(top.num_edges(), false);
  for (int e = 0; e < top.num_edges(); ++e) flag[e] = top.opposite(top.edge_half_edge(e)) < 0;
  for (const auto& [a, b] : features.sharp_edges) {
    const int h = find_half_edge(top, a, b);
    if (h >= 0) flag[top.edge(h)] = true;
  }
  return flag;
}

std::vector<bool> vertices_of_edges(const SurfaceTopology& top,
                                    const std::vector<bool>& edge_flag) {
  std::vector<bool> on(top.mesh().num_vertices(), false);
  for (int e = 0; e < top.num_edges(); ++e)
    if (edge_flag[e]) {
      const int h = top.edge_half_edge(e);
      on[top.from(h)] = on[top.to(h)] = true;
    }
  return on;
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
  return finish(top, clean_sharp_edges(top, std::move(sharp), options.erode_dilate), options);
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
