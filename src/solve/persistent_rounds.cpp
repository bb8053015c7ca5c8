#include "solve/persistent_rounds.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "backend/blossom_matching.hpp"
#include "core/deep_stack.hpp"
#include "core/stopwatch.hpp"
#include "reduce/bimcf.hpp"
#include "reduce/bmatching.hpp"
#include "reduce/linearize.hpp"
#include "reduce/matching_gadgets.hpp"
#include "solve/refine.hpp"
#include "solve/residual_pruning.hpp"

namespace bimdf::detail {
namespace {

// Slots per edge: 0, 1 forward by 1 and 2; 2, 3 backward by 1 and 2 (refine.hpp: U = 2).
constexpr int kSlots = 4;
// Bits of the LP's cost bound left unused, so that the slopes of later rounds may grow to 4×
// the first round's largest before a weight leaves the blossom solver's bound.
constexpr int kHeadroomBits = 2;

struct Slot {
  bool enabled = false;
  double cost = 0;  // per unit
};

// Slot s of edge e around flow x, priced as linearize.hpp prices unit pieces.
Slot slot(const Problem& p, int e, int64_t x, int s) {
  const int64_t k = s % 2 + 1;  // the step from deviation k − 1 to k
  const int direction = s < 2 ? +1 : -1;
  if (deviation_room(p, e, x, direction) < k) return {};
  return {true, piece_cost(CostAlong{p.cost[e], x, direction}, k - 1, 1)};
}

}  // namespace

struct PersistentRounds::State {
  std::vector<int64_t> x;  // the flow the slots are priced around
  double scale = 1;        // the first round's LP cost scale, kept for every weight
  BMatchingReduction bm;
  MatchingReduction mm;
  std::vector<int> bedge_of_arc;
  std::unique_ptr<BlossomMatching> solver;

  // The doubled integer weight of a matching edge (refine.hpp). Later rounds keep the first
  // round's scale, so a slope far steeper than any then seen could leave int64: such a weight
  // throws, and refinement falls back to fresh rounds.
  int64_t weight(double w) const { return doubled_matching_weight(w, scale); }

  // The end of b-edge be's block of matching edges (matching_gadgets.hpp).
  int block_end(int be) const {
    return be + 1 < bm.bmatching.num_edges() ? mm.first_edge_of_bedge[be + 1]
                                             : mm.graph.num_edges();
  }
  // The matching edges that carry b-edge be's weight (gadgets: its L–copy edges).
  template <typename Visit>
  void weighted_edges(int be, const Visit& visit) const {
    for (int k = mm.first_edge_of_bedge[be]; k < block_end(be); ++k)
      if (mm.bedge_of_edge[k] == be) visit(k);
  }
};

PersistentRounds::PersistentRounds(const Problem& problem, bool hub_throughflow)
    : problem_(problem), hub_throughflow_(hub_throughflow) {}
PersistentRounds::~PersistentRounds() = default;

PersistentRound PersistentRounds::round(std::span<const int64_t> flow,
                                        const std::vector<double>& start_potential) {
  const Problem& p = problem_;
  const int m = p.num_edges();
  PersistentRound out;
  auto t = std::chrono::steady_clock::now();
  const bool resume = state_ && state_->solver;
  if (!resume) {
    state_ = std::make_unique<State>();
    State& s = *state_;
    s.x.assign(flow.begin(), flow.end());
    // The residual with every slot (capacity 1) is the matching's shape; `enabled` says which
    // slots the bounds allow at present.
    BiMcf shape;
    std::vector<char> enabled;
    shape.demand.assign(p.num_nodes(), 0);
    for (int e = 0; e < m; ++e) {
      const End a = p.end_a[e], b = p.end_b[e];
      for (int k = 0; k < kSlots; ++k) {
        const Slot sl = slot(p, e, s.x[e], k);
        shape.end_a.push_back(k < 2 ? a : End{a.node, !a.head});
        shape.end_b.push_back(k < 2 ? b : End{b.node, !b.head});
        shape.capacity.push_back(1);
        shape.cost.push_back(sl.cost);
        enabled.push_back(sl.enabled);
      }
    }
    // The LP is a classic round's (linearize.hpp: equal prices merged, disabled slots absent,
    // half the arcs), its flow then spread over the slots in order.
    const Linearization lin = linearize(p, s.x, refinement_pieces());
    out.time_build_s += seconds_since(t);
    t = std::chrono::steady_clock::now();
    const ResidualLp lp =
        solve_residual_lp(lin.mcf, start_potential, lp_scale_log2(shape) - kHeadroomBits);
    out.lp_solved = true;
    out.lp_method = lp.lp_method;
    out.lp_potential = lp.potential;
    out.time_lp_s = seconds_since(t);
    if (lp.proves_optimal) {
      out.proves_optimal = true;
      state_.reset();
      return out;
    }
    t = std::chrono::steady_clock::now();
    s.scale = lp.cost_scale;
    // The throughflow limits of a classic first round (its arc counts: merged, enabled only).
    Throughflow throughflow;
    if (hub_throughflow_) {
      throughflow = refinement_throughflow(lin.mcf);
    } else {
      throughflow.limit.assign(p.num_nodes(), 2);
    }
    out.max_throughflow = *std::max_element(throughflow.limit.begin(), throughflow.limit.end());
    s.bm = reduce_to_bmatching(shape, throughflow);
    s.mm = reduce_to_perfect_matching(s.bm.bmatching);
    const BMatching& bm = s.bm.bmatching;
    const MatchingGraph& g = s.mm.graph;
    s.bedge_of_arc.assign(shape.num_arcs(), -1);
    for (int be = 0; be < bm.num_edges(); ++be)
      if (s.bm.arc_of_edge[be] >= 0) s.bedge_of_arc[s.bm.arc_of_edge[be]] = be;
    const std::vector<int64_t> weight = doubled_matching_weights(g.weight, s.scale);
    std::vector<int64_t> bedge_weight = doubled_matching_weights(bm.weight, s.scale);
    // A disabled slot's gadget must start unused and tight (L–R), which gadget_duals gives a
    // b-edge of weight −∞: its L–copy edges impose nothing.
    for (int arc = 0; arc < shape.num_arcs(); ++arc)
      if (!enabled[arc])
        bedge_weight[s.bedge_of_arc[arc]] = std::numeric_limits<int64_t>::min() / 4;
    s.solver = std::make_unique<BlossomMatching>(g.num_nodes, g.end_a, g.end_b, weight);
    for (int arc = 0; arc < shape.num_arcs(); ++arc)
      if (!enabled[arc])
        s.weighted_edges(s.bedge_of_arc[arc],
                         [&](int k) { s.solver->update_edge(k, weight[k], false); });
    // The warm start of a classic round (refine.cpp): the LP's duals, its integral part as
    // used gadgets. The LP may split a unit over both slots of a direction (half on each of two
    // equal prices, one copy each): integral in sum, so the sum's units go to the slots in order.
    std::vector<int64_t> twice(shape.num_arcs(), 0);
    std::vector<int> filled(2 * m, 0);  // slots taken per edge and direction
    for (int a = 0; a < lin.mcf.num_arcs(); ++a) {
      const int e = lin.arc_edge[a], backward = lin.arc_direction[a] < 0;
      int64_t rest = lp.twice_flow[a];
      for (int64_t c = 0; c < lin.mcf.capacity[a]; ++c) {
        const int arc = kSlots * e + 2 * backward + filled[2 * e + backward]++;
        twice[arc] = std::min<int64_t>(rest, 2);
        rest -= twice[arc];
      }
    }
    std::vector<int> used(bm.num_edges(), 0);
    for (int arc = 0; arc < shape.num_arcs(); arc += 2) {
      const int64_t units = (twice[arc] + twice[arc + 1]) / 2;
      used[s.bedge_of_arc[arc]] = static_cast<int>(std::min<int64_t>(units, 1));
      used[s.bedge_of_arc[arc + 1]] = static_cast<int>(units - std::min<int64_t>(units, 1));
    }
    s.solver->initial_duals(round_matching_duals(s.bm, s.mm, lp.node_dual, bedge_weight))
        .initial_matching(gadget_matching(bm, s.mm, used));
  } else {
    // The slots of every edge the last round changed get their new prices, and their gadgets
    // (R, then L) are reopened: the run starts from the zero circulation there, with L and R
    // as low as their edges allow (measured faster than reopening L alone).
    State& s = *state_;
    const MatchingGraph& g = s.mm.graph;
    for (int e = 0; e < m; ++e) {
      if (flow[e] == s.x[e]) continue;
      s.x[e] = flow[e];
      for (int k = 0; k < kSlots; ++k) {
        const Slot sl = slot(p, e, s.x[e], k);
        const int be = s.bedge_of_arc[kSlots * e + k];
        const int64_t w = s.weight(-sl.cost);
        s.weighted_edges(be, [&](int edge) { s.solver->update_edge(edge, w, sl.enabled); });
        for (int edge = s.mm.first_edge_of_bedge[be]; edge < s.block_end(be); ++edge)
          if (s.mm.gadget_of_node[g.end_a[edge]] >= 0 && s.mm.gadget_of_node[g.end_b[edge]] >= 0)
            s.solver->reopen(g.end_b[edge]).reopen(g.end_a[edge]);  // an L–R edge
      }
    }
    out.resumed = true;
  }
  State& s = *state_;
  const MatchingGraph& g = s.mm.graph;
  out.matching_nodes = g.num_nodes;
  out.matching_edges = g.num_edges();
  out.time_build_s += seconds_since(t);
  t = std::chrono::steady_clock::now();
  BlossomMatching::Status status = BlossomMatching::Status::NotRun;
  run_with_stack(matching_stack_bytes(g.num_nodes), [&] { status = s.solver->run(); });
  out.time_matching_s = seconds_since(t);
  if (status != BlossomMatching::Status::Optimal)
    throw std::logic_error("persistent refinement: the residual matching has no perfect matching");
  out.free_vertices = s.solver->free_after_start();
  t = std::chrono::steady_clock::now();
  const std::vector<int> values = s.mm.lift(s.solver->matched_edges(), s.bm.bmatching.num_edges());
  const std::vector<int64_t> arc_flow = s.bm.lift(values, kSlots * m);
  out.next_flow = s.x;
  for (int arc = 0; arc < kSlots * m; ++arc)
    out.next_flow[arc / kSlots] += (arc % kSlots < 2 ? 1 : -1) * arc_flow[arc];
  out.time_build_s += seconds_since(t);
  return out;
}

}  // namespace bimdf::detail
