// The arc Bi-MDF model of a quad T-mesh (paper §4.2.1–4.2.2, Fig. 10b) and the independent
// check of its solutions, with the relaxed variant's corner edges (§4.2.4, Fig. 10c). See
// tmesh/quantize.hpp for the construction.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "bimdf/tmesh/quantize.hpp"

namespace bimdf::tmesh {
namespace {

double side_target(const TMesh& tmesh, int patch, int side) {
  double length = 0;
  for (int h : tmesh.patch_sides[patch][side]) length += tmesh.arc_target[TMesh::arc_of(h)];
  return length;
}

std::string check_nonzero_paths(const TMesh& tmesh, const std::vector<int64_t>& arc_length) {
  for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m) {
    int64_t sum = 0;
    for (int h : tmesh.nonzero_paths[m]) sum += arc_length[TMesh::arc_of(h)];
    if (sum == 0) return "non-zero path " + std::to_string(m) + " has length 0";
  }
  return "";
}

}  // namespace

ArcModel build_arc_model(const TMesh& tmesh, const TMeshIncidence& incidence,
                         const MinOneConstraints& constraints, const ArcModelOptions& options) {
  if (options.relaxed) {
    if (options.coarse)
      throw std::invalid_argument("relaxed quantization has no coarse stage: it collapses no arc");
    if (!(options.relaxed_weight > 0) || !std::isfinite(options.relaxed_weight))
      throw std::invalid_argument("relaxed_weight must be positive and finite");
    if (std::find(options.arc_pattern.begin(), options.arc_pattern.end(), 0) !=
        options.arc_pattern.end())
      throw std::invalid_argument("relaxed quantization cannot fix an arc to 0");
    if (!options.two_gons.empty())
      throw std::invalid_argument("relaxed quantization has no two-gons");
  }
  if (!options.arc_weight.empty() &&
      static_cast<int>(options.arc_weight.size()) != tmesh.num_arcs())
    throw std::invalid_argument("arc_weight needs one weight per arc");
  ArcModel model;
  Problem& pb = model.problem;
  const int np = tmesh.num_patches();
  model.side_node.resize(np);
  model.pair_edge.resize(np);
  std::vector<std::array<int64_t, 2>> pair_lower(np, {0, 0});
  // A side's min-one constraint is its pair edge's lower bound only while the pair edge
  // carries the whole side; relaxed, the arcs' lower bounds of 1 imply it anyway.
  if (!options.relaxed)
    for (const SideRef& s : constraints.sides) pair_lower[s[0]][s[1] % 2] = 1;
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < 4; ++k) model.side_node[p][k] = pb.add_node(0);
  // A pair edge's flow is the patch's width (or height): its deviation from the mean of the
  // two sides' targets is priced too, because the arcs alone cannot see a side whose many
  // short arcs all round the same way (seven arcs of target 0.5 cost the same at 0 as at 1
  // each, but the side of target 3.5 is then 0 or 7).
  for (int p = 0; p < np; ++p)
    for (int pair = 0; pair < 2; ++pair) {
      const double t = 0.5 * (side_target(tmesh, p, pair) + side_target(tmesh, p, pair + 2));
      const Cost cost = options.coarse ? Cost::zero()
                        : options.cost == DeviationCost::Quadratic
                            ? Cost::quad_deviation(t, options.side_weight)
                            : Cost::abs_deviation(t, options.side_weight);
      model.pair_edge[p][pair] = pb.add_edge(
          {model.side_node[p][pair], false}, End{model.side_node[p][pair + 2], false},
          pair_lower[p][pair], kInfinity, options.side_weight > 0 ? cost : Cost::zero());
    }
  // Fig. 10c's corner edges: flow entering side k may leave through side k ± 1, so side k's
  // length is its pair edge's flow plus its two corner edges' flows.
  if (options.relaxed) {
    model.corner_edge.resize(np);
    for (int p = 0; p < np; ++p)
      for (int k = 0; k < 4; ++k)
        model.corner_edge[p][k] =
            pb.add_edge({model.side_node[p][k], false}, End{model.side_node[p][(k + 1) % 4], false},
                        0, kInfinity, Cost::linear(options.relaxed_weight));
  }
  // Relaxed: every arc ≥ 1 — zero arcs next to irregular patches may degenerate (§4.2.4).
  std::vector<int64_t> arc_lower(tmesh.num_arcs(), options.relaxed ? 1 : 0);
  std::vector<int64_t> arc_upper(tmesh.num_arcs(), kInfinity);
  for (int a : constraints.arcs) arc_lower[a] = std::max<int64_t>(arc_lower[a], 1);
  for (int a : constraints.arcs_two) arc_lower[a] = 2;
  if (!options.arc_pattern.empty())
    for (int a = 0; a < tmesh.num_arcs(); ++a) {
      if (options.arc_pattern[a] == 0) arc_lower[a] = arc_upper[a] = 0;
      if (options.arc_pattern[a] == 1) arc_lower[a] = std::max<int64_t>(arc_lower[a], 1);
    }
  // Where a two-gon's half-arcs end: exact, at the node of their side, which the two-gon's edge
  // joins; bounded, at the ladder's node of their position, entering from the first side and
  // leaving to the second.
  std::vector<End> border_end(tmesh.num_half_arcs(), End{-1, true});
  if (!options.two_gon_aligned.empty() && options.two_gon_aligned.size() != options.two_gons.size())
    throw std::invalid_argument("two_gon_aligned needs one entry per two-gon");
  for (size_t t = 0; t < options.two_gons.size(); ++t) {
    const auto& sides = options.two_gons[t];
    const size_t n = sides[0].size();
    // An aligned two-gon is a ladder without rungs: every position passes its half-arc across.
    const bool aligned = !options.two_gon_aligned.empty() && options.two_gon_aligned[t];
    const bool ladder = options.two_gon_reorder_weight >= 0 || aligned;
    if (ladder && sides[1].size() != n)
      throw std::invalid_argument("a bounded two-gon needs as many half-arcs on either side");
    // Exact with two overlapping paths: a chain of nodes per side (position p's half-arc
    // enters node p of its side), so that each side's prefix and suffix sums are edges.
    const std::array<int, 2> split =
        t < options.two_gon_split.size() ? options.two_gon_split[t] : std::array<int, 2>{-1, -1};
    const bool chains = !ladder && split[0] >= 0;
    if (chains && !(sides[1].size() == n && 0 < split[1] && split[1] < split[0] &&
                    split[0] < static_cast<int>(n)))
      throw std::invalid_argument("two-gon " + std::to_string(t) + ": overlap split (" +
                                  std::to_string(split[0]) + ", " + std::to_string(split[1]) +
                                  ") does not fit its " + std::to_string(n) + " half-arcs");
    std::vector<int> nodes;
    for (size_t i = 0; i < (ladder ? n : chains ? 2 * n + 2 : 2); ++i)
      nodes.push_back(pb.add_node(0));
    for (int c = 0; c < 2; ++c)
      for (size_t i = 0; i < sides[c].size(); ++i) {
        const int h = sides[c][i];
        if (h < 0 || h >= tmesh.num_half_arcs() || !incidence.is_border(h) ||
            border_end[h].node >= 0)
          throw std::invalid_argument("two-gon half-arc " + std::to_string(h) +
                                      " is not a border half-arc of one two-gon");
        const size_t position = c == 0 ? i : n - 1 - i;
        border_end[h] = ladder   ? End{nodes[position], c == 0}
                        : chains ? End{nodes[2 + c * n + position], true}
                                 : End{nodes[c], true};
      }
    if (chains) {
      // Side c's chain flows into its hub (node c) at a vertex position k: forward from the
      // tail (the edge from position p < k carrying the prefix sum to vertex p + 1), backward
      // from the head (suffix sums). The first path is the second side's prefix to split[0],
      // the second path the first side's suffix from split[1]: lower bound 1 on those edges.
      for (int c = 0; c < 2; ++c) {
        const int k = split[1 - c], base = 2 + c * static_cast<int>(n);
        for (int p = 0; p < static_cast<int>(n); ++p) {
          const int to = p + 1 == k ? c : p < k ? base + p + 1 : p == k ? c : base + p - 1;
          const bool measured = (c == 1 && p + 1 == k) || (c == 0 && p == k);
          pb.add_edge({nodes[base + p], false}, End{nodes[to], true}, measured ? 1 : 0, kInfinity,
                      Cost::zero());
        }
      }
      model.two_gon_edge.push_back(
          pb.add_edge({nodes[0], false}, End{nodes[1], false}, 0, kInfinity, Cost::zero()));
      continue;
    }
    if (!ladder) {
      model.two_gon_edge.push_back(
          pb.add_edge({nodes[0], false}, End{nodes[1], false}, 1, kInfinity, Cost::zero()));
      continue;
    }
    if (options.two_gon_reorder_weight < 0) model.two_gon_edge.push_back(-1);
    for (size_t i = 0; !aligned && i + 1 < n; ++i) {
      // The offset between nodes i and i + 1 is that at the path's vertex i + 1.
      if (t < options.two_gon_pinned.size() && i + 1 < options.two_gon_pinned[t].size() &&
          options.two_gon_pinned[t][i + 1])
        continue;
      for (const auto& [from, to] : {std::pair{nodes[i], nodes[i + 1]}, {nodes[i + 1], nodes[i]}})
        model.drift_edges.push_back(pb.add_edge({from, false}, End{to, true}, 0, kInfinity,
                                                Cost::linear(options.two_gon_reorder_weight)));
    }
  }
  model.arc_edge.resize(tmesh.num_arcs());
  for (int a = 0; a < tmesh.num_arcs(); ++a) {
    std::vector<End> ends;
    double across = 0;  // the coarse weight: half the extent of each patch across the arc
    for (int h : {2 * a, 2 * a + 1}) {
      const int p = incidence.half_arc_patch[h];
      if (p < 0) {
        if (border_end[h].node >= 0) ends.push_back(border_end[h]);
        continue;
      }
      const int k = incidence.half_arc_side[h];
      ends.push_back({model.side_node[p][k], true});
      across += 0.5 * side_target(tmesh, p, (k + 1) % 4);
    }
    const double t = tmesh.arc_target[a];
    const double w = options.arc_weight.empty() ? 1.0 : options.arc_weight[a];
    Cost cost = options.coarse                             ? Cost::linear(std::max(across, 1e-3))
                : options.cost == DeviationCost::Quadratic ? Cost::quad_deviation(t, w)
                                                           : Cost::abs_deviation(t, w);
    model.arc_edge[a] = ends.size() == 2
                            ? pb.add_edge(ends[0], ends[1], arc_lower[a], arc_upper[a], cost)
                            : pb.add_edge(ends[0], std::nullopt, arc_lower[a], arc_upper[a], cost);
  }
  return model;
}

std::vector<int64_t> arc_lengths(const ArcModel& model, const std::vector<int64_t>& flow) {
  std::vector<int64_t> lengths(model.arc_edge.size());
  for (size_t a = 0; a < lengths.size(); ++a) lengths[a] = flow[model.arc_edge[a]];
  return lengths;
}

std::string check_quantization(const TMesh& tmesh, const std::vector<int64_t>& arc_length) {
  if (static_cast<int>(arc_length.size()) != tmesh.num_arcs())
    return "expected " + std::to_string(tmesh.num_arcs()) + " arc lengths, got " +
           std::to_string(arc_length.size());
  for (int a = 0; a < tmesh.num_arcs(); ++a)
    if (arc_length[a] < 0)
      return "arc " + std::to_string(a) + ": negative length " + std::to_string(arc_length[a]);
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k = 0; k < 2; ++k) {
      const int64_t x = side_length(tmesh, p, k, arc_length);
      const int64_t y = side_length(tmesh, p, k + 2, arc_length);
      if (x != y)
        return "patch " + std::to_string(p) + ": sides " + std::to_string(k) + " and " +
               std::to_string(k + 2) + " have lengths " + std::to_string(x) + " and " +
               std::to_string(y);
    }
  return check_nonzero_paths(tmesh, arc_length);
}

std::string check_relaxed_quantization(const TMesh& tmesh, const std::vector<int64_t>& arc_length) {
  if (static_cast<int>(arc_length.size()) != tmesh.num_arcs())
    return "expected " + std::to_string(tmesh.num_arcs()) + " arc lengths, got " +
           std::to_string(arc_length.size());
  for (int a = 0; a < tmesh.num_arcs(); ++a)
    if (arc_length[a] < 1)
      return "arc " + std::to_string(a) + ": length " + std::to_string(arc_length[a]) +
             ", relaxed quantization needs ≥ 1";
  for (int p = 0; p < tmesh.num_patches(); ++p) {
    std::array<int64_t, 4> x;
    for (int k = 0; k < 4; ++k) x[k] = side_length(tmesh, p, k, arc_length);
    // Sides are non-empty paths of arcs ≥ 1, so only the parity can fail; still checked,
    // as this check must not trust the T-mesh's validation either.
    for (int k = 0; k < 4; ++k)
      if (x[k] < 1)
        return "patch " + std::to_string(p) + ": side " + std::to_string(k) + " has length " +
               std::to_string(x[k]);
    if ((x[0] + x[1] + x[2] + x[3]) % 2 != 0)
      return "patch " + std::to_string(p) + ": perimeter " + std::to_string(x[0]) + " + " +
             std::to_string(x[1]) + " + " + std::to_string(x[2]) + " + " + std::to_string(x[3]) +
             " = " + std::to_string(x[0] + x[1] + x[2] + x[3]) + " is odd";
  }
  return check_nonzero_paths(tmesh, arc_length);
}

bool is_irregular_patch(const TMesh& tmesh, int patch, const std::vector<int64_t>& arc_length) {
  for (int k = 0; k < 2; ++k)
    if (side_length(tmesh, patch, k, arc_length) != side_length(tmesh, patch, k + 2, arc_length))
      return true;
  return false;
}

}  // namespace bimdf::tmesh
