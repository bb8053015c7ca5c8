// Minimum-cost flow by successive shortest paths from given node potentials: our own solver
// (no LEMON), made to be warm-started, for the directed networks of graph/directed_mcf.hpp.
//
// Problem: arcs with lower bound 0, a capacity (possibly infinite) and an integer cost per
// unit; node supplies (outflow − inflow); find a flow of minimum total cost, or prove that
// none exists. The solver keeps node potentials π and, on the residual network, reduced costs
// r(u→v) = c + π(u) − π(v) that are never negative on an arc with residual capacity
// (complementary slackness), and a pseudo-flow whose imbalances it removes one shortest path
// at a time: from a node with surplus, Dijkstra on the reduced costs until the first node
// with a deficit is settled, potentials of the settled nodes lowered by their distance's
// shortfall to that node's (which keeps every residual reduced cost ≥ 0 and makes the path
// tight), then the path's bottleneck is sent. When no imbalance is left the flow is optimal.
//
// Warm start: `initial_potentials` may be anything (within the bound below). The start
// saturates every arc whose reduced cost is negative and leaves the others empty, so that the
// reduced-cost condition holds at once; good potentials (the previous, similar problem's
// optimum) leave only a small imbalance, which is then all the work. Each search stops at the
// first deficit it reaches, so a local imbalance costs a local search, not a pass over the
// network — the reason this beats a network simplex started from scratch on the refinement
// LPs of solve/refine.cpp, whose optimum moves little from round to round. Near an optimum most
// residual arcs are tight (reduced cost 0), so a search settles most nodes at the distance it
// is settling already: those go on a stack instead of the heap (the covers' shortest paths
// took a third less time on the shared instances).
//
// Infinite capacities: an arc of infinite capacity is given a finite one, B = the sum of the
// finite capacities and positive supplies plus 1, which no optimal flow of a problem with an
// optimum needs to reach (flow decomposition). If the capped problem's optimal flow uses some
// such arc up to B, or a search finds no deficit while any such arc is full, the answer would
// depend on the cap, and the solver reports NeedsExactFallback: the caller then asks a solver
// that decides unboundedness (backend/min_cost_flow.cpp uses LEMON's network simplex). The same
// status comes back when the costs exceed the overflow bound |cost|·(n + 1) < 2^60, when the
// supplies do not sum to 0, or when a run drives a potential below −2^61; initial potentials
// beyond ±2^60 are replaced by 0. Initial potentials that price such an arc negative are first
// repaired by a few Bellman–Ford passes over these arcs (lowering their heads' potentials), so
// that the start does not saturate them at B.
//
// Guarantee: Optimal is returned only after a check of the result — every arc within its
// bounds, every node balanced, and no arc with residual capacity priced negative — so the flow
// is optimal by LP duality and the potentials are an optimal dual. Deterministic.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace bimdf::detail {

class ShortestPathFlow {
 public:
  enum class Status { NotRun, Optimal, Infeasible, NeedsExactFallback, WorkLimitReached };

  // Copies the network: per arc source, target, capacity (INT64_MAX: infinite) and integer
  // cost; per node its supply. Throws std::invalid_argument on mismatched sizes, an end out
  // of range or a negative capacity.
  ShortestPathFlow(const std::vector<int64_t>& supply, const std::vector<int>& source,
                   const std::vector<int>& target, const std::vector<int64_t>& capacity,
                   const std::vector<int64_t>& cost);

  // Optional, one per node in the units of the costs (default 0); see the warm start above.
  ShortestPathFlow& initial_potentials(const std::vector<int64_t>& potential);

  // Optional: give up (WorkLimitReached) once the searches have scanned more than this many
  // residual arcs, for callers that have a solver whose cost does not grow with the distance
  // between surpluses and deficits (the network simplex). Default: no limit.
  ShortestPathFlow& work_limit(int64_t arc_scans) {
    work_limit_ = arc_scans;
    return *this;
  }

  // The imbalance (sum of surpluses) that run()'s start would leave with the current
  // potentials: a measure of the work ahead, O(arcs).
  int64_t start_imbalance() const;

  Status run();

  Status status() const { return status_; }
  // After Optimal: per arc its flow; per node its potential π, with c + π(source) − π(target)
  // ≥ 0 on arcs below capacity and ≤ 0 on arcs with flow.
  std::vector<int64_t> flow() const;
  std::vector<int64_t> potential() const;
  // Statistics of the last run: the imbalance the start left (sum of surpluses) and the
  // shortest-path searches it took to remove it.
  int64_t initial_imbalance() const { return initial_imbalance_; }
  int64_t searches() const { return searches_; }
  int64_t tight_routed() const { return tight_routed_; }

 private:
  // One search from `source` and the augmentation along the path it finds: NoDeficit when no
  // node with a deficit can be reached, GaveUp when the work limit was passed first.
  enum class Search { Augmented, NoDeficit, GaveUp };
  Search augment_from(int source);
  // Routes surplus to deficits along residual arcs of reduced cost 0 only: with good
  // potentials most of the start's imbalance sits on such arcs, and a few depth-first passes
  // move what would otherwise take a search per unit. Returns the amount.
  int64_t route_on_tight_arcs();
  bool verify() const;

  int n_ = 0, m_ = 0;
  // Residual network: half-arcs grouped by tail, at positions first_[v] .. first_[v+1] − 1.
  // Half-arc 2a of arc a runs source → target, 2a + 1 the other way (cost negated); pos_ maps
  // a half-arc to its position. Everything a search reads of a half-arc sits in one record.
  struct ResidualArc {
    int64_t cost;
    int64_t capacity;  // residual
    int head;
    int reverse;  // position of the opposite half-arc
  };
  std::vector<int> first_, pos_;
  std::vector<ResidualArc> arc_;
  int tail(int position) const { return arc_[arc_[position].reverse].head; }
  // The reduced cost of the half-arc at `position`, whose tail is `from`.
  int64_t reduced_cost(int from, int position) const {
    return arc_[position].cost + node_[from].potential - node_[arc_[position].head].potential;
  }
  // Whether an arc whose infinite capacity was capped at B is full (then the answer may depend
  // on the cap).
  bool capped_arc_full() const;
  // The sum of the positive entries, saturated at INT64_MAX.
  static int64_t surplus(const std::vector<int64_t>& excess);
  // Per node, what a search reads of it in one record. `mark` says what `dist` and `pred`
  // mean: 2k while search k has reached the node, 2k + 1 once it settled it; older values are
  // stale, so searches need no reset.
  struct NodeState {
    int64_t potential;
    int64_t dist;
    int pred;  // position of the half-arc that reached the node
    int mark;
  };
  std::vector<NodeState> node_;
  std::vector<int64_t> supply_, excess_;
  std::vector<char> capped_;  // per arc: its infinite capacity was replaced by B
  int64_t cap_b_ = 0;
  bool unsupported_ = false;  // overflow bounds exceeded at construction
  Status status_ = Status::NotRun;
  int64_t initial_imbalance_ = 0, searches_ = 0, tight_routed_ = 0;
  int search_mark_ = 0;  // 2k for the current search k
  int64_t work_ = 0, work_limit_ = std::numeric_limits<int64_t>::max();  // residual arcs scanned

  // Scratch space of the searches and the tight routing.
  std::vector<int> settled_order_, level_;
  std::vector<std::pair<int64_t, int>> heap_;
};

}  // namespace bimdf::detail
