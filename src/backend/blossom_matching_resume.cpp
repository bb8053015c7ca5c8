// BlossomMatching's re-optimization: a run that starts from the previous run's matching, duals
// and blossoms, re-opened around the vertices and edges that changed (blossom_matching.hpp).
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "backend/blossom_matching.hpp"

namespace bimdf::detail {
namespace {

// 2-SAT with clauses ¬(a ∧ b) over literals 2p ("variable p holds") and 2p + 1 (its
// negation): which literals hold. A variable whose literals imply each other both ways is
// marked in `given_up` and dropped with its clauses, until the rest is satisfiable. Tarjan's
// algorithm numbers the implication graph's components in reverse topological order, and a
// literal holds when its component comes before its negation's.
std::vector<char> solve_two_sat(int literals, const std::vector<std::pair<int, int>>& clauses,
                                std::vector<char>& given_up) {
  while (true) {
    std::vector<int> first(literals + 1, 0), target;
    auto live = [&](const std::pair<int, int>& c) {
      return !given_up[c.first / 2] && !given_up[c.second / 2];
    };
    for (const auto& c : clauses)  // a → ¬b and b → ¬a
      if (live(c)) ++first[c.first + 1], ++first[c.second + 1];
    for (int x = 0; x < literals; ++x) first[x + 1] += first[x];
    target.resize(first.back());
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (const auto& c : clauses)
      if (live(c)) {
        target[fill[c.first]++] = c.second ^ 1;
        target[fill[c.second]++] = c.first ^ 1;
      }
    std::vector<int> index(literals, -1), low(literals, 0), comp(literals, -1), next(literals);
    std::vector<int> stack, call;
    int counter = 0, comps = 0;
    for (int root = 0; root < literals; ++root) {
      if (index[root] >= 0) continue;
      auto open = [&](int x) {
        index[x] = low[x] = counter++;
        next[x] = first[x];
        stack.push_back(x);
        call.push_back(x);
      };
      open(root);
      while (!call.empty()) {
        const int x = call.back();
        if (next[x] < first[x + 1]) {
          const int w = target[next[x]++];
          if (index[w] < 0) {
            open(w);
          } else if (comp[w] < 0) {
            low[x] = std::min(low[x], index[w]);
          }
          continue;
        }
        call.pop_back();
        if (!call.empty()) low[call.back()] = std::min(low[call.back()], low[x]);
        if (low[x] != index[x]) continue;
        int w;
        do {
          w = stack.back();
          stack.pop_back();
          comp[w] = comps;
        } while (w != x);
        ++comps;
      }
    }
    bool contradiction = false;
    for (int p = 0; 2 * p < literals; ++p)
      if (!given_up[p] && comp[2 * p] == comp[2 * p + 1]) given_up[p] = contradiction = true;
    if (contradiction) continue;
    std::vector<char> holds(literals);
    for (int x = 0; x < literals; ++x) holds[x] = comp[x] < comp[x ^ 1];
    return holds;
  }
}

}  // namespace

BlossomMatching& BlossomMatching::update_edge(int e, int64_t weight, bool enabled) {
  if (e < 0 || e >= static_cast<int>(end_a_.size()))
    throw std::invalid_argument("blossom matching: no edge " + std::to_string(e));
  const uint64_t magnitude =
      weight < 0 ? uint64_t{0} - static_cast<uint64_t>(weight) : static_cast<uint64_t>(weight);
  if (magnitude >= weight_bound_)
    throw std::invalid_argument("blossom matching: |weight| * (nodes + 1) must stay below 2^58");
  w2_[e] = 2 * weight;
  enabled_[e] = enabled;
  adj_[adj_pos_[2 * e]].w2 = adj_[adj_pos_[2 * e + 1]].w2 = enabled ? w2_[e] : kDisabled;
  if (kept_) updated_.push_back(e);
  return *this;
}

BlossomMatching& BlossomMatching::reopen(int v) {
  if (v < 0 || v >= n_)
    throw std::invalid_argument("blossom matching: no vertex " + std::to_string(v));
  if (kept_) reopened_.push_back(v);
  return *this;
}

// The top blossom b dissolves into its children, its z spread over its vertices (z/2 each:
// edges inside b keep their slack, edges leaving it gain z/2). Its base's matched edge is then
// no longer tight unless z was 0, and is given up. O(children): the z/2 goes into the
// children's offsets (a vertex's dual is its own value plus its top's offset), since a
// reopened vertex deep in nested blossoms dissolves every level above it.
void BlossomMatching::dissolve_top(int b) {
  const int64_t half = z_[b] / 2;
  const int64_t off = top_[b].off + half;
  const int base = base_[b], e = mate_[base];
  if (half != 0 && e >= 0) mate_[base] = mate_[other(e, base)] = -1;
  for (int k : cycle(b).children) {
    link_[k].parent = -1;
    top_[k] = Top{};
    top_[k].off = off;
  }
  cycle(b).children.clear();
  cycle(b).edge.clear();
  cycle(b).from.clear();
  cycle(b).to.clear();
  z_[b] = 0;
  top_[b] = Top{};
  ++link_[b].gen;  // jumps to b are no longer trusted
  free_ids_.push_back(b);
}

// Makes every dual even (see the header). Odd tops come in matched pairs (a matched edge is
// tight, so its ends share parity); one of each pair moves down by 1 and the other up, which
// keeps their edge tight. An edge between two odd tops has even slack, so only a tight one
// whose ends both move down would break: "not both down" per such edge is a 2-SAT clause over
// the pairs' choices, solved exactly (strongly connected components of the implication
// graph). A pair whose choice is contradictory moves up on both ends and is unmatched (up
// never breaks an edge), and the rest is solved again. Edges to even tops have odd slack
// (≥ 1), which a move of 1 cannot break; free odd tops move up.
void BlossomMatching::shift_parity() {
  std::vector<int> odd;
  ++mark_stamp_;
  for (int v = 0; v < n_; ++v) {
    const int t = top_of(v);
    if (mark_[t] == mark_stamp_) continue;
    mark_[t] = mark_stamp_;
    if ((y_[v] + top_[t].off) & 1) odd.push_back(t);
  }
  // A blossom of z = 0 cannot give 2 to a move up: expand it (free; nothing changes).
  for (size_t i = 0; i < odd.size(); ++i) {
    const int t = odd[i];
    if (!nontrivial(t) || z_[t] != 0) continue;
    const std::vector<int> kids = cycle(t).children;
    dissolve_top(t);
    odd.insert(odd.end(), kids.begin(), kids.end());
  }
  auto move = [&](int t, int s) {
    top_[t].off += s;
    if (nontrivial(t)) z_[t] -= 2 * s;
  };
  // Literal 2p: the pair's first top moves down; 2p + 1: its partner does.
  std::vector<int> literal(link_.size(), -1), pair_top;
  for (int t : odd) {
    const bool expanded = nontrivial(t) && cycle(t).children.empty();
    if (expanded || literal[t] >= 0) continue;
    const int base = base_[t], e = mate_[base];
    if (e < 0) {
      move(t, +1);
      continue;
    }
    const int partner = top_of(other(e, base));
    literal[t] = static_cast<int>(pair_top.size());
    literal[partner] = literal[t] + 1;
    pair_top.insert(pair_top.end(), {t, partner});
  }
  // Clauses: a tight edge between tops of literals a and b (not partners) forbids a ∧ b.
  std::vector<std::pair<int, int>> clauses;
  for (int t : pair_top) {
    leaves(t, scratch_);
    for (int u : scratch_) {
      const int64_t yu = y_[u] + top_[t].off;
      for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
        const Incidence& in = adj_[k];
        if (in.w2 == kDisabled) continue;
        const int v = in.other, r = top_of(v);
        if (r == t || literal[r] < 0 || (literal[r] ^ 1) == literal[t]) continue;
        if (literal[t] < literal[r] && yu + y_[v] + top_[r].off == in.w2)
          clauses.emplace_back(literal[t], literal[r]);
      }
    }
  }
  std::vector<char> given_up(pair_top.size() / 2, 0);
  std::vector<char> down = solve_two_sat(static_cast<int>(pair_top.size()), clauses, given_up);
  for (size_t p = 0; p < given_up.size(); ++p) {
    const int t = pair_top[2 * p], partner = pair_top[2 * p + 1];
    if (given_up[p]) {
      ++parity_unmatched_pairs_;
      move(t, +1);
      move(partner, +1);
      const int base = base_[t];
      mate_[other(mate_[base], base)] = -1;
      mate_[base] = -1;
      continue;
    }
    move(t, down[2 * p] ? -1 : +1);
    move(partner, down[2 * p] ? +1 : -1);
  }
}

void BlossomMatching::resume() {
  // Duals as plain values (no offsets, nothing labeled), the clock back at 0; dissolving
  // blossoms below gives offsets to their children again.
  std::vector<int64_t> y(n_);
  for (int v = 0; v < n_; ++v) y[v] = dual(v);
  y_ = std::move(y);
  for (Top& t : top_) t = Top{};
  now_ = 0;
  for (int64_t x : y_)
    if (x <= -(int64_t{1} << 60) || x >= (int64_t{1} << 60))
      throw std::invalid_argument("blossom matching: duals beyond 2^60, cannot resume");
  parity_unmatched_pairs_ = 0;
  std::vector<int> open;
  ++mark_stamp_;
  auto add = [&](int v) {
    if (mark_[v] == mark_stamp_) return;
    mark_[v] = mark_stamp_;
    open.push_back(v);
  };
  for (int v : reopened_) add(v);
  // An updated edge needs a reopened end, whose dual is then set for its new weight.
  for (int e : updated_)
    if (mark_[end_a_[e]] != mark_stamp_ && mark_[end_b_[e]] != mark_stamp_) add(end_a_[e]);
  updated_.clear();
  std::vector<int> chain;
  for (int v : open) {
    // v's blossoms, outermost first: each is a top when its turn comes.
    chain.clear();
    for (int b = link_[v].parent; b >= 0; b = link_[b].parent) chain.push_back(b);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) dissolve_top(*it);
    if (const int e = mate_[v]; e >= 0) mate_[v] = mate_[other(e, v)] = -1;
  }
  // As low as their edges allow, one vertex after another: each sees its neighbours' current
  // duals (v is its own top, so no z applies), so every edge stays feasible and v is tight on
  // one of them, where the cheapest way to match it again starts. (Keeping the old dual where
  // it is still feasible measured slower: free vertices then wait for the trees to lower it.)
  // Even, as every dual at a start.
  for (int v : open) {
    int64_t y = std::numeric_limits<int64_t>::min();
    for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k) {
      const Incidence& in = adj_[k];
      if (in.w2 != kDisabled) y = std::max(y, in.w2 - dual(in.other));
    }
    if (y == std::numeric_limits<int64_t>::min()) y = dual(v);  // no edge: anything goes
    top_[v].off = 0;
    y_[v] = y + (y & 1);
  }
  // With nothing reopened every vertex stays matched: no tree grows, parity does not matter,
  // and the run only checks the certificate.
  if (!open.empty()) shift_parity();
}

}  // namespace bimdf::detail
