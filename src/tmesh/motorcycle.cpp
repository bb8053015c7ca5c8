#include "tmesh/motorcycle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bimdf/error.hpp"

namespace bimdf::tmesh::detail {
namespace {

using Vec = std::array<double, 3>;

// Newell's normal: robust for non-planar quads, zero for a degenerate one.
Vec quad_normal(const QuadMesh& mesh, int f) {
  Vec n{0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const Vec& a = mesh.vertices[mesh.quads[f][k]];
    const Vec& b = mesh.vertices[mesh.quads[f][(k + 1) % 4]];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

// The angle between two normals in degrees (atan2 stays accurate near 0° and 180°); −1 when
// either is zero, so that a degenerate quad never makes a sharp edge.
double angle_deg(const Vec& a, const Vec& b) {
  const Vec c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double sin_part = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double cos_part = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if (!(na > 0) || !(nb > 0)) return -1;
  return std::atan2(sin_part, cos_part) * 180 / std::numbers::pi;
}

bool on_feature(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge, int v) {
  for (int e : topo.vertex_edges(v))
    if (feature_edge[e]) return true;
  return false;
}

// Traces leave a seed along each of its edges that is neither border nor feature, in ring
// order: the same order for both graphs, so that trace i is the same in each.
template <class Emit>
void emit_traces(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge,
                 const std::vector<int>& seeds, Emit emit) {
  for (int s : seeds)
    for (int e : topo.vertex_edges(s))
      if (!topo.is_border_edge(e) && !feature_edge[e]) emit(s, e);
}

}  // namespace

std::vector<uint8_t> detect_feature_edges(const QuadMesh& mesh, const QuadMeshTopology& topo,
                                          double sharp_angle_deg,
                                          const std::vector<std::array<int, 2>>& given,
                                          const std::string& source) {
  std::vector<uint8_t> feature(topo.num_edges(), 0);
  if (sharp_angle_deg < 180) {
    std::vector<Vec> normal(topo.num_faces());
    for (int f = 0; f < topo.num_faces(); ++f) normal[f] = quad_normal(mesh, f);
    for (int e = 0; e < topo.num_edges(); ++e) {
      const auto [h0, h1] = topo.edge_half_edges(e);
      if (h1 < 0) continue;
      const double a =
          angle_deg(normal[QuadMeshTopology::face(h0)], normal[QuadMeshTopology::face(h1)]);
      if (a > sharp_angle_deg) feature[e] = 1;
    }
  }
  for (size_t i = 0; i < given.size(); ++i) {
    const auto [a, b] = given[i];
    const int e = topo.find_edge(a, b);
    if (e < 0)
      throw InputError(source, "",
                       "feature edge " + std::to_string(i) + " (" + std::to_string(a) + ", " +
                           std::to_string(b) + ") is not an edge of the mesh");
    feature[e] = 1;
  }
  return feature;
}

std::vector<int> feature_corners(const QuadMeshTopology& topo,
                                 const std::vector<uint8_t>& feature_edge) {
  std::vector<int> corners;
  for (int v = 0; v < topo.num_vertices(); ++v) {
    int count = 0, first = -1, second = -1;
    for (int e : topo.vertex_edges(v))
      if (feature_edge[e]) {
        (count == 0 ? first : second) = e;
        ++count;
      }
    if (count == 0) continue;
    if (count == 2 && topo.straight_on(v, first) == second) continue;
    corners.push_back(v);
  }
  return corners;
}

std::vector<int> seed_vertices(const QuadMeshTopology& topo,
                               const std::vector<uint8_t>& feature_edge) {
  const std::vector<int> corners = feature_corners(topo, feature_edge);
  std::vector<int> seeds;
  size_t c = 0;
  for (int v = 0; v < topo.num_vertices(); ++v) {
    while (c < corners.size() && corners[c] < v) ++c;
    const bool corner = c < corners.size() && corners[c] == v;
    if (topo.is_used(v) && (!topo.is_regular(v) || corner)) seeds.push_back(v);
  }
  return seeds;
}

MotorcycleGraph trace_motorcycle_graph(const QuadMeshTopology& topo,
                                       const std::vector<uint8_t>& feature_edge,
                                       const std::vector<int>& seeds) {
  MotorcycleGraph g;
  const int E = topo.num_edges(), V = topo.num_vertices();
  g.cut.assign(E, 0);
  g.edge_trace.assign(E, -1);
  std::vector<uint8_t> marked(V, 0);
  for (int e = 0; e < E; ++e)
    if (topo.is_border_edge(e) || feature_edge[e]) {
      g.cut[e] = 1;
      const auto [a, b] = topo.edge_vertices(e);
      marked[a] = marked[b] = 1;
    }
  for (int s : seeds) marked[s] = 1;

  struct Head {
    int trace, at, edge;  // the trace's current vertex and the edge it takes next
  };
  std::vector<Head> heads, next_heads;
  emit_traces(topo, feature_edge, seeds, [&](int s, int e) {
    heads.push_back({static_cast<int>(g.traces.size()), s, e});
    g.traces.push_back({s, {s}, {}});
  });
  while (!heads.empty()) {
    next_heads.clear();
    for (const Head& h : heads) {
      if (g.cut[h.edge]) continue;  // met head-on by a trace that took this edge first
      g.cut[h.edge] = 1;
      g.edge_trace[h.edge] = h.trace;
      const int w = topo.other_vertex(h.edge, h.at);
      Trace& t = g.traces[h.trace];
      t.vertices.push_back(w);
      t.edges.push_back(h.edge);
      if (marked[w]) continue;
      marked[w] = 1;
      next_heads.push_back({h.trace, w, topo.straight_on(w, h.edge)});
    }
    std::swap(heads, next_heads);
  }
  return g;
}

std::vector<Trace> trace_extended_motorcycle_graph(const QuadMeshTopology& topo,
                                                   const std::vector<uint8_t>& feature_edge,
                                                   const std::vector<int>& seeds,
                                                   bool cross_features) {
  const int V = topo.num_vertices();
  std::vector<uint8_t> stop(V, 0);
  for (int v = 0; v < V; ++v)
    stop[v] = topo.is_border_vertex(v) || (!cross_features && on_feature(topo, feature_edge, v));
  for (int s : seeds) stop[s] = 1;
  // Directed edge 2e (from edge_vertices(e)[0]) or 2e + 1, stamped with the last trace that
  // took it: one array for all traces, no clearing between them.
  std::vector<int> taken(2 * size_t(topo.num_edges()), -1);
  std::vector<Trace> traces;
  emit_traces(topo, feature_edge, seeds, [&](int s, int e) {
    const int id = static_cast<int>(traces.size());
    Trace t{s, {s}, {}};
    int at = s;
    while (true) {
      const int directed = 2 * e + (topo.edge_vertices(e)[0] == at ? 0 : 1);
      if (taken[directed] == id) break;
      taken[directed] = id;
      at = topo.other_vertex(e, at);
      t.vertices.push_back(at);
      t.edges.push_back(e);
      if (stop[at]) break;
      e = topo.straight_on(at, e);
      if (e < 0 || feature_edge[e]) break;  // not straight across a curve: ends on it
    }
    traces.push_back(std::move(t));
  });
  return traces;
}

CompletionCuts complete_to_rectangles(const QuadMeshTopology& topo, std::vector<uint8_t>& cut,
                                      const std::string& source) {
  CompletionCuts out;
  auto has_cut_edge = [&](int v) {
    for (int e : topo.vertex_edges(v))
      if (cut[e]) return true;
    return false;
  };
  // Straight on from `at` along e to the first vertex with a cut edge (or back to `at`),
  // cutting the edges passed when `mark`.
  auto walk = [&](int at, int e, bool mark) {
    std::vector<int> line{at};
    while (true) {
      if (line.size() > size_t(topo.num_edges()))  // a straight line never repeats an edge
        throw std::logic_error("complete_to_rectangles: a cut runs on forever");
      at = topo.other_vertex(e, at);
      line.push_back(at);
      const bool reached = at == line.front() || has_cut_edge(at);
      if (mark) cut[e] = 1;
      if (reached) return line;
      e = topo.straight_on(at, e);
    }
  };
  auto cut_line = [&](const std::vector<int>& line) {
    for (size_t i = 0; i + 1 < line.size(); ++i) cut[topo.find_edge(line[i], line[i + 1])] = 1;
    out.traces.push_back(line);
  };
  RegionScratch scratch(topo);
  for (bool changed = true; changed;) {
    changed = false;
    for (const std::vector<int>& faces : cut_regions(topo, cut)) {
      ++scratch.stamp;
      const RegionBorder b = region_border(topo, cut, faces, scratch);
      if (b.loops.size() == 1 && b.corners == 4 && b.reflex == 0) {
        const RegionRectangle r = region_rectangle(topo, cut, faces, b, scratch, source);
        if (r.repeat[0] < 0) continue;
        // Cut along the grid line between the two positions (they are never neighbours).
        const int w1 = r.width + 1;
        const int i1 = r.repeat[0] % w1, j1 = r.repeat[0] / w1;
        const int i2 = r.repeat[1] % w1, j2 = r.repeat[1] / w1;
        std::vector<int> line;
        if (std::abs(i1 - i2) >= 2) {
          for (int j = 0; j <= r.height; ++j) line.push_back(r.vertices[j * w1 + (i1 + i2) / 2]);
        } else {
          for (int i = 0; i <= r.width; ++i) line.push_back(r.vertices[(j1 + j2) / 2 * w1 + i]);
        }
        cut_line(line);
        changed = true;
        continue;
      }
      if (b.loops.size() < 2 || b.corners != 0 || b.reflex != 0) continue;
      // An annulus: its curves are parallel grid lines, so the grid line leaving one of them
      // across the region (the edge between the region's two quads at a border vertex)
      // reaches the other.
      std::vector<int> loop = b.loops[0];
      const size_t L = loop.size(), half = L / 2;
      std::rotate(loop.begin(),
                  std::min_element(loop.begin(), loop.end(),
                                   [&](int x, int y) { return topo.tail(x) < topo.tail(y); }),
                  loop.end());
      auto across = [&](size_t i) {
        return topo.edge(QuadMeshTopology::next(loop[(i + L - 1) % L]));
      };
      bool shared = false;
      for (int h : loop) scratch.vertex[topo.tail(h)] = scratch.stamp;
      for (size_t k = 1; k < b.loops.size(); ++k)
        for (int h : b.loops[k]) shared |= scratch.vertex[topo.tail(h)] == scratch.stamp;
      if (shared) {
        const std::vector<int> line = walk(topo.tail(loop[0]), across(0), false);
        if (line.size() < 3) continue;  // one quad across: the rectangle check reports it
        const size_t m = (line.size() - 1) / 2;
        const int mid = line[m], in = topo.find_edge(line[m - 1], mid);
        const auto ring = topo.vertex_edges(mid);
        const size_t i = std::find(ring.begin(), ring.end(), in) - ring.begin();
        walk(mid, ring[(i + 1) % 4], true);
      } else {
        // Two cuts, so that no arc closes on a single T-mesh vertex.
        out.traces.push_back(walk(topo.tail(loop[0]), across(0), true));
        out.traces.push_back(walk(topo.tail(loop[half]), across(half), true));
        std::vector<int> half_loop;
        for (size_t i = 0; i <= half; ++i) half_loop.push_back(topo.tail(loop[i % L]));
        out.half_loops.push_back(std::move(half_loop));
      }
      changed = true;
    }
  }
  return out;
}

}  // namespace bimdf::tmesh::detail
