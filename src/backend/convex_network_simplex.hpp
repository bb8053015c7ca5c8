// Minimum-cost flow with convex piecewise-linear arc costs by a primal network simplex: our own
// (no LEMON), for the linearized covers of solve/approximate.cpp, whose every edge is a run of
// unit or width-2 pieces that a plain network simplex must carry as separate parallel arcs.
//
// Problem: node supplies b (outflow − inflow, summing to 0) and arcs u → v whose flow x may take
// any integer value in [p_0, p_K] at a cost that is linear between consecutive breakpoints
// p_0 < p_1 < … < p_K with slopes s_1 ≤ s_2 ≤ … ≤ s_K (convex); p_0 may be −∞ and p_K +∞
// (kUnboundedPoint). Minimize Σ cost subject to conservation. Slopes are integers; a run
// needs |s|·(n + 1) ≤ 2^60 for every slope (backend/min_cost_flow.hpp scales costs so).
//
// Method: the bounded-variable network simplex with breakpoints in place of bounds. A non-tree
// arc sits at a breakpoint and is priced in both directions, with the slope of the segment it
// would move into; a tree arc lies in one segment, whose slope its potentials make tight, and
// the ratio test stops at the end of that segment, where the arc leaves the tree at a
// breakpoint and re-enters later on the next segment if that still pays. One arc per edge
// instead of one per piece makes the block search's scans proportionally shorter and moves an
// edge across several pieces without a pivot per piece. The tree is strongly feasible from an
// artificial root (artificial arcs of cost 0 up and M = (max|s| + 1)·(n + 1) down, as is usual),
// and the leaving arc is the last blocking arc of the cycle from its apex (Cunningham's rule),
// so degenerate pivots cannot cycle. Pricing is a block search over √m arcs.
//
// Guarantee: Optimal means a flow within every arc's range that balances every node, and
// potentials π under which every arc is optimal: left slope ≤ π(v) − π(u) ≤ right slope at its
// flow (the slopes beyond the range being ∓∞). Infeasible: an artificial arc keeps flow at the
// optimum of the big-M problem. Unbounded: a negative cycle of unbounded capacity exists.
// Deterministic.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace bimdf::detail {

// A breakpoint at infinity (only a first or last one).
inline constexpr int64_t kUnboundedPoint = std::numeric_limits<int64_t>::max();

// The network, as plain arrays. Arc j's breakpoints are point[first[j]] … point[first[j + 1] −
// 1] (at least two, increasing; the first may be −kUnboundedPoint, the last kUnboundedPoint)
// and the slope between point[k] and point[k + 1] is slope[k] (slope has the size of point; the
// entry at an arc's last breakpoint is unused). Arc j starts at breakpoint start[j] (an index
// into point, a finite one), which need not balance the nodes.
struct ConvexMcf {
  std::vector<int64_t> supply;  // per node: outflow − inflow
  std::vector<int> source, target;
  std::vector<int> first;  // per arc, plus one past the last
  std::vector<int64_t> point, slope;
  std::vector<int> start;

  int num_nodes() const { return static_cast<int>(supply.size()); }
  int num_arcs() const { return static_cast<int>(source.size()); }
};

class ConvexNetworkSimplex {
 public:
  enum class Status { NotRun, Optimal, Infeasible, Unbounded };

  // Keeps a reference to `mcf`, which must outlive the solver. Throws std::invalid_argument on
  // inconsistent arrays (sizes, ends out of range, breakpoints not increasing, slopes not
  // non-decreasing, a start at infinity) or supplies that do not sum to 0.
  explicit ConvexNetworkSimplex(const ConvexMcf& mcf);

  // Optional: a spanning tree to start from, as a parent per node (−1: the root), usually
  // tree_parent() of an earlier solve on a network with the same nodes. Each node's tree arc
  // becomes an arc between it and its parent (if there is none, the node hangs from the root);
  // the tree's flows follow from the non-tree arcs' starts, and every tree arc they would push
  // out of its range, or could not leave towards the root, is replaced by the node's
  // artificial arc (so the start is a strongly feasible basis). Not a tree: ignored.
  ConvexNetworkSimplex& start_tree(std::vector<int> parent);

  Status run();

  Status status() const { return status_; }
  // When Optimal: per arc its flow, per node its potential π (costs' units; reduced slope
  // s + π(u) − π(v)).
  int64_t flow(int arc) const { return x_[arc]; }
  int64_t potential(int node) const { return pi_[node]; }
  int64_t pivots() const { return pivots_; }
  // After a run: the final tree as a parent per node (−1: the root), for start_tree.
  std::vector<int> tree_parent() const;
  // After a run: how many start-tree arcs were replaced by artificial ones (statistics).
  int64_t start_tree_cuts() const { return start_tree_cuts_; }

 private:
  struct Priced {  // what the block search reads per arc, together
    int source, target;
    int64_t up, down;  // slope for increasing / decreasing the flow (±kBlocked if it cannot)
  };
  // A node's place in the tree and its tree arc (`pred`, towards the parent if `up`) with that
  // arc's flow and current segment [lo, hi]: all that the walks along tree paths read, in one
  // place. A tree arc's flow lives here, not in x_, until the arc leaves the tree.
  struct Link {
    int parent, succ_num, pred;
    bool up;
    int64_t x, lo, hi;
  };
  void initialize();
  void build_start_tree(const std::vector<int64_t>& excess, int64_t big_m);
  bool find_entering(int& arc, int& direction);
  void pivot(int arc, int direction);
  void set_nonbasic(int arc, int breakpoint);
  int64_t point(int arc, int k) const;
  void rehang(int u_in, int v_in, const Link& entering, int leave_node, int apex, int64_t shift);

  const ConvexMcf& mcf_;
  Status status_ = Status::NotRun;
  int n_ = 0, m_ = 0, root_ = 0;
  std::vector<Priced> priced_;     // real and artificial arcs
  std::vector<int64_t> x_;         // flow per non-tree arc
  std::vector<int> at_;            // breakpoint (non-tree) or segment start (tree) per arc
  std::vector<int64_t> art_cost_;  // artificial arc per node: its cost
  std::vector<int64_t> pi_;
  std::vector<Link> link_;
  // A preorder thread of the tree (cyclic through the root) in which every subtree is the run
  // from its root to last_succ_.
  std::vector<int> thread_, rev_thread_, last_succ_;
  std::vector<int> path_, path_last_, path_after_, path_before_, path_size_;  // rehang's scratch
  std::vector<Link> path_link_;
  std::vector<int> start_parent_;
  int64_t start_tree_cuts_ = 0;
  int block_size_ = 0, next_scan_ = 0;
  int64_t pivots_ = 0;
};

}  // namespace bimdf::detail
