// Quantizing a quadrangular T-mesh (tmesh.hpp) with Bi-MDF (paper §4.2): every arc gets a
// non-negative integer length, opposite sides of every patch sum equally (so each patch is a
// regular grid, or collapses when a side pair is 0), and every non-zero path keeps a length of
// at least 1.
//
// The model (Fig. 10b): four side nodes per patch; an inner tail–tail edge between the nodes of
// each pair of opposite sides, whose flow is the pair's common length; one edge per arc with a
// head at the side node of each of its half-arcs' sides — two heads inside the T-mesh, one on
// the border (an outer edge, §3.2.1). Conservation at a side node makes its side's arcs sum to
// the pair's inner flow. Arcs have lower bound 0: zero-length arcs are allowed.
//
// Non-zero paths are not modelled exactly: Algorithm 2 (§4.2.3) picks a small set of arcs and
// sides whose min-one lower bounds imply every path's — greedily, sides with the longest
// target first, over the non-zero implication graph (arc ⊂ side/path, side ⊂ path, path ⊂
// path, side → opposite side), deleting what each search visits so that the whole pass is
// linear. Paths that contain no whole side are covered by one of their arcs.
//
// Costs: the deviation of each arc from its target, quadratic (x − t)² by default or absolute
// |x − t|, plus the same deviation, weighted by `side_weight`, of each patch's width and height
// (the inner edges' flows) from the mean of its two sides' targets. The coarse objective (Lyon et
// al. 2021's) is linear instead: each arc costs, per unit of length, half the target extent of each
// of its patches across it (the other side pair's target), which approximates the total length of
// the layout's lines — the coarsest layout the non-zero paths allow.
//
// Relaxed quantization (§4.2.4, Fig. 10c; `relaxed`): each patch also gets a tail–tail *corner
// edge* between the side nodes of each pair of adjacent sides (k, k+1), lower bound 0, no upper
// bound, linear cost `relaxed_weight` per unit. Flow may then turn a corner instead of crossing
// the patch, so opposite sides may differ: side k's length is its pair edge's flow plus its two
// corner edges' flows. Every patch still has an even perimeter (twice the sum of its inner
// edges' flows) and no side longer than the other three together, so make_quad_pattern
// (quant/pattern.hpp) tessellates it. Self-loops and the single-node template of Fig. 10d,
// which would also allow a side longer than the other three, are not modelled. The pair edges
// keep their `side_weight` deviation, which in a relaxed patch prices the straight-through
// flow only: a turn then pays that deviation too.
//
// Relaxed quantization and zero-length arcs do not mix (§4.2.4: an irregular patch with zero
// sides can degenerate, and collapsing one is not defined), so in relaxed mode every arc has
// lower bound 1: nothing collapses, every side is ≥ 1 and every non-zero path holds without
// Algorithm 2's constraints (still computed and reported). A relaxed quantization is checked
// by check_relaxed_quantization; the coarse objective, whose point is zero arcs, is refused.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"
#include "bimdf/solution.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

enum class DeviationCost { Quadratic, Absolute };

// A side of a patch: (patch, side index 0..3).
using SideRef = std::array<int, 2>;

// Min-one constraints: arcs and sides whose length must be ≥ 1.
struct MinOneConstraints {
  std::vector<int> arcs;
  std::vector<SideRef> sides;
  // Arcs whose length must be ≥ 2: the longer arc of a border loop of two arcs, which would
  // otherwise close into a two-edge hole, and an arc along a quad left inverted with every
  // corner pinned, which then splits in two (separation repair, requantize.hpp).
  std::vector<int> arcs_two;
  int size() const { return static_cast<int>(arcs.size() + sides.size() + arcs_two.size()); }
};

// Appends `extra`'s bounds to `to`'s.
void add_constraints(MinOneConstraints& to, const MinOneConstraints& extra);

// Algorithm 2 on the T-mesh's nonzero_paths (`incidence` from validate_tmesh). Side target
// lengths are their arcs' summed targets. Deterministic: ties broken by patch, side and arc id.
// With `cover`: per path, the bound whose search covered it — an index into the result's
// sides, or sides.size() + an index into its arcs.
MinOneConstraints greedy_min_one_constraints(const TMesh& tmesh, const TMeshIncidence& incidence,
                                             std::vector<int>* cover = nullptr);

struct ArcModelOptions {
  DeviationCost cost = DeviationCost::Quadratic;
  bool coarse = false;  // the linear coarse objective instead of the deviation
  // Weight of each patch's width and height deviating from their sides' mean target (same
  // kind of cost as the arcs'); 0: arcs only.
  double side_weight = 1;
  // Optional, one entry per arc: −1 free, 0 fixed to 0, 1 at least 1 (empty: all free).
  std::vector<int8_t> arc_pattern;
  // Fig. 10c's corner edges (see above): every arc ≥ 1, irregular patches allowed. With
  // coarse, or an arc_pattern entry 0, build_arc_model throws std::invalid_argument.
  bool relaxed = false;
  // Cost per unit of flow turning a corner, > 0. The default 1 prices one turn like one
  // quad edge of absolute deviation on an arc — a turn adds two irregular vertices to the
  // patch, so it should cost about what a unit of rounding does; smaller values favour
  // irregular patches, larger ones regular grids.
  double relaxed_weight = 1;
  // Optional, one entry per arc: the weight of its deviation cost (empty: 1 each). Half-arc
  // quantization gives each copy of a cut arc ½, so that equal copies cost what the arc did.
  std::vector<double> arc_weight;
  // Virtual two-gons (half_arc.hpp): per two-gon, its two sides, chains of border half-arcs
  // each walked with the two-gon on its left (a Zip, collapse.hpp: the first from the path's
  // tail, the second back from its head). Their arcs' edges end at the two-gon (instead of being
  // outer edges). With two_gon_reorder_weight < 0 (exact, Fig. 12a) each side gets a node and
  // the two nodes an edge of lower bound 1 and no cost, whose flow is then both sides' length.
  // With a weight w ≥ 0 (bounded, Fig. 12b) the two-gon is a ladder instead: a node per
  // position i along the path, where the i-th half-arc of one side enters and the other's
  // leaves, and between consecutive nodes the offset d (how far the sides' vertices there have
  // drifted apart, either way) at cost w·|d|; no min-one. Not with `relaxed`.
  std::vector<std::array<std::vector<int>, 2>> two_gons;
  double two_gon_reorder_weight = -1;
  // Bounded only (optional, per two-gon and position 0..n along its path): 1 where the offset
  // must stay 0.
  std::vector<std::vector<char>> two_gon_pinned;
  // Optional, per two-gon: 1 where its sides must equal half-arc by half-arc (an arc
  // quantization along that path: no drift, no min-one of its own — give it bounds), whatever
  // the weight; exact or bounded.
  std::vector<char> two_gon_aligned;
  // Optional, per two-gon: {e, s} for two overlapping paths held by one exact two-gon
  // (half_arc.hpp; vertex positions 0..n along the path): the first, from the path's tail to
  // its vertex e, measured by the second side's half-arcs up to e (the left copies), the second,
  // from vertex s to the head, by the first side's from s (the right copies); 0 < s < e < n.
  // Each sum is one edge of lower bound 1. {−1, −1}: one path, the whole length.
  std::vector<std::array<int, 2>> two_gon_split;
  // Bounded two-gons whose drift cost only breaks ties (the exact model's tie-break,
  // quantize_inflated): the objectives reported leave it out.
  bool two_gon_drift_tie_break = false;
};

struct ArcModel {
  Problem problem;
  std::vector<int> arc_edge;                  // per arc: its network edge
  std::vector<std::array<int, 2>> pair_edge;  // per patch: inner edge of sides 0/2, of 1/3
  std::vector<std::array<int, 4>> side_node;  // per patch and side
  // Relaxed only (else empty): per patch, the corner edge between sides k and k+1 (mod 4).
  std::vector<std::array<int, 4>> corner_edge;
  std::vector<int> two_gon_edge;  // exact two-gons: per two-gon, the edge between its nodes
                                  // (−1 where aligned)
  std::vector<int> drift_edges;   // bounded two-gons: the rungs, each carrying one way's drift
};

// Builds the Bi-MDF problem with the min-one constraints as lower bounds of 1.
ArcModel build_arc_model(const TMesh& tmesh, const TMeshIncidence& incidence,
                         const MinOneConstraints& constraints, const ArcModelOptions& options);

// The arc lengths of a flow of `model`.
std::vector<int64_t> arc_lengths(const ArcModel& model, const std::vector<int64_t>& flow);

// Checks a quantization against the T-mesh, independently of any model: one length per arc,
// all ≥ 0, opposite sides of every patch equal, every non-zero path ≥ 1. Returns "" when
// valid, else the first violation ("patch 3: sides 0 and 2 have lengths 4 and 5").
std::string check_quantization(const TMesh& tmesh, const std::vector<int64_t>& arc_length);

// The same for a relaxed quantization: one length per arc, all ≥ 1 (relaxed mode collapses
// nothing), every patch's perimeter even and every side ≥ 1 — what make_quad_pattern needs —
// and every non-zero path ≥ 1. Opposite sides may differ. Returns "" when valid, else the
// first violation ("patch 3: perimeter 4 + 1 + 2 + 2 = 9 is odd").
std::string check_relaxed_quantization(const TMesh& tmesh, const std::vector<int64_t>& arc_length);

// Whether a patch has a pair of opposite sides of different lengths (an irregular patch of a
// relaxed quantization).
bool is_irregular_patch(const TMesh& tmesh, int patch, const std::vector<int64_t>& arc_length);

// The number of quads a quantization tessellates into: Σ width × height over the patches (0
// for a collapsed one). An irregular patch (relaxed) counts the product of its two side pairs'
// mean lengths, about what its pattern has.
double quantized_quads(const TMesh& tmesh, const std::vector<int64_t>& arc_length);

// The same for the arc targets: the quad count the targets ask for (for a T-mesh traced on a
// quad mesh, its quads times the density squared).
double target_quads(const TMesh& tmesh);

struct QuantizeOptions {
  DeviationCost cost = DeviationCost::Quadratic;
  double side_weight = 1;  // ArcModelOptions::side_weight
  // Min-one bounds added to Algorithm 2's (e.g. by requantize's separation repair).
  MinOneConstraints extra_constraints;
  // Coarse layout: first the coarse objective decides which arcs are 0; then either (default)
  // the same model with that pattern fixed (zero arcs 0, others ≥ 1) and the deviation costs
  // gives the lengths at the T-mesh's target density, or (coarse_uniform) the coarse lengths
  // are multiplied by one integer.
  bool coarse = false;
  // With `coarse`: instead of the second solve, multiply every coarse length by one integer
  // (chosen for the targets' total area), which keeps the coarse layout's base complex.
  bool coarse_uniform = false;
  // With coarse_uniform: one integer per strip of the coarse tessellation instead of one for
  // all, each fitted to the input's size along its strip (src/tmesh/strip_lengths.hpp); the base
  // complex is still the coarse layout's. (RequantizeOptions::refit_uniform may drop it for one
  // factor where smoothing leaves quads bad; TMeshQuantization::strip_lengths says what was used.)
  bool coarse_strips = false;
  // ArcModelOptions::relaxed / relaxed_weight; the result is checked with
  // check_relaxed_quantization. relaxed with coarse throws std::invalid_argument.
  bool relaxed = false;
  double relaxed_weight = 1;
  int threads = 1;
  double time_limit = -1;  // seconds per solve, < 0: none
};

struct TMeshQuantization {
  SolveStatus status = SolveStatus::Infeasible;
  double objective = 0;         // of the (last) model solved
  double coarse_objective = 0;  // the coarse stage's, when coarse
  int64_t coarse_factor = 0;    // with coarse_uniform: the factor k (strips: their mean, ≥ 1)
  bool strip_lengths = false;   // the lengths are one integer per strip (coarse_strips)
  std::vector<int64_t> arc_length;
  MinOneConstraints constraints;
  int zero_arcs = 0;
  int irregular_patches = 0;  // patches whose opposite sides differ (relaxed only)
  int nodes = 0, edges = 0;   // of the model
  double time_model_s = 0, time_solve_s = 0;
  Solution solution;  // the last solve's (stats for -v)
};

// Builds the model, solves it exactly and checks the result (check_quantization; a failure
// throws std::logic_error, it would be a bug). status Infeasible: no valid quantization
// exists (the solver's proof is in solution.stats).
TMeshQuantization quantize_tmesh(const TMesh& tmesh, const TMeshIncidence& incidence,
                                 const QuantizeOptions& options);

}  // namespace bimdf::tmesh
