// BlossomMatching's set-up (graph, warm start), its entry point and the optimality certificate
// it checks before answering; the forest growth itself is in blossom_matching.cpp.
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "backend/blossom_matching.hpp"

namespace bimdf::detail {

BlossomMatching::BlossomMatching(int num_nodes, std::span<const int> end_a,
                                 std::span<const int> end_b, std::span<const int64_t> weight)
    : n_(num_nodes), end_a_(end_a.begin(), end_a.end()), end_b_(end_b.begin(), end_b.end()) {
  const size_t m = end_a.size();
  if (num_nodes < 0 || end_b.size() != m || weight.size() != m)
    throw std::invalid_argument("blossom matching: edge arrays of different sizes");
  uint64_t largest = 0;  // unsigned: |INT64_MIN| fits
  for (int64_t w : weight)
    largest = std::max(largest, w < 0 ? uint64_t{0} - static_cast<uint64_t>(w) : uint64_t(w));
  weight_bound_ = (uint64_t{1} << 58) / (uint64_t(num_nodes) + 1);
  if (largest >= weight_bound_)
    throw std::invalid_argument("blossom matching: |weight| * (nodes + 1) must stay below 2^58");
  w2_.resize(m);
  enabled_.assign(m, 1);
  adj_start_.assign(n_ + 1, 0);
  for (size_t e = 0; e < m; ++e) {
    const int a = end_a_[e], b = end_b_[e];
    if (a < 0 || b < 0 || a >= n_ || b >= n_ || a == b)
      throw std::invalid_argument("blossom matching: edge " + std::to_string(e) +
                                  " is a loop or has an end out of range");
    w2_[e] = 2 * weight[e];
    ++adj_start_[a + 1];
    ++adj_start_[b + 1];
  }
  for (int v = 0; v < n_; ++v) adj_start_[v + 1] += adj_start_[v];
  adj_.resize(2 * m);
  adj_pos_.resize(2 * m);
  std::vector<int> fill(adj_start_.begin(), adj_start_.end() - 1);
  for (size_t e = 0; e < m; ++e) {
    const int a = end_a_[e], b = end_b_[e], ed = static_cast<int>(e);
    adj_pos_[2 * e] = fill[a];
    adj_[fill[a]++] = {b, ed, w2_[e]};
    adj_pos_[2 * e + 1] = fill[b];
    adj_[fill[b]++] = {a, ed, w2_[e]};
  }
}

BlossomMatching& BlossomMatching::initial_duals(std::span<const int64_t> y) {
  if (static_cast<int>(y.size()) != n_)
    throw std::invalid_argument("blossom matching: one initial dual per vertex expected");
  for (int64_t x : y)
    if (x <= -(int64_t{1} << 58) || x >= (int64_t{1} << 58))
      throw std::invalid_argument("blossom matching: initial duals must stay below 2^58");
  y_.resize(n_);
  for (int v = 0; v < n_; ++v) y_[v] = 2 * y[v];
  kept_ = false;  // a new start: the next run does not resume
  return *this;
}

BlossomMatching& BlossomMatching::initial_matching(std::span<const char> matched) {
  if (matched.size() != end_a_.size())
    throw std::invalid_argument("blossom matching: one initial flag per edge expected");
  start_match_.assign(matched.begin(), matched.end());
  kept_ = false;  // a new start: the next run does not resume
  return *this;
}

void BlossomMatching::start() {
  const int m = static_cast<int>(end_a_.size());
  // A blossom has at least three children, so at most (n − 1) / 2 blossoms live at once: ids
  // stay below 1.5 n, and reserving that keeps the per-id arrays from moving.
  const size_t most_ids = n_ + n_ / 2 + 1;
  link_.reserve(most_ids);
  top_.reserve(most_ids);
  base_.reserve(most_ids);
  cycle_.reserve(most_ids - n_);
  z_.reserve(most_ids);
  size_.reserve(most_ids);
  label_edge_.reserve(most_ids);
  label_from_.reserve(most_ids);
  label_to_.reserve(most_ids);
  mark_.reserve(most_ids);
  link_.assign(n_, Link{});
  top_.assign(n_, Top{});
  base_.resize(n_);
  for (int v = 0; v < n_; ++v) base_[v] = v;
  cycle_.clear();
  z_.assign(n_, 0);
  size_.assign(n_, 1);
  label_edge_.assign(n_, -1);
  label_from_.assign(n_, -1);
  label_to_.assign(n_, -1);
  mark_.assign(n_, 0);
  free_ids_.clear();

  const bool given = static_cast<int>(y_.size()) == n_;
  // Even, as the algorithm needs (a run that found no perfect matching may leave odd ones).
  for (int64_t& y : y_) y += y & 1;
  if (!given) {
    // y_v = max incident w makes every edge feasible; then lower each y_v as far as its edges
    // allow, so every vertex has a tight edge for the greedy matching below.
    y_.assign(n_, 0);
    for (int v = 0; v < n_; ++v) {
      int64_t best = std::numeric_limits<int64_t>::min();
      for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k)
        if (adj_[k].w2 != kDisabled) best = std::max(best, adj_[k].w2 / 2);
      // Even, like every dual the start hands over: then all trees share their duals' parity
      // and every dual change is an integer (see the header).
      if (best != std::numeric_limits<int64_t>::min()) y_[v] = best + (best & 1);
    }
  }
  for (int e = 0; e < m; ++e) {
    const int64_t deficit = w2_[e] - y_[end_a_[e]] - y_[end_b_[e]];
    if (enabled_[e] && deficit > 0) y_[end_a_[e]] += deficit;
  }
  if (!given) {
    for (int v = 0; v < n_; ++v) {
      int64_t need = std::numeric_limits<int64_t>::min();
      for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k) {
        const Incidence& in = adj_[k];
        if (in.w2 != kDisabled) need = std::max(need, in.w2 - y_[in.other]);
      }
      if (need != std::numeric_limits<int64_t>::min()) y_[v] = need;
    }
  }
  mate_.assign(n_, -1);
  auto try_match = [&](int e) {
    const int a = end_a_[e], b = end_b_[e];
    if (enabled_[e] && mate_[a] < 0 && mate_[b] < 0 && y_[a] + y_[b] == w2_[e])
      mate_[a] = mate_[b] = e;
  };
  if (static_cast<int>(start_match_.size()) == m)
    for (int e = 0; e < m; ++e)
      if (start_match_[e]) try_match(e);
  for (int e = 0; e < m; ++e) try_match(e);
}

BlossomMatching::Status BlossomMatching::run() {
  if (kept_) {
    kept_ = false;  // a throw below leaves no state to resume from
    resume();
  } else {
    start();
  }
  reopened_.clear();
  updated_.clear();
  if (!grow_forest()) return status_ = Status::NoPerfectMatching;
  if (!certificate_holds())
    throw std::logic_error("blossom matching: the optimality certificate does not hold");
  kept_ = true;
  return status_ = Status::Optimal;
}

// Perfect matching + feasible duals + tight matched edges + full blossoms where z > 0, in
// O((n + m) log depth) however deeply blossoms nest: the z of the blossoms holding both ends of
// an edge is a prefix sum at the ends' lowest common blossom (a short walk up from the
// shallower end to the first blossom whose preorder leaf interval holds the other, else binary
// lifting), and a blossom's vertices matched outside it are counted by subtree sums (+1 at each
// end of a matched edge, −2 at their lowest common blossom). Unmatched edges feasible on the
// vertex duals alone need no blossom at all (every z ≥ 0). At 10^6 edges, the walk from both
// ends to equal depth that this replaces fell back to lifting on most queries: 70% of the
// certificate's time, a tenth of each refinement round.
bool BlossomMatching::certificate_holds() {
  const int ids = static_cast<int>(link_.size());
  for (int v = 0; v < n_; ++v) {
    const int e = mate_[v];
    if (e < 0 || (end_a_[e] != v && end_b_[e] != v) || mate_[other(e, v)] != e) return false;
  }
  // Preorder of the blossom forest (parents first), depth and z summed from the top down.
  std::vector<int> order, depth(ids, 0), stack;
  order.reserve(ids);
  std::vector<int64_t> z_down(ids, 0);
  for (int b = 0; b < ids; ++b) {
    const bool live = b < n_ || !cycle(b).children.empty();
    if (!live || link_[b].parent >= 0) continue;
    stack.assign(1, b);
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      order.push_back(x);
      const int p = link_[x].parent;
      depth[x] = p >= 0 ? depth[p] + 1 : 0;
      if (nontrivial(x) && z_[x] < 0) return false;
      z_down[x] = (nontrivial(x) ? z_[x] : 0) + (p >= 0 ? z_down[p] : 0);
      if (nontrivial(x))
        stack.insert(stack.end(), cycle(x).children.begin(), cycle(x).children.end());
    }
  }
  // Each id's leaves (vertices) are consecutive in the preorder: [first_leaf, last_leaf] in
  // leaf order, filled children first.
  std::vector<int> leaf_pos(ids, -1), first_leaf(ids, std::numeric_limits<int>::max()),
      last_leaf(ids, -1);
  int leaves_seen = 0;
  for (int x : order)
    if (!nontrivial(x)) leaf_pos[x] = first_leaf[x] = last_leaf[x] = leaves_seen++;
  for (auto it = order.rbegin(); it != order.rend(); ++it)
    if (const int p = link_[*it].parent; p >= 0) {
      first_leaf[p] = std::min(first_leaf[p], first_leaf[*it]);
      last_leaf[p] = std::max(last_leaf[p], last_leaf[*it]);
    }
  const auto contains = [&](int x, int pos) { return first_leaf[x] <= pos && pos <= last_leaf[x]; };
  // Binary lifting, built the first time a walk below gets long (deeply nested blossoms).
  std::vector<std::vector<int>> up;
  const auto build_lifting = [&] {
    int deepest = 0;
    for (int x : order) deepest = std::max(deepest, depth[x]);
    int levels = 1;
    while ((1 << levels) <= deepest) ++levels;
    up.assign(levels, std::vector<int>(ids, -1));
    for (int x : order) {
      up[0][x] = link_[x].parent;
      for (int k = 1; k < levels; ++k) up[k][x] = up[k - 1][x] < 0 ? -1 : up[k - 1][up[k - 1][x]];
    }
  };
  // Lowest common blossom of two vertices (−1: none): up from the shallower one to the first
  // blossom whose leaves include the other. The matched and nearly tight edges this is asked
  // about mostly have an end near the top of its blossom tree; past 32 steps, binary lifting.
  const auto lowest_common = [&](int a, int b) {
    if (depth[a] > depth[b]) std::swap(a, b);
    const int at = leaf_pos[b];
    for (int steps = 0; steps < 32; ++steps) {
      if (a < 0 || contains(a, at)) return a;
      a = link_[a].parent;
    }
    if (a < 0 || contains(a, at)) return a;
    if (up.empty()) build_lifting();
    for (int k = static_cast<int>(up.size()) - 1; k >= 0; --k)
      if (up[k][a] >= 0 && !contains(up[k][a], at)) a = up[k][a];
    return link_[a].parent;
  };
  // Most edges join two top blossoms, where no z applies: each vertex's top and dual once.
  std::vector<int> top(n_);
  std::vector<int64_t> y(n_);
  for (int v = 0; v < n_; ++v) {
    top[v] = top_of(v);
    y[v] = dual(v);
  }
  std::vector<int64_t> outside(ids, 0);
  for (int e = 0; e < static_cast<int>(end_a_.size()); ++e) {
    const int u = end_a_[e], v = end_b_[e];
    // Every z is ≥ 0 (checked above), so an unmatched edge feasible on the vertex duals alone
    // is feasible whatever blossoms hold both ends: no need to find them.
    if (mate_[u] != e && (!enabled_[e] || y[u] + y[v] >= w2_[e])) continue;
    if (!enabled_[e]) return false;  // a disabled edge matched
    const int common = top[u] == top[v] ? lowest_common(u, v) : -1;
    const int64_t s = y[u] + y[v] + (common >= 0 ? z_down[common] : 0) - w2_[e];
    if (s < 0 || (mate_[u] == e && s != 0)) return false;
    if (mate_[u] == e) {
      ++outside[u];
      ++outside[v];
      if (common >= 0) outside[common] -= 2;
    }
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (nontrivial(*it) && z_[*it] > 0 && outside[*it] > 1) return false;
    if (link_[*it].parent >= 0) outside[link_[*it].parent] += outside[*it];
  }
  return true;
}

std::vector<char> BlossomMatching::matched_edges() const {
  std::vector<char> out(end_a_.size(), 0);
  for (int v = 0; v < n_; ++v)
    if (mate_[v] >= 0) out[mate_[v]] = 1;
  return out;
}

int64_t BlossomMatching::matching_weight() const {
  int64_t total = 0;
  for (int v = 0; v < n_; ++v)
    if (mate_[v] >= 0 && v == std::min(end_a_[mate_[v]], end_b_[mate_[v]])) total += w2_[mate_[v]];
  return total / 2;
}

}  // namespace bimdf::detail
