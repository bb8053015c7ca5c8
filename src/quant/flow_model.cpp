// The Bi-MDF model of a layout (quantize.hpp; ../shared/reference/quadwild_modeling.md
// §3.2–3.4): per chart its side nodes and gadget, then per subside the edges that carry its
// length into the side nodes of its charts, then the boundary node's loop. Node and edge order
// follow the reference quantizer's, so exported models can be compared line by line.
#include <algorithm>
#include <cmath>

#include "bimdf/quant/quantize.hpp"

namespace bimdf::quant {
namespace {

struct GadgetWeights {
  double loop = 0, neighbour = 0, opposite = 0, boundary_singularity = 0;
};

// Weights of note §3.2: the regularity energy the IQP would charge per unit of emergency flow.
GadgetWeights gadget_weights(int k, const ModelOptions& o, bool regularity_off) {
  double w = (1 - o.alpha) / (k * k) * (k != 4 ? o.nonquad_weight : 1.0);
  if (regularity_off) w = 0;
  switch (k) {
    case 3:
      return {4 * w, 0, 0, w};
    case 4:
      return {4 * w, 4 * w, 0, 0};
    case 5:
      return {4 * w, 2 * w, 0, w};
    default:
      return {w, 3 * w, 6 * w, 0.5 * w};
  }
}

Cost iso_cost(IsoObjective objective, double target, double weight) {
  return objective == IsoObjective::Quadratic ? Cost::quad_deviation(target, weight)
                                              : Cost::abs_deviation(target, weight);
}

// Per subside: its lower bound on the border (ModelOptions::min_border_loop), 1 elsewhere.
// Border loops are the border subsides joined at their end vertices.
std::vector<int64_t> border_subside_minimum(const Layout& layout, const ModelOptions& options) {
  const int S = static_cast<int>(layout.subsides.size());
  std::vector<int64_t> minimum(S, 1);
  std::vector<int> root(layout.mesh.num_vertices());
  for (size_t v = 0; v < root.size(); ++v) root[v] = static_cast<int>(v);
  const auto find = [&](int v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (const Subside& sub : layout.subsides)
    if (sub.on_border() && !sub.vertices.empty())
      root[find(sub.vertices.front())] = find(sub.vertices.back());
  std::vector<int> per_loop(root.size(), 0);
  for (const Subside& sub : layout.subsides)
    if (sub.on_border() && !sub.vertices.empty()) ++per_loop[find(sub.vertices.front())];
  for (int s = 0; s < S; ++s) {
    const Subside& sub = layout.subsides[s];
    if (!sub.on_border() || sub.vertices.empty()) continue;
    const int k = per_loop[find(sub.vertices.front())];
    minimum[s] = std::max<int64_t>(1, (options.min_border_loop + k - 1) / k);
  }
  return minimum;
}

}  // namespace

FlowModel build_flow_model(const Layout& layout, const std::vector<double>& targets,
                           double edge_length, const std::vector<AlignmentPair>& pairs,
                           const ModelOptions& options, const PairedWeights& paired,
                           const std::vector<std::array<std::array<double, 2>, 2>>& virtual_targets,
                           const std::vector<bool>& regularity_off) {
  FlowModel model;
  Problem& p = model.problem;
  const int C = static_cast<int>(layout.charts.size());
  const int S = static_cast<int>(layout.subsides.size());

  std::vector<std::vector<bool>> is_paired(C);
  for (int c = 0; c < C; ++c) is_paired[c].assign(layout.charts[c].valence(), false);
  for (const AlignmentPair& pair : pairs)
    for (auto [c, j] : pair.sides) is_paired[c][j] = true;

  // Side nodes: node[c][j] = {start half, end half}; both the same node for an unpaired side.
  std::vector<std::vector<std::array<int, 2>>> node(C);
  model.chart_strips.assign(C, {});
  auto tail = [](int v) { return End{v, false}; };
  auto head = [](int v) { return End{v, true}; };
  for (int c = 0; c < C; ++c) {
    const Chart& chart = layout.charts[c];
    if (chart.empty()) continue;
    const int k = chart.valence();
    const GadgetWeights gw =
        gadget_weights(k, options, !regularity_off.empty() && regularity_off[c]);
    node[c].resize(k);
    for (int j = 0; j < k; ++j) {
      const int a = p.add_node();
      node[c][j] = {a, is_paired[c][j] ? p.add_node() : a};
    }
    auto nodes_of = [&](int j) {
      std::vector<int> v{node[c][j][0]};
      if (node[c][j][1] != node[c][j][0]) v.push_back(node[c][j][1]);
      return v;
    };
    auto emergency = [&](int a, int b, double weight) {
      p.add_edge(tail(a), tail(b), 0, kInfinity, Cost::abs_deviation(0, weight));
    };
    // 1. Side loops: a side may be two units longer than its strips allow.
    for (int j = 0; j < k; ++j) {
      for (int v : nodes_of(j)) emergency(v, v, gw.loop);
      if (is_paired[c][j]) emergency(node[c][j][0], node[c][j][1], gw.loop);
    }
    // 2. Neighbour edges: two adjacent sides one unit longer each (moves parity between sides).
    if (k >= 4)
      for (int j = 0; j < k; ++j)
        for (int a : nodes_of(j))
          for (int b : nodes_of((j + 1) % k)) emergency(a, b, gw.neighbour);
    // 3. Opposite edges of hexagons: flips the parity of both alternate-side triples.
    if (k == 6)
      for (int j = 0; j < 3; ++j)
        for (int a : nodes_of(j))
          for (int b : nodes_of(j + 3)) emergency(a, b, gw.opposite);
    // 4–5. Strips of the regular pattern (side j to side j+2), each with a parallel
    // singularity-on-boundary edge for k ≠ 4 that cancels one mandatory strip.
    auto side_target = [&](int j) { return chart.sides[j].length / edge_length; };
    for (int j = 0; j < (k == 4 ? 2 : k); ++j) {
      const int o = (j + 2) % k;
      const auto guess = static_cast<int64_t>(std::llround((side_target(j) + side_target(o)) / 4));
      std::vector<std::array<int, 2>> strips{{node[c][j][1], node[c][o][0]}};
      if (k == 4 && (is_paired[c][j] || is_paired[c][o]))
        strips.push_back({node[c][j][0], node[c][o][1]});
      model.chart_strips[c].emplace_back();
      for (auto [a, b] : strips) {
        model.chart_strips[c].back().strips.push_back(
            p.add_edge(tail(a), tail(b), k == 4 ? 0 : 1, kInfinity, Cost::zero(guess)));
        if (k != 4)
          model.chart_strips[c].back().cancels.push_back(
              p.add_edge(head(a), head(b), 0, 1, Cost::abs_deviation(0, gw.boundary_singularity)));
      }
    }
  }

  // 6. Subsides. Border subsides end in one boundary node B for the whole mesh.
  model.boundary_node = p.add_node();
  const int B = model.boundary_node;
  model.subside_edges.assign(S, {});
  model.virtual_edges.assign(S, {{{-1, -1}, {-1, -1}}});
  double border_total = 0;
  auto iso_weight = [&](int c) {
    return options.alpha / static_cast<double>(layout.charts[c].subsides.size());
  };
  const std::vector<int64_t> border_minimum = border_subside_minimum(layout, options);
  for (int s = 0; s < S; ++s) {
    const Subside& sub = layout.subsides[s];
    const int L = sub.charts[0], R = sub.charts[1];
    const double t = targets[s];
    if (sub.on_border()) {
      border_total += t;
      const int e = p.add_edge(head(node[L][sub.sides[0]][0]), head(B), border_minimum[s],
                               kInfinity, Cost::quad_deviation(t, iso_weight(L)));
      model.subside_edges[s] = {e};
      continue;
    }
    if (!is_paired[L][sub.sides[0]]) {
      const int M = p.add_node();
      const int e = p.add_edge(head(node[L][sub.sides[0]][0]), head(M), 1, kInfinity,
                               Cost::quad_deviation(t, iso_weight(L)));
      p.add_edge(tail(M), head(node[R][sub.sides[1]][0]), 1, kInfinity,
                 Cost::quad_deviation(t, iso_weight(R)));
      model.subside_edges[s] = {e};
      continue;
    }
    // A link of an alignment chain: the subside is split at the separatrix into two virtual
    // subsides per chart; M0 joins L's start half with R's end half (R walks it reversed).
    std::array<std::array<double, 2>, 2> tau{};
    std::array<double, 2> omega{};
    for (int slot = 0; slot < 2; ++slot) {
      const int c = sub.charts[slot], j = sub.sides[slot];
      const Chart& chart = layout.charts[c];
      const int k = chart.valence();
      omega[slot] = k == 4 ? 0.0 : 1.0;
      if (!virtual_targets.empty()) {
        tau[slot] = virtual_targets[s][slot];
      } else if (options.simple_targets && k == 3) {
        // The regular triangle's strip count between side j and side j+1 is (a + b − c)/2.
        const double a = chart.sides[j].length, b = chart.sides[(j + 1) % 3].length,
                     cc = chart.sides[(j + 2) % 3].length;
        tau[slot][0] = std::clamp(0.5 * (a + b - cc), 0.0, a) / edge_length;
        tau[slot][1] = a / edge_length - tau[slot][0];
        omega[slot] = 1.0;
      } else {
        // Half the subside's length, without the max(1, ·) of its own target (as the
        // reference does; it matters for subsides shorter than ℓ).
        const double half = sub.length / edge_length / 2;
        tau[slot] = {half, half};
      }
    }
    const int M0 = p.add_node(), M1 = p.add_node();
    auto virtual_edge = [&](End m, int side_node, int slot, int half) {
      const int c = sub.charts[slot];
      return p.add_edge(m, head(side_node), 1, kInfinity,
                        iso_cost(paired.iso_objective, tau[slot][half],
                                 paired.iso_weight * omega[slot] * iso_weight(c)));
    };
    const auto& hl = node[L][sub.sides[0]];
    const auto& hr = node[R][sub.sides[1]];
    const int e0 = virtual_edge(head(M0), hl[0], 0, 0);
    const int e1 = virtual_edge(head(M1), hl[1], 0, 1);
    const int e2 = virtual_edge(tail(M0), hr[1], 1, 1);
    const int e3 = virtual_edge(tail(M1), hr[0], 1, 0);
    const double average_subsides = 0.5 * static_cast<double>(layout.charts[L].subsides.size() +
                                                              layout.charts[R].subsides.size());
    const double u =
        paired.unalign_weight * (1 - options.alpha) * options.align_weight * 0.5 / average_subsides;
    p.add_edge(tail(M0), head(M1), 0, kInfinity, Cost::abs_deviation(0, u));
    p.add_edge(tail(M1), head(M0), 0, kInfinity, Cost::abs_deviation(0, u));
    model.subside_edges[s] = {e0, e1};
    model.virtual_edges[s] = {{{e0, e1}, {e3, e2}}};
  }
  p.add_edge(tail(B), tail(B), 0, kInfinity,
             Cost::zero(static_cast<int64_t>(std::llround(border_total / 2))));
  return model;
}

std::vector<int64_t> read_subside_lengths(const FlowModel& model,
                                          const std::vector<int64_t>& flow) {
  std::vector<int64_t> lengths(model.subside_edges.size(), 0);
  for (size_t s = 0; s < lengths.size(); ++s)
    for (int e : model.subside_edges[s]) lengths[s] += flow[e];
  return lengths;
}

std::vector<double> estimate_quads(const Layout& layout, const FlowModel& model,
                                   const std::vector<int64_t>& flow,
                                   const std::vector<int64_t>& lengths) {
  std::vector<double> quads(layout.charts.size(), 0);
  for (size_t c = 0; c < layout.charts.size(); ++c) {
    const Chart& chart = layout.charts[c];
    if (chart.empty()) continue;
    std::vector<double> n;  // net strips per strip family
    double strip_total = 0;
    for (const StripEdges& family : model.chart_strips[c]) {
      int64_t net = 0;
      for (int e : family.strips) net += flow[e];
      for (int e : family.cancels) net -= flow[e];
      n.push_back(static_cast<double>(std::max<int64_t>(net, 0)));
      strip_total += n.back();
    }
    double regular = 0;
    if (chart.valence() == 4) {
      regular = n[0] * n[1];
    } else {
      // The corner between sides j and j+1 is a grid of (strips j → j+2) × (strips j−1 → j+1).
      const int k = chart.valence();
      for (int j = 0; j < k; ++j) regular += n[j] * n[(j + k - 1) % k];
    }
    double perimeter = 0;
    for (int64_t side : side_lengths(layout, static_cast<int>(c), lengths))
      perimeter += static_cast<double>(side);
    // Emergency flow lengthens sides beyond the strips: scale the pattern's area to the
    // actual perimeter (exact for regular charts, where both perimeters agree).
    quads[c] = strip_total > 0 ? regular * std::pow(perimeter / (2 * strip_total), 2)
                               : std::pow(perimeter / 4, 2);
  }
  return quads;
}

}  // namespace bimdf::quant
