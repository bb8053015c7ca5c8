// QuadWild-style energies of a quantization (quantize.hpp; ../shared/reference/
// quadwild_modeling.md §2.2, §3.7, §4.4): the IQP's isometry, regularity and alignment terms
// evaluated on the integer result, whatever model produced it, so that quantizers compare.
#include <cmath>
#include <cstdlib>

#include "bimdf/quant/quantize.hpp"

namespace bimdf::quant {
namespace {

// Positions where the separatrix of singular chart c leaving through side j meets it, doubled:
// `up` from the side's start corner, `down` from its end corner (note §2.2).
std::array<int64_t, 2> separatrix_position(const std::vector<int64_t>& S, int j) {
  const int k = static_cast<int>(S.size());
  auto s = [&](int i) { return S[((j + i) % k + k) % k]; };
  switch (k) {
    case 3:
      return {s(0) + s(1) - s(2), s(0) + s(2) - s(1)};
    case 5:
      return {s(3) + s(4) + s(0) - s(1) - s(2), s(0) + s(1) + s(2) - s(3) - s(4)};
    default:
      return {s(0) + s(4) - s(2), s(0) + s(2) - s(4)};  // k = 6
  }
}

bool satisfied(int64_t irregularity, int valence) { return irregularity <= (valence == 4 ? 0 : 1); }

}  // namespace

int64_t chart_irregularity(const std::vector<int64_t>& S) {
  const int k = static_cast<int>(S.size());
  auto s = [&](int i) { return S[i % k]; };
  int64_t total = 0;
  for (int j = 0; j < k; ++j) {
    switch (k) {
      case 4:
        total += std::llabs(s(j) - s(j + 2));
        break;
      case 3:
        total += std::max<int64_t>(0, s(j) + 1 - s(j + 1) - s(j + 2));
        break;
      case 5:
        total += std::max<int64_t>(0, s(j) + s(j + 1) + 1 - s(j + 2) - s(j + 3) - s(j + 4));
        break;
      case 6:
        total += std::max<int64_t>(0, s(j) + 1 - s(j + 2) - s(j + 4)) +
                 ((s(j) + s(j + 2) + s(j + 4)) % 2 != 0);
        break;
      default:
        break;
    }
  }
  return total;
}

std::vector<int64_t> side_lengths(const Layout& layout, int c,
                                  const std::vector<int64_t>& lengths) {
  std::vector<int64_t> S;
  for (const Side& side : layout.charts[c].sides) {
    int64_t sum = 0;
    for (int s : side.subsides) sum += lengths[s];
    S.push_back(sum);
  }
  return S;
}

Energies evaluate_quantization(const Layout& layout, const std::vector<double>& targets,
                               const std::vector<int64_t>& lengths,
                               const std::vector<AlignmentPair>& pairs,
                               const ModelOptions& options) {
  Energies e;
  const double R = 1 - options.alpha;
  const int C = static_cast<int>(layout.charts.size());
  std::vector<int64_t> irregularity(C, 0);
  for (int c = 0; c < C; ++c) {
    const Chart& chart = layout.charts[c];
    if (chart.empty()) continue;
    ++e.charts;
    const int k = chart.valence();
    double iso = 0;
    for (int s : chart.subsides) iso += (targets[s] - lengths[s]) * (targets[s] - lengths[s]);
    e.isometry += options.alpha * iso / static_cast<double>(chart.subsides.size());
    irregularity[c] = chart_irregularity(side_lengths(layout, c, lengths));
    e.regular_charts += irregularity[c] == 0;
    e.satisfied_charts += satisfied(irregularity[c], k);
    e.regularity += static_cast<double>(irregularity[c]) * R / (k * k) *
                    (k != 4 ? options.nonquad_weight : 1.0) * (k == 6 ? 0.5 : 1.0);
  }
  for (const AlignmentPair& pair : pairs) {
    ++e.pairs;
    const auto [a, ja] = pair.sides.front();
    const auto [z, jz] = pair.sides.back();
    const auto pa = separatrix_position(side_lengths(layout, a, lengths), ja);
    const auto pz = separatrix_position(side_lengths(layout, z, lengths), jz);
    // a's start corner meets z's end corner: a's `up` must equal z's `down`.
    const int64_t v1 = pa[0] - pz[1], v2 = pa[1] - pz[0];
    const double mismatch = 0.5 * static_cast<double>(std::llabs(v1) + std::llabs(v2));
    const int ka = layout.charts[a].valence(), kz = layout.charts[z].valence();
    e.alignment += R * options.align_weight * mismatch * (1.0 / (ka * ka) + 1.0 / (kz * kz));
    bool ok = v1 == 0 && v2 == 0;
    e.aligned_pairs += ok;
    for (auto [c, j] : pair.sides)
      ok = ok && satisfied(irregularity[c], layout.charts[c].valence());
    e.pair_satisfied.push_back(ok);
  }
  return e;
}

}  // namespace bimdf::quant
