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

// Drops one side of every lens the curves leave: a small region bounded by curves alone
// whose boundary has fewer than 3 sharp turns (a scan's crease that forks and joins again, a
// chamfer seen as two creases meeting at shallow angles). A patch there would need 3 corners it
// does not have: the layout would force one onto a straight curve, a valence-2 vertex in the
// quad mesh, and its two cusps would pinch quads flat. Of the boundary's pieces between curve
// junctions the one bending least (mean dihedral angle; border edges stay) is dropped, and the
// regions are looked at again.
std::vector<bool> drop_lens_branches(const SurfaceTopology& top, std::vector<bool> sharp,
                                     int max_faces) {
  const TriangleMesh& m = top.mesh();
  const int F = m.num_faces(), V = m.num_vertices(), E = top.num_edges();
  std::vector<double> total(V, 0);
  for (int h = 0; h < 3 * F; ++h) total[top.from(h)] += top.corner_angle(h);
  const auto border = [&](int e) { return top.opposite(top.edge_half_edge(e)) < 0; };
  const auto dihedral = [&](int e) {
    const int h = top.edge_half_edge(e), g = top.opposite(h);
    return std::acos(std::clamp(detail::dot(detail::normalized(detail::triangle_normal(m, h / 3)),
                                            detail::normalized(detail::triangle_normal(m, g / 3))),
                                -1.0, 1.0));
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<int> degree(V, 0);
    for (int e = 0; e < E; ++e)
      if (sharp[e] || border(e)) {
        const int h = top.edge_half_edge(e);
        ++degree[top.from(h)], ++degree[top.to(h)];
      }
    // One pass looks at every region once; a region beside one that lost a piece has changed
    // (`touched`) and waits for the next pass.
    std::vector<int> region(F, -1);
    std::vector<char> touched(F, 0);
    for (int f0 = 0; f0 < F; ++f0) {
      if (region[f0] >= 0) continue;
      std::vector<int> faces{f0};
      region[f0] = f0;
      bool waits = false;
      for (size_t i = 0; i < faces.size(); ++i) {
        waits |= touched[faces[i]];
        for (int k = 0; k < 3; ++k) {
          const int h = 3 * faces[i] + k, g = top.opposite(h);
          if (g < 0 || sharp[top.edge(h)] || region[g / 3] >= 0) continue;
          region[g / 3] = f0;
          faces.push_back(g / 3);
        }
      }
      if (waits || faces.size() > static_cast<size_t>(max_faces)) continue;
      // Its boundary as one loop of half-edges (next boundary half-edge from each vertex).
      std::map<int, int> next_from;
      std::map<int, double> sector;
      bool disk = true;
      for (int f : faces)
        for (int k = 0; k < 3; ++k) {
          const int h = 3 * f + k, g = top.opposite(h);
          sector[top.from(h)] += top.corner_angle(h);
          if (g >= 0 && region[g / 3] == f0) continue;
          disk &= next_from.emplace(top.from(h), h).second;
        }
      if (!disk || next_from.empty()) continue;
      std::vector<int> loop{next_from.begin()->second};
      while (loop.size() <= next_from.size()) {
        const auto it = next_from.find(top.to(loop.back()));
        if (it == next_from.end() || it->second == loop.front()) break;
        loop.push_back(it->second);
      }
      if (loop.size() != next_from.size()) continue;  // several boundary loops
      // Its turns, in quarters as the surface's angles count them (the field is not known yet).
      std::vector<char> ends(loop.size(), 0);  // where the pieces to choose from begin
      std::vector<char> turn(loop.size(), 0);
      int turns = 0, junctions = 0;
      bool cusp = false;
      for (size_t i = 0; i < loop.size(); ++i) {
        const int v = top.from(loop[i]);
        const double quarters = sector[v] / total[v] * (top.on_border(v) ? 2 : 4);
        turns += turn[i] = quarters < 1.5;
        cusp |= quarters < 0.5;
        junctions += ends[i] = degree[v] >= 3;
      }
      // Without a junction, a closed curve: a lens if it pinches (a round cap keeps its rim; its
      // field has a singularity inside whose traces cut it), and then cut at its turns.
      if (turns >= 3 || (junctions == 0 && !cusp)) continue;
      if (junctions == 0) ends = turn;
      const auto first = std::find(ends.begin(), ends.end(), 1) - ends.begin();
      if (first == static_cast<std::ptrdiff_t>(ends.size())) continue;
      std::rotate(ends.begin(), ends.begin() + first, ends.end());
      std::rotate(loop.begin(), loop.begin() + first, loop.end());
      int best_begin = -1, best_end = -1;
      double best_bend = 0;
      for (size_t begin = 0; begin < loop.size();) {
        size_t end = begin + 1;
        while (end < loop.size() && !ends[end]) ++end;
        bool on_border = false;
        double bend = 0;
        for (size_t i = begin; i < end; ++i) {
          const int e = top.edge(loop[i]);
          on_border |= border(e);
          if (!on_border) bend += dihedral(e);
        }
        bend /= static_cast<double>(end - begin);
        if (!on_border && (best_begin < 0 || bend < best_bend))
          best_begin = static_cast<int>(begin), best_end = static_cast<int>(end), best_bend = bend;
        begin = end;
      }
      if (best_begin < 0) continue;
      for (int i = best_begin; i < best_end; ++i) {
        sharp[top.edge(loop[i])] = false;
        touched[top.opposite(loop[i]) / 3] = 1;
      }
      changed = true;
    }
  }
  return sharp;
}

}  // namespace

std::vector<bool> clean_sharp_edges(const SurfaceTopology& top, std::vector<bool> sharp,
                                    int steps) {
  if (steps <= 0) return sharp;
  return drop_lens_branches(
      top, erode_dilate(top, drop_spiky_triangles(top, std::move(sharp)), steps), 16 * steps);
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
