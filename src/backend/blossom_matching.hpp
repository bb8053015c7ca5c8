// Maximum-weight perfect matching with integer weights: Edmonds' primal-dual blossom algorithm,
// our own implementation (no LEMON), made to be warm-started.
//
// Problem: an undirected graph (parallel edges allowed, no loops) with int64 weights w; find a
// perfect matching of maximum total weight, or prove that none exists. The algorithm keeps a
// feasible solution of the dual of Edmonds' matching polytope — a value y_v per vertex and
// z_B ≥ 0 per blossom (odd vertex set) with y_u + y_v + Σ_{B ∋ u,v} z_B ≥ w_uv on every edge —
// and a matching on tight edges (equality). Every free vertex roots an alternating tree, and
// all trees grow together with one dual change δ (positive vertices −δ, negative +δ, positive
// blossoms' z +2δ, negative −2δ). δ is never applied vertex by vertex: the moments at which an
// edge between positive blossoms becomes tight, an unlabeled blossom can first be grown into
// a tree (one event per blossom, its earliest edge) or a negative blossom's z reaches 0 sit in
// a priority queue, and a vertex's dual is its stored value plus its top blossom's offset plus
// the change since that blossom was labeled (lazy duals). A tight edge between two trees augments
// (both trees are taken apart), inside one tree it forms a blossom; blossoms outlive the trees. A
// new blossom keeps its largest child's vertices as they are and rebases only the others, so nested
// blossoms cost their smaller parts; tops are found through path-compressed jumps.
//
// Warm start: `initial_duals` and `initial_matching` may be anything. Duals are first raised
// until every edge is feasible, then only the given matched edges that are tight (and then
// greedily any tight edge) are kept, so a bad start costs time, never correctness. From the
// LP relaxation's duals and integral flow (refinement, solve/refine.cpp) only a few hundred of
// ~10^5 vertices stay free.
//
// Re-optimization: after run() returned Optimal the solver keeps its matching, duals and
// blossoms, and `update_edge` / `reopen` followed by run() solve the changed problem from them
// (refinement's persistent rounds, solve/persistent_rounds.hpp). The vertices reopened — those
// asked for, and an end of each updated edge that has none — leave every blossom that holds
// them (a blossom's z moves onto its vertices' duals, z/2 each, which keeps every edge inside
// it as tight as before) and lose their matched edge; their duals are set as low as their
// edges allow. Everything else keeps its state, and the trees grow from the reopened vertices
// and the partners they freed only. (Measured: this is not yet a local search — a dissolved
// blossom's z/2 can be as large as the whole dual change of a fresh run, which the trees then
// have to make up; docs/benchmarks.md.) Dual parity: the algorithm needs all duals even at a
// start (above), but a run ends with the duals of vertices labeled at different times of
// mixed parity, and a dissolved blossom's z/2 may be odd. Duals are uniform in parity per top
// blossom, and a matched edge joins two tops of equal parity, so each odd top is moved by ±1
// (its z by ∓2, after blossoms of z = 0 are expanded), one of each matched pair down and the
// other up, which keeps their edge tight; which one goes down is a 2-SAT problem (no tight
// edge between two tops that both go down), and a pair it cannot place is unmatched (both up).
//
// Guarantee: `run()` returns Optimal only after checking the certificate — a perfect matching,
// feasible duals, tight matched edges, and every blossom with z > 0 holding ⌊|B|/2⌋ matched
// edges — so the matching is optimal by LP duality, whatever the path to it (a failed check
// throws std::logic_error: a bug). Internally weights and duals are doubled and start even, so
// every dual change is an integer (all labeled vertices share the parity of their duals).
// |w|·(n + 1) must stay below 2^58 (checked: std::invalid_argument).
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace bimdf::detail {

class BlossomMatching {
 public:
  enum class Status { NotRun, Optimal, NoPerfectMatching };

  // Copies the graph. Throws std::invalid_argument on a loop, an end out of range, mismatched
  // sizes or weights too large for the overflow bound above.
  BlossomMatching(int num_nodes, std::span<const int> end_a, std::span<const int> end_b,
                  std::span<const int64_t> weight);

  // Optional: a dual value per vertex, in the units of the weights, each below 2^58 in
  // magnitude (std::invalid_argument otherwise). After a run, either setter makes the next run
  // start afresh instead of resuming.
  BlossomMatching& initial_duals(std::span<const int64_t> y);
  // Optional: per edge, 1 if it starts matched. Edges that are not tight after the duals are
  // made feasible, or that touch an already matched vertex, are dropped.
  BlossomMatching& initial_matching(std::span<const char> matched);

  // Solves from the start given above, or — after a run that returned Optimal — from that
  // run's solution, re-opened where `update_edge` and `reopen` asked (see above).
  Status run();

  // Before a run: edge e gets weight `weight` (overflow bound as in the constructor;
  // std::invalid_argument otherwise) and is part of the graph iff `enabled` (a disabled edge is
  // never matched and needs no dual feasibility). After an Optimal run one of its ends is
  // reopened — the one `reopen` names, else end_a — since its dual must meet the new weight.
  BlossomMatching& update_edge(int e, int64_t weight, bool enabled = true);
  // After an Optimal run: the next run re-opens vertex v (leaves its blossoms and its mate).
  // Between these calls and that run, status() and matched_edges() still describe the last
  // run (whose matching may use an edge just disabled).
  BlossomMatching& reopen(int v);

  Status status() const { return status_; }
  // After Optimal: per edge, 1 if matched.
  std::vector<char> matched_edges() const;
  int64_t matching_weight() const;
  // Vertices the start left free, i.e. trees grown (a measure of the warm start's quality).
  int64_t free_after_start() const { return free_after_start_; }
  // Of a resumed run: matched pairs the parity step had to unmatch (no 2-SAT placement).
  int64_t parity_unmatched_pairs() const { return parity_unmatched_pairs_; }

 private:
  enum Label : int8_t { kNone, kPlus, kMinus };
  struct Event {
    int64_t time;
    int kind;  // kEdgeEvent, kExpandEvent or kGrowEvent (blossom_matching.cpp)
    int id;
    bool operator>(const Event& o) const { return time > o.time; }
  };

  int other(int e, int v) const { return end_a_[e] ^ end_b_[e] ^ v; }
  bool nontrivial(int b) const { return b >= n_; }
  int64_t dual(int v);                    // current y of a vertex (doubled units)
  int64_t dual_in(int v, int top) const;  // the same, its top blossom known
  int64_t slack(int e);
  void leaves(int b, std::vector<int>& out);
  void bring_up_to_date(int b);
  // The top blossom of v (blossom_matching.cpp: top_of_slow walks up when the remembered jump
  // is stale). The fast path is inline: it runs once or twice per edge the forest scans.
  int top_of(int v) {
    const Link& lv = link_[v];
    if (lv.parent < 0) return v;
    if (lv.jump >= 0 && lv.jump_gen == link_[lv.jump].gen && link_[lv.jump].parent < 0)
      return lv.jump;
    return top_of_slow(v);
  }
  int top_of_slow(int v);
  void set_label(int b, Label label, int edge, int from, int to, int tree);
  void scan_plus(int b);
  void push_edge_events_towards(int b);
  void consider_grow(int b, int e, int64_t time);
  void push_event(int64_t time, int kind, int id);
  bool grow_forest();
  void grow(int u, int v, int e);
  void make_blossom(int u, int v, int e);
  void expand(int b);
  void augment(int u, int v, int e);
  void flip_to_root(int x, std::vector<int>& pairs);
  void dissolve_tree(int tree, std::vector<int>& were_minus);
  void rotate_to(int b, int v);
  int tree_parent(int b);
  int new_blossom_id();
  void start();
  void resume();
  void dissolve_top(int b);
  void shift_parity();
  bool certificate_holds();

  int n_;
  std::vector<int> end_a_, end_b_;
  std::vector<int64_t> w2_;    // doubled weights
  std::vector<char> enabled_;  // per edge: part of the graph (update_edge)
  uint64_t weight_bound_ = 0;  // |w| must stay below this (the overflow bound above)
  bool kept_ = false;          // the last run was Optimal: the next one resumes from it
  std::vector<int> reopened_;  // asked for since (reopen)
  std::vector<int> updated_;   // edges updated since (update_edge)
  // Incidence lists: per vertex, from adj_start_[v], an entry per edge with what the hot loops
  // (scan_plus, push_edge_events_towards) read of it, so that they stream through memory
  // instead of looking each edge up; w2 is kDisabled for a disabled edge. adj_pos_[2e] and
  // [2e + 1] are edge e's entries at end_a and end_b (update_edge keeps them in step).
  struct Incidence {
    int other;  // the edge's other end
    int edge;
    int64_t w2;
  };
  static constexpr int64_t kDisabled = std::numeric_limits<int64_t>::min();
  std::vector<int> adj_start_, adj_pos_;
  std::vector<Incidence> adj_;
  // Doubled dual of vertex v: y_[v] + top_[t].off for its top blossom t + the change since t
  // was labeled.
  std::vector<int64_t> y_;
  std::vector<int> mate_;  // matched edge per vertex or -1
  std::vector<char> start_match_;

  // Blossom forest: ids < n are vertices, ids ≥ n blossoms. Fields read together on the hot
  // path (top_of, dual) share a struct, so that one lookup touches one cache line.
  struct Link {
    int parent = -1;
    int jump = -1, jump_gen = 0;  // see top_of
    int gen = 0;                  // bumped when the blossom is expanded (its id freed)
  };
  std::vector<Link> link_;
  std::vector<int> base_, path_;
  // The odd cycle of blossom b ≥ n lives at cycle_[b − n] (ids are reused, and so are the
  // vectors' buffers): children in cycle order from the base child; edge[k] joins children k
  // (at vertex from[k]) and k + 1 (at to[k]), the last one closing the cycle.
  struct Cycle {
    std::vector<int> children, edge, from, to;
  };
  std::vector<Cycle> cycle_;
  Cycle& cycle(int b) { return cycle_[b - n_]; }
  std::vector<int64_t> z_;
  std::vector<int> size_;  // vertices in a blossom
  std::vector<int> free_ids_;
  // The forest, per top blossom; trees are numbered in the order of their free root vertices.
  // `off` is kept for every id (children keep theirs inside a blossom); the rest only for tops.
  struct Top {
    int64_t off = 0;         // added to the duals of all vertices below
    int64_t label_time = 0;  // now_ when labeled; dual changes since are applied lazily
    Label label = kNone;
    int tree = -1;
    int grow_edge = -1;  // unlabeled tops: the edge of their queued grow event, due at
    int64_t grow_time = std::numeric_limits<int64_t>::max();  // (see consider_grow)
  };
  std::vector<Top> top_;
  std::vector<std::vector<int>> tree_tops_;  // per tree, its tops (stale entries skipped)
  std::vector<int> label_edge_, label_from_, label_to_;
  std::vector<int> mark_;
  int mark_stamp_ = 0;
  int64_t now_ = 0;
  std::vector<Event> heap_;
  std::vector<int> scratch_, leaf_stack_;  // buffers of leaves() and its callers

  Status status_ = Status::NotRun;
  int64_t free_after_start_ = 0;
  int64_t parity_unmatched_pairs_ = 0;
};

}  // namespace bimdf::detail
