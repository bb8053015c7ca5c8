// The "quadwild" family of generate.hpp: QuadWild's Bi-MDF quantization model (reference:
// ../shared/reference/quadwild_modeling.md §3.2–3.6, configuration flow.txt with alpha 0.005,
// regularityNonQuadrilateralsWeight 0.9, alignSingularitiesWeight 0.1, flow_virtual_simple.json
// round 1) on a random chart adjacency: charts get valences 3–6 in the proportions of the shared
// layouts, sides get 1–3 subsides, and subside slots are paired at random (a few go to the
// mesh border). Sides joined by a single-subside connection are aligned (half nodes, virtual
// subsides, unaligners) with some probability, as QuadWild does for singularity chains.
#include <algorithm>
#include <numeric>

#include "generate/generators.hpp"

namespace bimdf::detail {
namespace {

constexpr double kAlpha = 0.005;
constexpr double kRegularity = 1 - kAlpha;
constexpr double kNonQuadWeight = 0.9;
constexpr double kAlignWeight = 0.1;
constexpr double kUnalignWeight = 2;  // flow_virtual_simple.json, round 1

struct Side {
  int subsides = 1;
  bool paired = false;
  int node = -1, half0 = -1, half1 = -1;  // half nodes when paired
  double target = 0;                      // Σ of its subsides' targets

  // The node a strip leaving towards side j+2 uses (the end half), and the one a strip from
  // side j−2 arrives at (the start half).
  int end_node() const { return paired ? half1 : node; }
  int start_node() const { return paired ? half0 : node; }
  std::vector<int> nodes() const { return paired ? std::vector<int>{half0, half1} : std::vector<int>{node}; }
};

struct Chart {
  int valence = 4;
  std::vector<Side> sides;
  int subsides = 0;
};

struct Slot {
  int chart, side;
};

int random_valence(RandomSource& r) {
  // Roughly the mix of the shared layouts (e.g. bull: 3:1396 4:877 5:219 6:7).
  const double u = r.real();
  return u < 0.45 ? 3 : u < 0.85 ? 4 : u < 0.99 ? 5 : 6;
}

}  // namespace

Problem generate_quadwild_like(int64_t size, uint64_t seed) {
  RandomSource r(seed);
  // About 21 edges per chart on average (measured on this generator).
  const int num_charts = static_cast<int>(std::max<int64_t>(2, size / 21));
  std::vector<Chart> charts(num_charts);
  std::vector<Slot> slots;
  for (int c = 0; c < num_charts; ++c) {
    Chart& chart = charts[c];
    chart.valence = random_valence(r);
    chart.sides.resize(chart.valence);
    for (int j = 0; j < chart.valence; ++j) {
      const double u = r.real();
      chart.sides[j].subsides = u < 0.7 ? 1 : u < 0.92 ? 2 : 3;
      chart.subsides += chart.sides[j].subsides;
      for (int s = 0; s < chart.sides[j].subsides; ++s) slots.push_back({c, j});
    }
  }
  for (size_t i = slots.size(); i > 1; --i) std::swap(slots[i - 1], slots[r.below(i)]);

  // Subsides: consecutive slots form an interior subside unless they belong to one chart or
  // the border takes one of them.
  struct Subside {
    Slot left, right;  // right.chart = −1 on the border
    double target;
    bool aligned = false;
  };
  std::vector<Subside> subsides;
  for (size_t i = 0; i < slots.size();) {
    const double target = std::max(1.0, std::exp(1.2 + 0.5 * r.normal()));
    if (i + 1 < slots.size() && slots[i].chart != slots[i + 1].chart && !r.chance(0.03)) {
      subsides.push_back({slots[i], slots[i + 1], target});
      i += 2;
    } else {
      subsides.push_back({slots[i], {-1, -1}, target});
      i += 1;
    }
  }
  for (Subside& s : subsides) {
    charts[s.left.chart].sides[s.left.side].target += s.target;
    if (s.right.chart >= 0) charts[s.right.chart].sides[s.right.side].target += s.target;
    Side& a = charts[s.left.chart].sides[s.left.side];
    if (s.right.chart < 0 || a.subsides != 1) continue;
    Side& b = charts[s.right.chart].sides[s.right.side];
    if (b.subsides == 1 && r.chance(0.35)) s.aligned = a.paired = b.paired = true;
  }

  Problem p;
  for (Chart& chart : charts)
    for (Side& side : chart.sides) {
      if (side.paired) side.half0 = p.add_node(0), side.half1 = p.add_node(0);
      else side.node = p.add_node(0);
    }
  auto tail = [](int v) { return End{v, false}; };
  auto head = [](int v) { return End{v, true}; };

  // Per-chart gadgets (§3.3).
  for (const Chart& chart : charts) {
    const int k = chart.valence;
    const double w = kRegularity / (k * k) * (k == 4 ? 1.0 : kNonQuadWeight);
    const double loop_w = (k == 6 ? 1 : 4) * w;
    const double neighbour_w = (k == 4 ? 4 : k == 5 ? 2 : 3) * w;
    const double sing_w = (k == 6 ? 0.5 : 1) * w;
    auto side = [&](int j) -> const Side& { return chart.sides[((j % k) + k) % k]; };
    for (const Side& s : chart.sides) {
      for (int v : s.nodes())
        p.add_edge(tail(v), tail(v), 0, kInfinity, Cost::abs_deviation(0, loop_w));
      if (s.paired)
        p.add_edge(tail(s.half0), tail(s.half1), 0, kInfinity, Cost::abs_deviation(0, loop_w));
    }
    auto connect_all = [&](const Side& a, const Side& b, double weight) {
      for (int u : a.nodes())
        for (int v : b.nodes())
          p.add_edge(tail(u), tail(v), 0, kInfinity, Cost::abs_deviation(0, weight));
    };
    if (k >= 4)
      for (int j = 0; j < k; ++j) connect_all(side(j), side(j + 1), neighbour_w);
    if (k == 6)
      for (int j = 0; j < 3; ++j) connect_all(side(j), side(j + 3), 6 * w);
    const int strips = k == 4 ? 2 : k;
    for (int j = 0; j < strips; ++j) {
      const Side &a = side(j), &b = side(j + 2);
      const auto guess = static_cast<int64_t>((a.target + b.target) / 4);
      const int64_t lower = k == 4 ? 0 : 1;
      p.add_edge(tail(a.end_node()), tail(b.start_node()), lower, kInfinity, Cost::zero(guess));
      if (k == 4 && (a.paired || b.paired))
        p.add_edge(tail(a.start_node()), tail(b.end_node()), 0, kInfinity, Cost::zero(guess));
      if (k != 4)
        p.add_edge(head(a.end_node()), head(b.start_node()), 0, 1, Cost::abs_deviation(0, sing_w));
    }
  }

  // Subside edges (§3.4) and the border node.
  int border = -1;
  for (const Subside& s : subsides) {
    const Chart& left = charts[s.left.chart];
    const Side& a = left.sides[s.left.side];
    const double a_left = kAlpha / left.subsides;
    if (s.right.chart < 0) {
      if (border < 0) {
        border = p.add_node(0);
        p.add_edge(tail(border), tail(border), 0, kInfinity, Cost::zero());
      }
      p.add_edge(head(a.node), head(border), 1, kInfinity,  // border sides are never paired
                 Cost::quad_deviation(s.target, a_left));
      continue;
    }
    const Chart& right = charts[s.right.chart];
    const Side& b = right.sides[s.right.side];
    const double a_right = kAlpha / right.subsides;
    if (!s.aligned) {
      const int m = p.add_node(0);
      p.add_edge(head(a.node), head(m), 1, kInfinity, Cost::quad_deviation(s.target, a_left));
      p.add_edge(tail(m), head(b.node), 1, kInfinity, Cost::quad_deviation(s.target, a_right));
      continue;
    }
    // Virtual subsides: half targets, no isometry weight on quads ("half" fallback of the
    // "simple" mode), and unaligners that shift the split point.
    const double omega_left = left.valence == 4 ? 0 : 1, omega_right = right.valence == 4 ? 0 : 1;
    const int m0 = p.add_node(0), m1 = p.add_node(0);
    const double half = s.target / 2;
    p.add_edge(head(m0), head(a.half0), 1, kInfinity, Cost::quad_deviation(half, omega_left * a_left));
    p.add_edge(head(m1), head(a.half1), 1, kInfinity, Cost::quad_deviation(half, omega_left * a_left));
    p.add_edge(tail(m0), head(b.half1), 1, kInfinity, Cost::quad_deviation(half, omega_right * a_right));
    p.add_edge(tail(m1), head(b.half0), 1, kInfinity, Cost::quad_deviation(half, omega_right * a_right));
    const double u = kUnalignWeight * kRegularity * kAlignWeight * 0.5 /
                     (0.5 * (left.subsides + right.subsides));
    p.add_edge(tail(m0), head(m1), 0, kInfinity, Cost::abs_deviation(0, u));
    p.add_edge(tail(m1), head(m0), 0, kInfinity, Cost::abs_deviation(0, u));
  }
  return p;
}

}  // namespace bimdf::detail
