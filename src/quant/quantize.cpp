// The quantization driver (quantize.hpp): targets, alignment chains, one or two exact solves
// (../shared/reference/quadwild_modeling.md §3.7), read-back and checks.
#include "bimdf/quant/quantize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "bimdf/flow.hpp"
#include "bimdf/solve.hpp"
#include "core/stopwatch.hpp"

namespace bimdf::quant {
namespace {

using bimdf::detail::seconds_since;

double surface_area(const TriangleMesh& m) {
  double area = 0;
  for (const auto& f : m.faces) {
    const auto &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

// The rules every quantization must keep, checked on the result (the model guarantees them).
void check_quantization(const Layout& layout, const std::vector<int64_t>& lengths) {
  for (size_t s = 0; s < lengths.size(); ++s)
    if (lengths[s] < 1)
      throw std::runtime_error("internal error: subside " + std::to_string(s) + " has length " +
                               std::to_string(lengths[s]));
  for (size_t c = 0; c < layout.charts.size(); ++c) {
    if (layout.charts[c].empty()) continue;
    int64_t perimeter = 0;
    for (int64_t side : side_lengths(layout, static_cast<int>(c), lengths)) perimeter += side;
    if (perimeter < 4 || perimeter % 2 != 0)
      throw std::runtime_error("internal error: chart " + std::to_string(c) + " has perimeter " +
                               std::to_string(perimeter));
  }
}

std::vector<double> subside_targets(const Layout& layout, double edge_length) {
  std::vector<double> targets;
  for (const Subside& s : layout.subsides) targets.push_back(std::max(1.0, s.length / edge_length));
  return targets;
}

// One or two rounds (note §3.7) at edge length ℓ.
Quantization quantize_at(const Layout& layout, double edge_length, const QuantizeOptions& o) {
  Quantization q;
  q.edge_length = edge_length;
  if (!(q.edge_length > 0) || !std::isfinite(q.edge_length))
    throw std::invalid_argument("the target edge length must be positive and finite");
  q.targets = subside_targets(layout, q.edge_length);

  std::vector<AlignmentPair> pairs;
  if (o.align) pairs = find_alignment_pairs(layout);
  std::vector<std::array<std::array<double, 2>, 2>> virtual_targets;
  for (int round = 0; round < 2; ++round) {
    QuantizationRound r;
    r.pairs = pairs;
    auto t = std::chrono::steady_clock::now();
    r.model = build_flow_model(layout, q.targets, q.edge_length, pairs, o.model,
                               round == 0 ? o.initial : o.resolve, virtual_targets);
    r.time_model_s = seconds_since(t);
    t = std::chrono::steady_clock::now();
    Solver solver(r.model.problem);
    solver.threads(o.threads)
        .lower_bound(false)
        .matching(o.matching)
        .approximate_unchained(o.approximate_unchained);
    if (o.time_limit >= 0) solver.time_limit(o.time_limit);
    const SolveStatus status = solver.run();
    r.time_solve_s = seconds_since(t);
    if (status != SolveStatus::Optimal && status != SolveStatus::Feasible)
      throw std::runtime_error("internal error: the quantization model was found " +
                               std::string(status_name(status)));
    r.solution = solver.solution();
    r.lengths = read_subside_lengths(r.model, r.solution.flow);
    check_quantization(layout, r.lengths);
    // Energies count every pair round 1 found, dropped or not, like the reference's report.
    double quads = 0;
    for (double x : estimate_quads(layout, r.model, r.solution.flow, r.lengths)) quads += x;
    r.estimated_quads = quads;
    r.energies = evaluate_quantization(layout, q.targets, r.lengths,
                                       q.rounds.empty() ? pairs : q.rounds[0].pairs, o.model);
    q.rounds.push_back(std::move(r));

    const QuantizationRound& last = q.rounds.back();
    const std::vector<bool>& kept_pairs = last.energies.pair_satisfied;
    const bool all_satisfied =
        last.energies.satisfied_charts == last.energies.charts &&
        std::find(kept_pairs.begin(), kept_pairs.end(), false) == kept_pairs.end();
    if (round == 1 || !o.align || !o.second_round || all_satisfied) break;
    // Round 2: keep the aligned pairs; their split targets follow round 1's split positions.
    std::vector<AlignmentPair> kept;
    for (size_t i = 0; i < pairs.size(); ++i)
      if (kept_pairs[i]) kept.push_back(pairs[i]);
    pairs = std::move(kept);
    virtual_targets.clear();
    if (o.resolve_new_targets) {
      virtual_targets.assign(layout.subsides.size(), {});
      for (size_t s = 0; s < layout.subsides.size(); ++s)
        for (int slot = 0; slot < 2; ++slot) {
          const auto& edges = last.model.virtual_edges[s][slot];
          if (edges[0] < 0) continue;
          const double f0 = static_cast<double>(last.solution.flow[edges[0]]);
          const double f1 = static_cast<double>(last.solution.flow[edges[1]]);
          const double t0 = q.targets[s] * f0 / (f0 + f1);
          virtual_targets[s][slot] = {t0, q.targets[s] - t0};
        }
    }
  }
  return q;
}

}  // namespace

double target_edge_length(const Layout& layout, const QuantizeOptions& o) {
  if (o.edge_length > 0) return o.edge_length;
  if (o.target_faces > 0)
    return std::sqrt(surface_area(layout.mesh) / static_cast<double>(o.target_faces));
  return layout.average_edge_length * o.scale;
}

Quantization quantize(const Layout& layout, const QuantizeOptions& o) {
  Quantization q = quantize_at(layout, target_edge_length(layout, o), o);
  if (o.edge_length > 0 || o.target_faces <= 0) return q;
  // Squares of side ℓ tiling the surface are only a start: short subsides round up to 1 and
  // patterns add quads. The count falls about as ℓ^−p, p = 2 at fine scales and less where
  // lengths reach their minimum, so p is re-estimated from the last two steps (a secant step
  // in log–log) until the count is within 1%; the closest quantization is kept.
  const double wanted = static_cast<double>(o.target_faces);
  auto quads = [](const Quantization& x) { return x.final_round().estimated_quads; };
  Quantization best = q;
  double exponent = 2;
  for (int step = 0; step < 8 && std::fabs(quads(q) - wanted) > 0.01 * wanted; ++step) {
    const double length = q.edge_length * std::pow(quads(q) / wanted, 1 / exponent);
    Quantization next = quantize_at(layout, length, o);
    if (quads(next) == quads(q)) break;  // the count no longer moves (coarsest possible)
    exponent =
        std::clamp(std::log(quads(q) / quads(next)) / std::log(length / q.edge_length), 0.25, 4.0);
    q = std::move(next);
    if (std::fabs(quads(q) - wanted) < std::fabs(quads(best) - wanted)) best = q;
  }
  return best;
}

}  // namespace bimdf::quant
