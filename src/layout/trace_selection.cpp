// Which traced separatrices a layout keeps (trace_selection.hpp).
#include "layout/trace_selection.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>

#include "layout/surface_point.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::layout {
namespace {

bool is_seed(const std::vector<int>& seeds, int v) {
  return std::find(seeds.begin(), seeds.end(), v) != seeds.end();
}

}  // namespace

int drop_dangling(std::vector<Trace>& traces) {
  std::vector<bool> removed(traces.size(), false);
  bool changed = true;
  while (changed) {
    changed = false;
    for (size_t i = 0; i < traces.size(); ++i) {
      if (removed[i]) continue;
      const Trace& t = traces[i];
      // A trace that ends at a singularity keeps its end, whatever becomes of the trace that
      // passed there first; one that ends on a trace loses it with that trace.
      const bool dangling =
          t.end == Trace::End::Unfinished ||
          (t.end == Trace::End::Trace && t.end_trace >= 0 && removed[t.end_trace]) ||
          t.points.size() < 2;
      if (dangling) removed[i] = changed = true;
    }
  }
  int n = 0;
  std::vector<Trace> kept;
  for (size_t i = 0; i < traces.size(); ++i)
    if (removed[i])
      ++n;
    else
      kept.push_back(std::move(traces[i]));
  traces = std::move(kept);
  return n;
}

void ban_shallow_ends(const std::vector<Trace>& traces, double on_trace, double on_curve,
                      const std::vector<int>& seeds, std::vector<std::array<int, 2>>& banned) {
  for (const Trace& t : traces) {
    const double shallow = t.end == Trace::End::Trace   ? on_trace
                           : t.end == Trace::End::Curve ? on_curve
                                                        : 0;
    if (t.end_angle < shallow && (t.end == Trace::End::Curve || !is_seed(seeds, t.start_vertex)))
      banned.push_back({t.start_vertex, t.start_way});
  }
}

void ban_short_to_curve(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                        const std::vector<int>& seeds, double short_length,
                        std::vector<std::array<int, 2>>& banned) {
  if (short_length <= 0) return;
  std::map<int, std::map<int, const Trace*>> short_ones;  // start vertex → way → trace
  for (const Trace& t : traces)
    if (t.end == Trace::End::Curve && t.length < short_length && !curve_vertex[t.start_vertex] &&
        !is_seed(seeds, t.start_vertex))
      short_ones[t.start_vertex][t.start_way] = &t;
  for (const auto& [v, ways] : short_ones) {
    if (ways.size() < 2) continue;
    const int n = ways.begin()->second->start_ways;
    // Walk each run from its first way (one whose predecessor is not short), or from any way
    // when all of them are short.
    std::set<int> done;
    for (const auto& [first, unused] : ways) {
      if (done.count(first) || (ways.count((first + n - 1) % n) && ways.size() < size_t(n)))
        continue;
      std::vector<const Trace*> run;
      for (int w = first; ways.count(w) && !done.count(w); w = (w + 1) % n) {
        done.insert(w);
        run.push_back(ways.at(w));
      }
      if (run.size() < 2) continue;
      const Trace* keep =
          *std::min_element(run.begin(), run.end(),
                            [](const Trace* a, const Trace* b) { return a->length < b->length; });
      for (const Trace* t : run)
        if (t != keep) banned.push_back({v, t->start_way});
    }
  }
}

void ban_seed_loops(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                    const std::vector<int>& seeds, double short_length,
                    std::vector<std::array<int, 2>>& banned) {
  std::map<int, std::array<const Trace*, 4>> of_seed;
  for (const Trace& t : traces)
    if (t.start_ways == 4 && !curve_vertex[t.start_vertex] && is_seed(seeds, t.start_vertex))
      of_seed[t.start_vertex][t.start_way] = &t;
  for (const auto& [v, ways] : of_seed)
    for (int w = 0; w < 2; ++w) {
      const Trace *a = ways[w], *b = ways[w + 2];
      if (a && b && a->end == Trace::End::Curve && b->end == Trace::End::Curve &&
          a->length < short_length && b->length < short_length) {
        for (int other : {w + 1, (w + 3) % 4})
          if (ways[other]) banned.push_back({v, other});
        break;
      }
    }
}

std::vector<double> distance_to_curves(const SurfaceTopology& top,
                                       const std::vector<bool>& curve_vertex) {
  const TriangleMesh& m = top.mesh();
  std::vector<double> dist(m.num_vertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int v = 0; v < m.num_vertices(); ++v)
    if (curve_vertex[v]) dist[v] = 0, queue.push({0.0, v});
  while (!queue.empty()) {
    const auto [du, u] = queue.top();
    queue.pop();
    if (du > dist[u]) continue;
    for (int h : top.outgoing(u)) {
      const int w = top.to(h);
      const double d = du + detail::norm(detail::sub(m.vertices[u], m.vertices[w]));
      if (d < dist[w]) dist[w] = d, queue.push({d, w});
    }
  }
  return dist;
}

namespace {

// A point's distance to the curves, interpolated from its edge's or face's vertices.
double distance_at(const SurfaceTopology& top, const SurfacePoint& p,
                   const std::vector<double>& to_curve) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      return to_curve[p.id];
    case SurfacePoint::Kind::Edge: {
      const int h = top.edge_half_edge(p.id);
      return (1 - p.t) * to_curve[top.from(h)] + p.t * to_curve[top.to(h)];
    }
    default: {
      const auto& f = top.mesh().faces[p.id];
      return p.bary[0] * to_curve[f[0]] + p.bary[1] * to_curve[f[1]] + p.bary[2] * to_curve[f[2]];
    }
  }
}

}  // namespace

void ban_along_curves(const SurfaceTopology& top, const std::vector<Trace>& traces,
                      const std::vector<double>& to_curve, const std::vector<int>& seeds,
                      double near, double along, std::vector<std::array<int, 2>>& banned) {
  for (const Trace& t : traces) {
    if (is_seed(seeds, t.start_vertex)) continue;
    double beside = 0;
    for (size_t i = 1; i < t.points.size(); ++i)
      if (distance_at(top, t.points[i - 1], to_curve) < near &&
          distance_at(top, t.points[i], to_curve) < near)
        beside +=
            detail::norm(detail::sub(position(top, t.points[i]), position(top, t.points[i - 1])));
    if (beside > along) banned.push_back({t.start_vertex, t.start_way});
  }
}

}  // namespace bimdf::layout
