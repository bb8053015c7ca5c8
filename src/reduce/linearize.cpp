#include "reduce/linearize.hpp"

#include <algorithm>
#include <cmath>

#include "reduce/checked.hpp"

namespace bimdf::detail {
namespace {

class PieceWriter {
 public:
  PieceWriter(Linearization& lin, int edge, int direction, End a, End b)
      : lin_(lin), edge_(edge), direction_(direction), a_(a), b_(b) {}

  void add(int64_t capacity, double cost) {
    if (capacity <= 0) return;
    BiMcf& mcf = lin_.mcf;
    if (last_ >= 0 && mcf.cost[last_] == cost) {
      mcf.capacity[last_] = (capacity == kInfinity || mcf.capacity[last_] == kInfinity)
                                ? kInfinity
                                : mcf.capacity[last_] + capacity;
      return;
    }
    last_ = mcf.num_arcs();
    mcf.end_a.push_back(a_);
    mcf.end_b.push_back(b_);
    mcf.capacity.push_back(capacity);
    mcf.cost.push_back(cost);
    lin_.arc_edge.push_back(edge_);
    lin_.arc_direction.push_back(static_cast<int8_t>(direction_));
  }

 private:
  Linearization& lin_;
  int edge_, direction_;
  End a_, b_;
  int last_ = -1;
};

// Pieces in one direction: `room` is how far the flow may move (kInfinity for unbounded),
// `at(d)` the cost at deviation d in that direction, `minimizer_beyond(d)` the deviation ≥ d
// where the cost is smallest (used by underestimating tails only).
template <typename Minimizer>
void add_pieces(PieceWriter& out, int64_t room, const CostAlong& at,
                const Minimizer& minimizer_beyond, const LinearizeOptions& opt, int max_deviation) {
  const int64_t s = opt.step;
  int64_t d = 0;
  while (d + s <= max_deviation && room - d >= s) {
    out.add(s, piece_cost(at, d, s));
    d += s;
  }
  if (!opt.tails || room == d) return;
  if (opt.underestimating_tails) {
    const double slope = piece_cost(at, d, 1);
    if (room != kInfinity || slope >= 0) {
      out.add(room == kInfinity ? kInfinity : room - d, slope);
      return;
    }
    const int64_t m = minimizer_beyond(d);
    out.add(m - d, slope);
    out.add(kInfinity, std::max(0.0, piece_cost(at, m, 1)));
    return;
  }
  if (room == kInfinity) {
    out.add(kInfinity, std::max(0.0, piece_cost(at, d, s)));
  } else {
    const int64_t w = room - d;
    const int64_t sample = std::min<int64_t>(w, s);
    out.add(w, piece_cost(at, d, sample));
  }
}

}  // namespace

int64_t deviation_room(const Problem& p, int e, int64_t g, int direction) {
  if (direction > 0) return p.upper[e] == kInfinity ? kInfinity : p.upper[e] - g;
  return p.lower[e] == -kInfinity ? kInfinity : g - p.lower[e];
}

Linearization linearize(const Problem& p, std::span<const int64_t> guess,
                        const LinearizeOptions& opt) {
  Linearization lin;
  lin.guess.assign(guess.begin(), guess.end());
  std::vector<__int128> residual(p.demand.begin(), p.demand.end());
  for (int e = 0; e < p.num_edges(); ++e) {
    const int64_t g = guess[e];
    const End a = p.end_a[e], b = p.end_b[e];
    residual[a.node] -= static_cast<__int128>(a.sign()) * g;
    residual[b.node] -= static_cast<__int128>(b.sign()) * g;
    const Cost& c = p.cost[e];
    const int window =
        opt.edge_max_deviation.empty() ? opt.max_deviation : opt.edge_max_deviation[e];
    PieceWriter forward(lin, e, +1, a, b);
    add_pieces(
        forward, deviation_room(p, e, g, +1), CostAlong{c, g, +1},
        [&](int64_t d) { return c.argmin(g + d, kInfinity) - g; }, opt, window);
    PieceWriter backward(lin, e, -1, End{a.node, !a.head}, End{b.node, !b.head});
    add_pieces(
        backward, deviation_room(p, e, g, -1), CostAlong{c, g, -1},
        [&](int64_t d) { return g - c.argmin(-kInfinity, g - d); }, opt, window);
  }
  lin.mcf.demand.resize(p.num_nodes());
  for (int v = 0; v < p.num_nodes(); ++v)
    lin.mcf.demand[v] =
        narrow_checked(residual[v], "the residual demand of node " + std::to_string(v));
  return lin;
}

std::vector<int64_t> Linearization::lift(std::span<const int64_t> arc_flow) const {
  std::vector<int64_t> x = guess;
  for (size_t i = 0; i < arc_flow.size(); ++i) x[arc_edge[i]] += arc_direction[i] * arc_flow[i];
  return x;
}

}  // namespace bimdf::detail
