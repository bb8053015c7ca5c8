#include "tmesh/angle_bounded.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace bimdf::tmesh::detail {
namespace {

// Integer length ratios that differ from tan α by less than this (relative) count as equal to
// it, so that 45° admits l_ji = l_ij although tan(45°) rounds below 1. Distinct ratios of
// lengths below 10^5 differ by far more.
constexpr double kRatioTolerance = 1e-12;

// Traces a and b meet at a vertex, a after pa edges from its seed and b after pb.
struct Crossing {
  int a, pa, b, pb;
};

int ring_index(const QuadMeshTopology& topo, int v, int e) {
  const auto ring = topo.vertex_edges(v);
  return static_cast<int>(std::find(ring.begin(), ring.end(), e) - ring.begin());
}

// Directed edge 2e (from edge_vertices(e)[0]) or 2e + 1.
int directed(const QuadMeshTopology& topo, int e, int from) {
  return 2 * e + (topo.edge_vertices(e)[0] == from ? 0 : 1);
}

bool is_curve(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge, int e) {
  return topo.is_border_edge(e) || feature_edge[e];
}

class Tracer {
 public:
  Tracer(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge,
         const std::vector<int>& seeds, double max_angle_deg, AngleBoundedGraph& g)
      : topo_(topo),
        g_(g),
        angle_rule_(max_angle_deg < 90),
        tan_alpha_(angle_rule_ ? std::tan(max_angle_deg * std::numbers::pi / 180) : 0),
        stop_(topo.num_vertices(), 0),
        slot_trace_(4 * size_t(topo.num_vertices()), -1),
        slot_pos_(4 * size_t(topo.num_vertices()), -1),
        taken_(2 * size_t(topo.num_edges()), 0) {
    for (int e = 0; e < topo.num_edges(); ++e)
      if (is_curve(topo, feature_edge, e)) {
        g.cut[e] = 1;
        const auto [a, b] = topo.edge_vertices(e);
        stop_[a] = stop_[b] = 1;
      }
    for (int v = 0; v < topo.num_vertices(); ++v) stop_[v] |= topo.is_border_vertex(v);
    for (int s : seeds) stop_[s] = 1;
    for (int s : seeds)
      for (int e : topo.vertex_edges(s))
        if (!is_curve(topo, feature_edge, e)) {
          heads_.push_back({static_cast<int>(g.traces.size()), s, e, false});
          g.traces.push_back({s, {s}, {}});
        }
    const size_t T = g.traces.size();
    left_ok_.assign(T, 0);
    right_ok_.assign(T, 0);
    done_.assign(T, 0);
    head_step_.assign(T, -1);
  }

  void run() {
    for (int step = 1; !heads_.empty(); ++step) {
      move_all(step);
      for (const Moved& m : moved_) record_crossings(m);
      decide(step);
    }
  }

  // (1) and (2): per trace, how many of its edges its non-zero path takes.
  std::vector<int> path_lengths() const {
    std::vector<int> len(g_.traces.size());
    for (size_t t = 0; t < len.size(); ++t) len[t] = static_cast<int>(g_.traces[t].edges.size());
    auto at_most = [&](int t, int p) { len[t] = std::min(len[t], p); };
    for (const Crossing& c : crossings_) {
      if (c.pb < c.pa) at_most(c.a, c.pa);
      if (c.pa < c.pb) at_most(c.b, c.pb);
      if (!angle_rule_) continue;
      if (!within_angle(c.pb, c.pa)) at_most(c.b, c.pb);
      if (!within_angle(c.pa, c.pb)) at_most(c.a, c.pa);
    }
    return len;
  }

  int num_crossings() const { return static_cast<int>(crossings_.size()); }

 private:
  struct Head {
    int trace, at, edge;  // the edge it takes next from `at`
    bool finishing;       // done, running on to a vertex a cut line passes through
  };
  struct Moved {
    int trace, at, next_edge, slot;
    bool finishing;
  };

  // |α| ≤ α_max for a seed `across` edges to the side of a trace `along` edges from its seed.
  bool within_angle(int across, int along) const {
    return across <= tan_alpha_ * along * (1 + kRatioTolerance);
  }

  void move_all(int step) {
    moved_.clear();
    for (const Head& h : heads_) {
      const int d = directed(topo_, h.edge, h.at);
      // A taken directed edge leaves h.at: a trace (this one, by a closed grid line) has
      // passed straight through h.at, so ending here leaves no dead end.
      if (taken_[d]) continue;
      taken_[d] = 1;
      const int w = topo_.other_vertex(h.edge, h.at);
      Trace& t = g_.traces[h.trace];
      t.vertices.push_back(w);
      t.edges.push_back(h.edge);
      g_.cut[h.edge] = 1;
      if (stop_[w]) continue;
      // Not a stop vertex: interior and regular, so its ring has 4 edges; one trace at most
      // arrives along each (a directed edge is taken once).
      const int k = ring_index(topo_, w, h.edge);
      slot_trace_[4 * size_t(w) + k] = h.trace;
      slot_pos_[4 * size_t(w) + k] = step;
      head_step_[h.trace] = step;
      moved_.push_back({h.trace, w, topo_.straight_on(w, h.edge), k, h.finishing});
    }
  }

  // The crossings of m's trace at its new vertex with traces that arrived there along the two
  // perpendicular edges, before or in this step (the latter recorded by the lower trace id).
  void record_crossings(const Moved& m) {
    const size_t base = 4 * size_t(m.at);
    const int pi = slot_pos_[base + m.slot];
    for (int turn : {1, 3}) {
      const int kk = (m.slot + turn) % 4;
      const int j = slot_trace_[base + kk];
      if (j < 0 || j == m.trace) continue;
      const int pj = slot_pos_[base + kk];
      if (pj == pi && j < m.trace) continue;
      crossings_.push_back({m.trace, pi, j, pj});
      // Leaving along ring[slot + 2], the left is its counter-clockwise neighbour ring[slot + 3].
      note_side(m.trace, /*left=*/turn == 3, pj, pi);
      note_side(j, /*left=*/turn == 1, pi, pj);
    }
  }

  void note_side(int t, bool left, int across, int along) {
    if (!angle_rule_ || !within_angle(across, along)) return;
    (left ? left_ok_ : right_ok_)[t] = 1;
  }

  void decide(int step) {
    heads_.clear();
    for (const Moved& m : moved_)
      done_[m.trace] = angle_rule_ && (m.finishing || (left_ok_[m.trace] && right_ok_[m.trace]));
    for (const Moved& m : moved_) {
      if (!done_[m.trace]) {
        heads_.push_back({m.trace, m.at, m.next_edge, false});
      } else if (!line_through(m, step)) {
        heads_.push_back({m.trace, m.at, m.next_edge, true});
      }
    }
  }

  // Whether a cut line passes straight through m's vertex once this step's decisions are made
  // (m itself is done, and stop vertices never get here).
  bool line_through(const Moved& m, int step) const {
    const size_t base = 4 * size_t(m.at);
    for (int k = 0; k < 4; ++k) {
      const int j = slot_trace_[base + k];
      if (j < 0) continue;
      const int r = slot_pos_[base + k];
      if (r < static_cast<int>(g_.traces[j].edges.size())) return true;  // j moved on
      if (j != m.trace && head_step_[j] == step && !done_[j]) return true;  // j will move on
    }
    return false;
  }

  const QuadMeshTopology& topo_;
  AngleBoundedGraph& g_;
  const bool angle_rule_;
  const double tan_alpha_;
  std::vector<uint8_t> stop_;
  // Per interior regular vertex and ring index k: the trace that arrived along ring edge k,
  // and after how many edges.
  std::vector<int> slot_trace_, slot_pos_;
  std::vector<uint8_t> taken_;  // per directed edge
  std::vector<uint8_t> left_ok_, right_ok_, done_;
  std::vector<int> head_step_;  // the last step in which the trace arrived somewhere
  std::vector<Head> heads_;
  std::vector<Moved> moved_;
  std::vector<Crossing> crossings_;
};

// (3): from each seed along each border or feature edge, straight on to the next seed. A
// non-seed vertex on a curve is regular with the curve passing straight on; the checks only
// guard against a malformed seed list (the chain then ends early, still along cut edges).
void add_curve_paths(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge,
                     const std::vector<int>& seeds, std::vector<std::vector<int>>& chains,
                     std::vector<int>& chain_trace) {
  std::vector<uint8_t> is_seed(topo.num_vertices(), 0);
  for (int s : seeds) is_seed[s] = 1;
  for (int s : seeds)
    for (int e0 : topo.vertex_edges(s)) {
      if (!is_curve(topo, feature_edge, e0)) continue;
      std::vector<int> chain{s};
      for (int e = e0, at = s;;) {
        at = topo.other_vertex(e, at);
        chain.push_back(at);
        if (is_seed[at] || chain.size() > size_t(topo.num_edges())) break;
        e = topo.straight_on(at, e);
        if (e < 0 || !is_curve(topo, feature_edge, e)) break;
      }
      chains.push_back(std::move(chain));
      chain_trace.push_back(-1);
    }
}

// Drops every chain whose edge set equals (keeping the lexicographically smallest vertex
// sequence) or strictly includes another's, then sorts. Each mesh edge lies on few chains (a
// directed edge starts at most one trace's path, a curve edge at most two curve paths), so
// the candidates for including chain q are those through q's smallest edge.
void prune_and_sort(const QuadMeshTopology& topo, std::vector<std::vector<int>>& chains,
                    std::vector<int>& chain_trace) {
  const size_t n = chains.size();
  std::vector<std::vector<int>> edges(n);
  std::vector<std::vector<int>> on_edge(topo.num_edges());
  for (size_t c = 0; c < n; ++c) {
    for (size_t i = 0; i + 1 < chains[c].size(); ++i)
      edges[c].push_back(topo.find_edge(chains[c][i], chains[c][i + 1]));
    std::sort(edges[c].begin(), edges[c].end());
    edges[c].erase(std::unique(edges[c].begin(), edges[c].end()), edges[c].end());
    for (int e : edges[c]) on_edge[e].push_back(static_cast<int>(c));
  }
  std::vector<uint8_t> dropped(n, 0);
  for (size_t q = 0; q < n; ++q)
    for (int p : on_edge[edges[q].front()]) {
      if (size_t(p) == q || edges[p].size() < edges[q].size() ||
          !std::includes(edges[p].begin(), edges[p].end(), edges[q].begin(), edges[q].end()))
        continue;
      if (edges[p].size() > edges[q].size())
        dropped[p] = 1;
      else  // the same edge set
        dropped[chains[p] < chains[q] ? q : p] = 1;
    }
  std::vector<size_t> order;
  for (size_t c = 0; c < n; ++c)
    if (!dropped[c]) order.push_back(c);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return chains[a] < chains[b]; });
  std::vector<std::vector<int>> kept_chains;
  std::vector<int> kept_trace;
  for (size_t c : order) {
    kept_chains.push_back(std::move(chains[c]));
    kept_trace.push_back(chain_trace[c]);
  }
  chains = std::move(kept_chains);
  chain_trace = std::move(kept_trace);
}

}  // namespace

AngleBoundedGraph trace_angle_bounded(const QuadMeshTopology& topo,
                                      const std::vector<uint8_t>& feature_edge,
                                      const std::vector<int>& seeds, double max_angle_deg) {
  if (feature_edge.size() != size_t(topo.num_edges()))
    throw std::invalid_argument("trace_angle_bounded: " + std::to_string(feature_edge.size()) +
                                " feature flags for " + std::to_string(topo.num_edges()) +
                                " edges");
  for (int s : seeds)
    if (s < 0 || s >= topo.num_vertices())
      throw std::invalid_argument("trace_angle_bounded: seed " + std::to_string(s) +
                                  " is not a vertex");
  if (!(max_angle_deg >= 0))
    throw std::invalid_argument("trace_angle_bounded: the maximum angle must be ≥ 0 degrees");

  AngleBoundedGraph g;
  g.cut.assign(topo.num_edges(), 0);
  Tracer tracer(topo, feature_edge, seeds, max_angle_deg, g);
  tracer.run();
  g.crossings = tracer.num_crossings();

  const std::vector<int> len = tracer.path_lengths();
  for (size_t t = 0; t < g.traces.size(); ++t) {
    const auto& v = g.traces[t].vertices;
    g.nonzero_chains.emplace_back(v.begin(), v.begin() + len[t] + 1);
    g.nonzero_trace.push_back(static_cast<int>(t));
  }
  add_curve_paths(topo, feature_edge, seeds, g.nonzero_chains, g.nonzero_trace);
  prune_and_sort(topo, g.nonzero_chains, g.nonzero_trace);
  return g;
}

}  // namespace bimdf::tmesh::detail
