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

bool is_curve(const QuadMeshTopology& topo, const std::vector<uint8_t>& feature_edge, int e) {
  return topo.is_border_edge(e) || feature_edge[e];
}

// Vertices on a curve: border vertices, and those with a feature edge.
std::vector<uint8_t> curve_vertices(const QuadMeshTopology& topo,
                                    const std::vector<uint8_t>& feature_edge) {
  std::vector<uint8_t> on(topo.num_vertices(), 0);
  for (int e = 0; e < topo.num_edges(); ++e)
    if (is_curve(topo, feature_edge, e)) {
      const auto [a, b] = topo.edge_vertices(e);
      on[a] = on[b] = 1;
    }
  return on;
}

// Where traces end: the border and seeds. Traces pass only through the other vertices, which
// are interior and regular (their rings have 4 edges) — across a feature curve too, straight
// on (ours: a separatrix that crosses a feature stays in the T-mesh on both sides, so a
// coarsening cannot bend it there onto another singularity) — and cross each other there.
std::vector<uint8_t> stop_vertices(const QuadMeshTopology& topo, const std::vector<int>& seeds) {
  std::vector<uint8_t> stop(topo.num_vertices(), 0);
  for (int v = 0; v < topo.num_vertices(); ++v) stop[v] = topo.is_border_vertex(v);
  for (int s : seeds) stop[s] = 1;
  return stop;
}

// Lockstep runs of the angle rule over the full extended traces (`lines`): a trace never leaves
// its line (each directed edge is taken by one line at most), so a run only decides how far
// along its line each trace gets. run(tan_max) applies the rule at that threshold (a seed
// `across` edges to the side of a trace `along` edges from its seed is within the angle when
// across ≤ tan_max · along) and also finds the smallest threshold above it at which some trace
// would have been done at a step where it was not: the run is the same for every threshold
// below that (by induction over the steps, every move, crossing and decision is the same).
class Lockstep {
 public:
  Lockstep(const QuadMeshTopology& topo, const std::vector<uint8_t>& stop,
           const std::vector<uint8_t>& on_curve, const std::vector<Trace>& lines)
      : lines_(lines),
        on_curve_(on_curve),
        slot_trace_(4 * size_t(topo.num_vertices()), -1),
        slot_pos_(4 * size_t(topo.num_vertices()), -1) {
    // Per line position p ≥ 1: the slot of its vertex and of the edge it arrives along, −1 at
    // a stop vertex.
    for (const Trace& t : lines) {
      offset_.push_back(slot_of_.size());
      slot_of_.push_back(-1);  // the seed
      for (size_t p = 1; p < t.vertices.size(); ++p) {
        const int v = t.vertices[p];
        slot_of_.push_back(stop[v] ? -1 : 4 * v + ring_index(topo, v, t.edges[p - 1]));
      }
    }
  }

  void run(double tan_max) {
    tan_max_ = tan_max;
    const size_t T = lines_.size();
    for (size_t t = 0; t < len_.size(); ++t)  // clear the previous run's slots
      for (int p = 1; p <= len_[t]; ++p)
        if (const int s = slot_of_[offset_[t] + p]; s >= 0) slot_trace_[s] = -1;
    constexpr double kNone = std::numeric_limits<double>::infinity();
    len_.assign(T, 0);
    left_ratio_.assign(T, kNone);
    right_ratio_.assign(T, kNone);
    done_.assign(T, 0);
    running_.assign(T, 1);
    head_step_.assign(T, -1);
    next_threshold_ = kNone;
    heads_.clear();
    for (size_t t = 0; t < T; ++t) heads_.push_back({static_cast<int>(t), false});
    for (int step = 1; !heads_.empty(); ++step) {
      move_all(step);
      for (const Moved& m : moved_) record_crossings(m);
      decide(step);
    }
  }

  const std::vector<int>& lengths() const { return len_; }
  double next_threshold() const { return next_threshold_; }

 private:
  struct Head {
    int trace;
    bool finishing;  // done, running on to a vertex a cut line passes through
  };
  struct Moved {
    int trace, slot;
    bool finishing;
  };

  void move_all(int step) {
    moved_.clear();
    for (const Head& h : heads_) {
      const int t = h.trace;
      running_[t] = 0;
      // At the end of its line: a stop vertex, or its next edge would repeat one it took, so
      // it passed straight through here before and ending here leaves no dead end.
      if (len_[t] == static_cast<int>(lines_[t].edges.size())) continue;
      const int p = ++len_[t];
      const int s = slot_of_[offset_[t] + p];
      if (s < 0) continue;  // a stop vertex
      slot_trace_[s] = t;
      slot_pos_[s] = p;
      head_step_[t] = step;
      running_[t] = 1;
      moved_.push_back({t, s, h.finishing});
    }
  }

  // The crossings of m's trace at its new vertex with traces that arrived there along the two
  // perpendicular edges, before or in this step.
  void record_crossings(const Moved& m) {
    const int base = m.slot & ~3, k = m.slot & 3;
    const int pi = slot_pos_[m.slot];
    for (int turn : {1, 3}) {
      const int kk = base + (k + turn) % 4;
      const int j = slot_trace_[kk];
      if (j < 0 || j == m.trace) continue;
      const int pj = slot_pos_[kk];
      // Leaving along ring[k + 2], the left is its counter-clockwise neighbour ring[k + 3].
      note_side(m.trace, /*left=*/turn == 3, pj, pi);
      if (pj < pi) note_side(j, /*left=*/turn == 1, pi, pj);  // else j notes it itself
    }
  }

  // The smallest ratio across / along seen on each side: the trace is done once both are
  // within tan_max.
  void note_side(int t, bool left, int across, int along) {
    if (done_[t] || !running_[t]) return;  // it cannot matter any more
    double& r = (left ? left_ratio_ : right_ratio_)[t];
    r = std::min(r, double(across) / along);
  }

  void decide(int step) {
    for (const Moved& m : moved_) {
      // The threshold that would make it done now (both ratios only decrease over the steps,
      // so the last step before it is done, or stops, gives its smallest).
      const double needed = std::max(left_ratio_[m.trace], right_ratio_[m.trace]);
      done_[m.trace] = m.finishing || needed <= tan_max_;
      if (!done_[m.trace]) next_threshold_ = std::min(next_threshold_, needed);
    }
    heads_.clear();
    for (const Moved& m : moved_) {
      if (!done_[m.trace])
        heads_.push_back({m.trace, false});
      else if (!line_through(m, step))
        heads_.push_back({m.trace, true});
      else
        running_[m.trace] = 0;
    }
  }

  // Whether a trace line or a feature curve crosses m's vertex straight through,
  // perpendicular to m, once this step's decisions are made (m itself is done; stop vertices
  // never get here; a trace meets a feature curve only across it). A line along m's own (an
  // opposite trace) does not count: m would end inside an arc, not at a T-mesh vertex where
  // its non-zero path can end.
  bool line_through(const Moved& m, int step) const {
    const int base = m.slot & ~3;
    if (on_curve_[base / 4]) return true;
    for (int turn : {1, 3}) {
      const int s = base + ((m.slot & 3) + turn) % 4;
      const int j = slot_trace_[s];
      if (j < 0) continue;
      if (slot_pos_[s] < len_[j]) return true;                              // j moved on
      if (j != m.trace && head_step_[j] == step && !done_[j]) return true;  // j will move on
    }
    return false;
  }

  const std::vector<Trace>& lines_;
  const std::vector<uint8_t>& on_curve_;
  std::vector<size_t> offset_;  // per line, into slot_of_
  std::vector<int> slot_of_;
  // Per interior regular vertex v and ring index k, slot 4v + k: the trace that arrived along
  // ring edge k in this run, and after how many edges.
  std::vector<int> slot_trace_, slot_pos_;
  double tan_max_ = 0;
  std::vector<int> len_;
  std::vector<double> left_ratio_, right_ratio_;
  std::vector<uint8_t> done_, running_;
  std::vector<int> head_step_;  // the last step in which the trace arrived somewhere
  std::vector<Head> heads_;
  std::vector<Moved> moved_;
  double next_threshold_ = 0;
};

// Every crossing of the final traces, once, in vertex order.
std::vector<Crossing> crossings_of(const QuadMeshTopology& topo, const std::vector<uint8_t>& stop,
                                   const std::vector<Trace>& traces) {
  std::vector<int> slot_trace(4 * size_t(topo.num_vertices()), -1);
  std::vector<int> slot_pos(slot_trace.size(), -1);
  for (size_t t = 0; t < traces.size(); ++t)
    for (size_t p = 1; p < traces[t].vertices.size(); ++p) {
      const int v = traces[t].vertices[p];
      if (stop[v]) continue;
      const size_t s = 4 * size_t(v) + ring_index(topo, v, traces[t].edges[p - 1]);
      slot_trace[s] = static_cast<int>(t);
      slot_pos[s] = static_cast<int>(p);
    }
  std::vector<Crossing> out;
  for (size_t base = 0; base < slot_trace.size(); base += 4)
    for (int k = 0; k < 4; ++k) {
      const size_t s = base + k, s2 = base + (k + 1) % 4;
      const int a = slot_trace[s], b = slot_trace[s2];
      if (a >= 0 && b >= 0 && a != b) out.push_back({a, slot_pos[s], b, slot_pos[s2]});
    }
  return out;
}

// (1) and (2): per trace, how many of its edges its non-zero path takes.
std::vector<int> path_lengths(const std::vector<Trace>& traces,
                              const std::vector<Crossing>& crossings, bool angle_rule,
                              double tan_max) {
  std::vector<int> len(traces.size());
  for (size_t t = 0; t < len.size(); ++t) len[t] = static_cast<int>(traces[t].edges.size());
  auto at_most = [&](int t, int p) { len[t] = std::min(len[t], p); };
  for (const Crossing& c : crossings) {
    if (c.pb < c.pa) at_most(c.a, c.pa);
    if (c.pa < c.pb) at_most(c.b, c.pb);
    if (!angle_rule) continue;
    if (c.pb > tan_max * c.pa) at_most(c.b, c.pb);
    if (c.pa > tan_max * c.pb) at_most(c.a, c.pa);
  }
  return len;
}

// (3): from each seed along each border or feature edge, straight on to the next seed. A
// non-seed vertex on a curve is regular with the curve passing straight on; the checks only
// guard against a malformed seed list (the chain then ends early, still along cut edges).
std::vector<std::vector<int>> curve_paths(const QuadMeshTopology& topo,
                                          const std::vector<uint8_t>& feature_edge,
                                          const std::vector<int>& seeds) {
  std::vector<uint8_t> is_seed(topo.num_vertices(), 0);
  for (int s : seeds) is_seed[s] = 1;
  std::vector<std::vector<int>> chains;
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
    }
  return chains;
}

// (2) against curves (ours): a border or feature curve through seed i is i's separatrix along
// it as much as a trace would be, but no trace runs there, so (2) never sees it. Where trace
// t_j (from another seed) reaches the q-th vertex of a curve path from i (3), arriving across
// the curve after p edges: with p > tan α · q, t_j's path runs at least to the curve (len[j] ≤
// p; else seed j could slide onto the curve's line, which would then leave j at more than α);
// with q > tan α · p, the curve path's first q edges are a path of their own (`prefixes`; else
// i could slide along the curve onto t_j's line). Measured: without it, seeds on feature curves
// (elk at 20°) ended up joined at 26.6° under the bound (tmesh/separatrix_deviation.hpp).
void apply_angle_rule_to_curves(const QuadMeshTopology& topo,
                                const std::vector<uint8_t>& feature_edge,
                                const std::vector<Trace>& traces,
                                const std::vector<std::vector<int>>& curves, double tan_max,
                                std::vector<int>& len, std::vector<std::vector<int>>& prefixes) {
  // Per vertex, the traces arriving there across a curve: (trace, edges from its seed).
  std::vector<std::vector<std::array<int, 2>>> arriving(topo.num_vertices());
  for (size_t t = 0; t < traces.size(); ++t)
    for (size_t p = 1; p < traces[t].vertices.size(); ++p)
      if (!is_curve(topo, feature_edge, traces[t].edges[p - 1]))
        arriving[traces[t].vertices[p]].push_back({static_cast<int>(t), static_cast<int>(p)});
  for (const std::vector<int>& curve : curves)
    for (size_t q = 1; q < curve.size(); ++q)
      for (const auto& [t, p] : arriving[curve[q]]) {
        if (traces[t].seed == curve[0]) continue;
        if (p > tan_max * double(q)) len[t] = std::min(len[t], p);
        if (double(q) > tan_max * p) prefixes.emplace_back(curve.begin(), curve.begin() + q + 1);
      }
}

// (4, ours): each piece of a trace from one curve it reaches to the next, so that a strip
// between two feature curves (or a feature curve and the border) that a trace crosses keeps a
// width ≥ 1 there: without it a coarsening could fold two sharp curves into one.
void add_between_curve_paths(const std::vector<Trace>& traces, const std::vector<uint8_t>& on_curve,
                             std::vector<std::vector<int>>& chains, std::vector<int>& chain_trace) {
  for (size_t t = 0; t < traces.size(); ++t) {
    const std::vector<int>& v = traces[t].vertices;
    size_t last = v.size();  // none yet
    for (size_t p = 0; p < v.size(); ++p) {
      if (!on_curve[v[p]]) continue;
      if (last < p) {
        chains.emplace_back(v.begin() + last, v.begin() + p + 1);
        chain_trace.push_back(-2 - static_cast<int>(t));
      }
      last = p;
    }
  }
}

// Drops every chain whose edge set equals (keeping the lexicographically smallest vertex
// sequence) or strictly includes another's, then sorts. Each mesh edge lies on few chains (a
// directed edge lies on one trace at most, a curve edge on two curve paths at most), so
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
      else  // the same edge set: keep the smaller sequence, of equal ones the first
        dropped[chains[p] < chains[q] || (chains[p] == chains[q] && size_t(p) < q) ? q : p] = 1;
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
                                      const std::vector<int>& seeds, double max_angle_deg,
                                      bool cross_features) {
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

  // The union of the lockstep runs over every threshold from tan α up (see the header): one
  // run per threshold at which the outcome changes, each at the next threshold of the last.
  const bool angle_rule = max_angle_deg < 90;
  const double tan_max =
      angle_rule ? std::tan(max_angle_deg * std::numbers::pi / 180) * (1 + kRatioTolerance) : 0;
  const std::vector<uint8_t> stop = stop_vertices(topo, seeds);
  const std::vector<uint8_t> on_curve = curve_vertices(topo, feature_edge);
  AngleBoundedGraph g;
  g.traces = trace_extended_motorcycle_graph(topo, feature_edge, seeds, cross_features);
  if (angle_rule) {
    Lockstep lockstep(topo, stop, on_curve, g.traces);
    std::vector<int> keep(g.traces.size(), 0);
    for (double t = tan_max;;) {
      lockstep.run(t);
      ++g.lockstep_runs;
      for (size_t i = 0; i < keep.size(); ++i) keep[i] = std::max(keep[i], lockstep.lengths()[i]);
      const double next = lockstep.next_threshold();
      if (!std::isfinite(next)) break;
      t = next * (1 + kRatioTolerance);
    }
    for (size_t i = 0; i < keep.size(); ++i) {
      g.traces[i].vertices.resize(keep[i] + 1);
      g.traces[i].edges.resize(keep[i]);
    }
  }
  g.cut.resize(topo.num_edges());
  for (int e = 0; e < topo.num_edges(); ++e) g.cut[e] = is_curve(topo, feature_edge, e);
  for (const Trace& t : g.traces)
    for (int e : t.edges) g.cut[e] = 1;

  const std::vector<Crossing> crossings = crossings_of(topo, stop, g.traces);
  g.crossings = static_cast<int>(crossings.size());
  std::vector<int> len = path_lengths(g.traces, crossings, angle_rule, tan_max);
  std::vector<std::vector<int>> curves = curve_paths(topo, feature_edge, seeds), prefixes;
  if (angle_rule)
    apply_angle_rule_to_curves(topo, feature_edge, g.traces, curves, tan_max, len, prefixes);
  for (std::vector<int>& c : prefixes) curves.push_back(std::move(c));
  for (size_t t = 0; t < g.traces.size(); ++t) {
    const auto& v = g.traces[t].vertices;
    g.nonzero_chains.emplace_back(v.begin(), v.begin() + len[t] + 1);
    g.nonzero_trace.push_back(static_cast<int>(t));
  }
  for (std::vector<int>& c : curves) {
    g.nonzero_chains.push_back(std::move(c));
    g.nonzero_trace.push_back(-1);
  }
  add_between_curve_paths(g.traces, on_curve, g.nonzero_chains, g.nonzero_trace);
  prune_and_sort(topo, g.nonzero_chains, g.nonzero_trace);
  return g;
}

}  // namespace bimdf::tmesh::detail
