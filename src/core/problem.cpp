#include "bimdf/problem.hpp"

#include <numeric>
#include <string>

namespace bimdf {

const char* edge_kind_name(EdgeKind kind) {
  static constexpr const char* kNames[kNumEdgeKinds] = {
      "head-tail", "head-head", "tail-tail", "loop +2", "loop -2", "outer head", "outer tail"};
  return kNames[static_cast<int>(kind)];
}

int Problem::add_node(int64_t node_demand) {
  demand.push_back(node_demand);
  if (!node_name.empty()) node_name.emplace_back();
  return num_nodes() - 1;
}

int Problem::add_edge(End a, std::optional<End> b, int64_t lo, int64_t up, Cost c) {
  end_a.push_back(a);
  end_b.push_back(b.value_or(End{kNoNode, false}));
  lower.push_back(lo);
  upper.push_back(up);
  cost.push_back(std::move(c));
  if (!edge_name.empty()) edge_name.emplace_back();
  return num_edges() - 1;
}

void Problem::reserve(int nodes, int edges) {
  demand.reserve(nodes);
  if (!node_name.empty()) node_name.reserve(nodes);
  end_a.reserve(edges);
  end_b.reserve(edges);
  lower.reserve(edges);
  upper.reserve(edges);
  cost.reserve(edges);
  if (!edge_name.empty()) edge_name.reserve(edges);
}

EdgeKind Problem::edge_kind(int e) const {
  const End a = end_a[e], b = end_b[e];
  if (b.node == kNoNode) return a.head ? EdgeKind::OuterHead : EdgeKind::OuterTail;
  if (a.node == b.node) return a.head ? EdgeKind::LoopHeads : EdgeKind::LoopTails;
  if (a.head != b.head) return EdgeKind::HeadTail;
  return a.head ? EdgeKind::HeadHead : EdgeKind::TailTail;
}

namespace {

ProblemIssue node_issue(int v, std::string field, std::string message) {
  return {ProblemIssue::Where::Node, v, std::move(field), std::move(message)};
}
ProblemIssue edge_issue(int e, std::string field, std::string message) {
  return {ProblemIssue::Where::Edge, e, std::move(field), std::move(message)};
}

bool finite_in_range(int64_t v) { return v >= -kMaxMagnitude && v <= kMaxMagnitude; }

}  // namespace

std::optional<ProblemIssue> validate(const Problem& p) {
  const size_t m = p.end_a.size();
  if (p.end_b.size() != m || p.lower.size() != m || p.upper.size() != m || p.cost.size() != m)
    return ProblemIssue{ProblemIssue::Where::Problem, -1, "edges",
                        "per-edge arrays have different lengths"};
  if (!p.node_name.empty() && p.node_name.size() != p.demand.size())
    return ProblemIssue{ProblemIssue::Where::Problem, -1, "node_name",
                        "node names must be absent or one per node"};
  if (!p.edge_name.empty() && p.edge_name.size() != m)
    return ProblemIssue{ProblemIssue::Where::Problem, -1, "edge_name",
                        "edge names must be absent or one per edge"};

  for (int v = 0; v < p.num_nodes(); ++v)
    if (!finite_in_range(p.demand[v]))
      return node_issue(v, "demand",
                        "demand must be within +-2^40 (1099511627776), got " +
                            std::to_string(p.demand[v]));

  const int n = p.num_nodes();
  for (int e = 0; e < p.num_edges(); ++e) {
    const End a = p.end_a[e], b = p.end_b[e];
    if (a.node < 0 || a.node >= n)
      return edge_issue(e, "ends",
                        "node id " + std::to_string(a.node) + " is out of range [0, " +
                            std::to_string(n) + ")");
    if (b.node != kNoNode && (b.node < 0 || b.node >= n))
      return edge_issue(e, "ends",
                        "node id " + std::to_string(b.node) + " is out of range [0, " +
                            std::to_string(n) + ")");
    if (a.node == b.node && a.head != b.head)
      return edge_issue(e, "ends",
                        "head-tail loop at node " + std::to_string(a.node) +
                            " has no effect on conservation; expected head-head or tail-tail");
    const int64_t lo = p.lower[e], up = p.upper[e];
    if (lo == kInfinity)
      return edge_issue(e, "lower", "lower bound must be finite or -inf, got +inf");
    if (up == -kInfinity)
      return edge_issue(e, "upper", "upper bound must be finite or +inf, got -inf");
    if (lo != -kInfinity && !finite_in_range(lo))
      return edge_issue(e, "lower",
                        "lower bound must be within +-2^40 (1099511627776) or -inf, got " +
                            std::to_string(lo));
    if (up != kInfinity && !finite_in_range(up))
      return edge_issue(e, "upper",
                        "upper bound must be within +-2^40 (1099511627776) or inf, got " +
                            std::to_string(up));
    if (lo > up)
      return edge_issue(e, "lower",
                        "lower bound " + std::to_string(lo) + " is greater than upper bound " +
                            std::to_string(up));
    if (auto msg = validate_cost(p.cost[e], lo, up)) return edge_issue(e, "cost", *msg);
  }
  return std::nullopt;
}

std::vector<int> connected_components(const Problem& p, int* num_components) {
  // Union-find with path halving; then number the roots in order of their smallest node.
  const int n = p.num_nodes();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.is_outer(e)) continue;
    int x = find(p.end_a[e].node), y = find(p.end_b[e].node);
    if (x == y) continue;
    if (x > y) std::swap(x, y);
    parent[y] = x;  // the smaller id stays the root
  }
  std::vector<int> comp(n, -1);
  int count = 0;
  for (int v = 0; v < n; ++v) {
    const int r = find(v);
    if (comp[r] < 0) comp[r] = count++;
    comp[v] = comp[r];
  }
  if (num_components) *num_components = count;
  return comp;
}

}  // namespace bimdf
