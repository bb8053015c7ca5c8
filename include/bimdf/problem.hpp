// The Bi-MDF problem: a bidirected network with integer demands, integer bounds and convex
// per-edge costs (paper §3.1, DESIGN §2).
//
// Conventions, used by every part of bimdf:
//   * Nodes 0..n−1, each with a demand b[v]. Edges 0..m−1, each with one or two ends; an end is
//     (node, head|tail) with sign σ = +1 for a head and −1 for a tail. An edge with a single end
//     is an *outer edge* (§3.2.1). Two ends at one node form a loop: head–head counts +2,
//     tail–tail −2; a head–tail loop would contribute nothing and is rejected as input.
//   * A flow is x ∈ Z^m with lower[e] ≤ x[e] ≤ upper[e].
//   * Conservation: Σ_e σ(v,e)·x[e] = b[v] at every node v (net head-minus-tail flow).
//   * Objective: minimize Σ_e cost[e](x[e]).
// Flows, bounds and demands are int64_t. An infinite bound is the explicit marker kInfinity
// (upper) or −kInfinity (lower); finite values are limited to |v| ≤ kMaxMagnitude so that sums
// over a whole network cannot overflow and every value is exact as a double.
//
// Storage is a plain struct of arrays, one entry per edge, indexed by edge id.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bimdf/cost.hpp"

namespace bimdf {

// The explicit infinite bound. Never a valid finite value (finite values are ≤ kMaxMagnitude).
inline constexpr int64_t kInfinity = std::numeric_limits<int64_t>::max();
// Largest magnitude of a finite bound, demand or flow value (2^40 ≈ 1.1e12).
inline constexpr int64_t kMaxMagnitude = int64_t{1} << 40;
// Marks the missing second end of an outer edge.
inline constexpr int kNoNode = -1;

// One end of an edge.
struct End {
  int node = kNoNode;
  bool head = false;  // true: head (σ = +1), false: tail (σ = −1)

  int sign() const { return head ? 1 : -1; }
  friend bool operator==(const End&, const End&) = default;
};

// How an edge attaches to the network; used for statistics and by reductions.
enum class EdgeKind {
  HeadTail,   // ordinary directed edge between two different nodes
  HeadHead,   // two heads at different nodes
  TailTail,   // two tails at different nodes
  LoopHeads,  // head–head loop: contributes +2·x to its node
  LoopTails,  // tail–tail loop: contributes −2·x to its node
  OuterHead,  // single head end
  OuterTail,  // single tail end
};
inline constexpr int kNumEdgeKinds = 7;
// Human-readable name ("head-tail", "head-head", "tail-tail", "loop +2", "loop -2",
// "outer head", "outer tail").
const char* edge_kind_name(EdgeKind kind);

struct Problem {
  // Per node.
  std::vector<int64_t> demand;
  // Per edge. `end_b[e].node == kNoNode` marks an outer edge.
  std::vector<End> end_a;
  std::vector<End> end_b;
  std::vector<int64_t> lower;
  std::vector<int64_t> upper;
  std::vector<Cost> cost;
  // Optional names: either empty, or one (possibly empty) string per node / edge. Readers leave
  // a vector empty when no element has a name, and writers omit empty names.
  std::vector<std::string> node_name;
  std::vector<std::string> edge_name;

  int num_nodes() const { return static_cast<int>(demand.size()); }
  int num_edges() const { return static_cast<int>(end_a.size()); }

  // Appends a node and returns its id.
  int add_node(int64_t node_demand = 0);
  // Appends an edge and returns its id. `b` omitted: an outer edge.
  int add_edge(End a, std::optional<End> b, int64_t lo, int64_t up, Cost c);
  // Makes room for this many nodes and edges in all (contents unchanged), so that building a
  // problem of known size allocates each array once.
  void reserve(int nodes, int edges);

  bool is_outer(int e) const { return end_b[e].node == kNoNode; }
  EdgeKind edge_kind(int e) const;

  friend bool operator==(const Problem&, const Problem&) = default;
};

// Where a validation problem was found.
struct ProblemIssue {
  enum class Where { Problem, Node, Edge };
  Where where = Where::Problem;
  int index = -1;     // node or edge id
  std::string field;  // "demand", "lower", "upper", "cost", "ends", …
  std::string message;
};

// Checks every rule of the model that does not depend on solving: array sizes agree, node ids
// are in range, no head–tail loop, finite values within ±kMaxMagnitude, lower ≤ upper, costs
// valid for their bounds (validate_cost). Returns the first issue found in id order, nodes
// before edges; nullopt if the problem is well-formed. Infeasibility is *not* an issue here.
std::optional<ProblemIssue> validate(const Problem& problem);

// Connected components of the graph whose vertices are the nodes and whose edges join the ends
// of each edge. Returns the component id of every node, numbered 0.. in order of the smallest
// node id they contain.
std::vector<int> connected_components(const Problem& problem, int* num_components = nullptr);

}  // namespace bimdf
