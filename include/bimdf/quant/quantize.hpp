// Quantizing a patch layout (layout.hpp) with Bi-MDF: every subside gets a positive integer
// length so that each chart admits an all-quad pattern, close to its target length and, where
// possible, to the regular pattern of its valence with singularities aligned across chains of
// quads — the model of QuadWild-BiMDF (paper §4.4; ../shared/reference/quadwild_modeling.md §3).
//
// The model: one node per chart side (two "half" nodes for a side on an alignment chain); each
// subside is a path of edges carrying its length into the side nodes of its charts, with the
// quadratic isometry cost α/n_c·(x − t)² per chart; inside a chart, tail–tail "strip" edges
// consume the side lengths pairwise as the regular pattern does (every chart perimeter is
// therefore even), and priced emergency edges (side loops, neighbour and opposite edges,
// singularity-on-boundary edges) absorb any irregularity at the regularity cost the
// QuadWild IQP would charge. Alignment chains get unaligner edges priced per unit of
// misalignment. A second round drops the pairs the first could not align (note §3.7).
//
// Defaults reproduce the reference configuration `flow.txt` + `flow_virtual_simple.json`.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"
#include "bimdf/quant/layout.hpp"
#include "bimdf/solution.hpp"
#include "bimdf/solve.hpp"

namespace bimdf::quant {

enum class IsoObjective { Quadratic, Absolute };

// Costs of the virtual subside edges of alignment chains (note §3.6), per round.
struct PairedWeights {
  double iso_weight = 1;
  IsoObjective iso_objective = IsoObjective::Quadratic;
  double unalign_weight = 2;
};

// ModelOptions::min_border_loop for `remesh` (CLI and Python): every hole keeps 3 edges or more.
inline constexpr int kRemeshMinBorderLoop = 3;

struct ModelOptions {
  double alpha = 0.005;         // isometry weight; regularity gets 1 − alpha
  double nonquad_weight = 0.9;  // regularityNonQuadrilateralsWeight
  double align_weight = 0.1;    // alignSingularitiesWeight
  // "simple" virtual targets: a triangle's paired side is split where its regular pattern's
  // separatrix meets it; false: "half" (split in the middle; no isometry on quads).
  bool simple_targets = true;
  // Quads along every border loop, at least: a loop quantized to 1 or 2 edges is no hole of a
  // quad mesh (the standalone remesher's layouts of ChineseDragon-10kv and mannequin-devil
  // lost a hole so). A loop of k border subsides gets a lower bound of ⌈min_border_loop / k⌉
  // on each. 1 (the default): every subside at least 1, the reference quantizer's model, which
  // `bimdf quantize` reproduces; remeshing uses kRemeshMinBorderLoop.
  int min_border_loop = 1;
};

// A chain of quads between two singular charts (valence 3, 5 or 6), crossing one subside per
// step: sides[i] = (chart, side) in walking order, from the first singular chart's side to the
// last one's. Every side on the chain has exactly one subside.
struct AlignmentPair {
  std::vector<std::array<int, 2>> sides;
};

// Chains of note §3.5: from every side with one subside of every singular chart, through quads
// (entering a side, leaving by the opposite one) to the next singular chart; chains reaching
// the border or a side with several subsides are dropped, each chain kept once.
std::vector<AlignmentPair> find_alignment_pairs(const Layout& layout);

// The strip edges of one family of a chart (sides j and j+2) and their parallel
// singularity-on-boundary edges, each unit of which cancels a strip.
struct StripEdges {
  std::vector<int> strips, cancels;
};

// A round's Bi-MDF problem and how to read subside lengths back from its flow.
struct FlowModel {
  Problem problem;
  // Per subside: the edges whose flows sum to its length.
  std::vector<std::vector<int>> subside_edges;
  // Per subside on a chain: its two virtual edges on each chart's side, [chart slot][half];
  // −1 for unpaired subsides. Used for the second round's new targets.
  std::vector<std::array<std::array<int, 2>, 2>> virtual_edges;
  // Per chart, per strip family (quads: 2, others: one per side).
  std::vector<std::vector<StripEdges>> chart_strips;
  int boundary_node = -1;
};

// Builds the model. `targets[s]`: subside s's target length in quads (max(1, length/ℓ));
// `edge_length`: ℓ; `pairs`: alignment chains (empty: no alignment); `paired`: the cost of
// their virtual edges; `virtual_targets`: per subside on a chain, [chart slot][half] target
// (empty: computed from the layout as the options say); `regularity_off[c]`: chart c gets no
// regularity cost (round 2 of note §3.7; may be empty).
FlowModel build_flow_model(
    const Layout& layout, const std::vector<double>& targets, double edge_length,
    const std::vector<AlignmentPair>& pairs, const ModelOptions& options,
    const PairedWeights& paired,
    const std::vector<std::array<std::array<double, 2>, 2>>& virtual_targets = {},
    const std::vector<bool>& regularity_off = {});

// Subside lengths from a flow of the model.
std::vector<int64_t> read_subside_lengths(const FlowModel& model, const std::vector<int64_t>& flow);

// The number of quads each chart's pattern will have, from the strip counts of a flow: the
// regular pattern's corner grids, exact for regular charts; irregular charts are scaled to
// their perimeter (an estimate until the padded pattern is built).
std::vector<double> estimate_quads(const Layout& layout, const FlowModel& model,
                                   const std::vector<int64_t>& flow,
                                   const std::vector<int64_t>& lengths);

// QuadWild-style evaluation of a quantization (note §4.4).
struct Energies {
  double isometry = 0;    // α Σ_c Σ_{s∈c} (t_s − x_s)² / n_c
  double regularity = 0;  // Σ_c irregularity_c · (1−α)/k² (·w_nq for k ≠ 4, ·½ for k = 6)
  double alignment = 0;   // Σ_pairs (1−α)·w_align·½(|v1|+|v2|)/k², over both end charts
  int regular_charts = 0;    // charts of irregularity 0
  int satisfied_charts = 0;  // irregularity 0 (quads) or ≤ 1 (a singularity on the boundary)
  int charts = 0;
  int aligned_pairs = 0;  // pairs whose separatrix positions match (v1 = v2 = 0)
  int pairs = 0;
  // Per pair: aligned and every chart on its chain satisfied (what round 2 keeps).
  std::vector<bool> pair_satisfied;
};

// Irregularity of chart c given its side lengths (note §3.7): quads Σ_j|S_j − S_{j+2}|;
// triangles, pentagons, hexagons Σ_j of how far the regular pattern's strict inequality j is
// violated; hexagons add one per odd alternate-side triple per j.
int64_t chart_irregularity(const std::vector<int64_t>& side_lengths);

// Side lengths S_j of chart c from subside lengths.
std::vector<int64_t> side_lengths(const Layout& layout, int c, const std::vector<int64_t>& lengths);

Energies evaluate_quantization(const Layout& layout, const std::vector<double>& targets,
                               const std::vector<int64_t>& lengths,
                               const std::vector<AlignmentPair>& pairs,
                               const ModelOptions& options);

// Everything `quantize` needs beyond the layout. Defaults: the reference configuration.
struct QuantizeOptions {
  ModelOptions model;
  // The target edge length ℓ: `edge_length` if > 0; else, if `target_faces` > 0, the ℓ at
  // which the quantization gives about that many quads (estimate_quads; within 1% where the
  // layout allows, found by up to 9 quantizations); else
  // QuadWild's average triangle edge × `scale`.
  double scale = 1;
  double edge_length = 0;
  int64_t target_faces = 0;
  bool align = true;  // alignment chains (note §3.5)
  // Round 2 (note §3.7): when round 1 leaves a chart or pair unsatisfied, drop the unaligned
  // pairs and solve again with `resolve` weights (and, with `resolve_new_targets`, split
  // targets taken from round 1's split positions). Only with `align`, as in the reference.
  bool second_round = true;
  bool resolve_new_targets = true;
  PairedWeights initial{1, IsoObjective::Quadratic, 2};
  PairedWeights resolve{1, IsoObjective::Absolute, 4};
  int threads = 1;  // for the exact solver's components
  // The exact solver's perfect matching. LEMON by default here: the blossom solver reaches the
  // same optimum but may pick another of several optimal quantizations, and on the shared
  // layouts LEMON's choice is the one the remesh tables and tests were measured with (one
  // mannequin-devil chart tessellates with an inverted quad under the other choice).
  MatchingBackend matching = MatchingBackend::Lemon;
  // The exact solver's approximation before chain collapse (Solver::approximate_unchained). On
  // here for the same reason: with the faster chained approximation refinement ends at another
  // optimal quantization of mannequin-devil, under which one chart (290) keeps an inverted quad.
  bool approximate_unchained = true;
  double time_limit = -1;  // seconds per solve; < 0 unlimited (then status may be Feasible)
};

struct QuantizationRound {
  FlowModel model;
  Solution solution;  // of model.problem
  std::vector<int64_t> lengths;
  Energies energies;
  std::vector<AlignmentPair> pairs;
  double estimated_quads = 0;  // see estimate_quads
  double time_model_s = 0, time_solve_s = 0;
};

struct Quantization {
  double edge_length = 0;
  std::vector<double> targets;            // per subside, max(1, length/ℓ)
  std::vector<QuantizationRound> rounds;  // 1 or 2; the last one is the result

  const QuantizationRound& final_round() const { return rounds.back(); }
  const std::vector<int64_t>& lengths() const { return rounds.back().lengths; }
};

// The target edge length ℓ the options ask for; for `target_faces`, the starting point of
// quantize's search (see QuantizeOptions).
double target_edge_length(const Layout& layout, const QuantizeOptions& options);

// Solves the model exactly (one or two rounds). Every subside length is ≥ 1 and every chart
// perimeter even and ≥ 4; throws std::runtime_error if a solve fails (not expected: the
// emergency edges keep every model feasible) or a result breaks those rules.
Quantization quantize(const Layout& layout, const QuantizeOptions& options);

}  // namespace bimdf::quant
