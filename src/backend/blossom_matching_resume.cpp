// BlossomMatching's re-optimization: a run that starts from the previous run's matching, duals
// and blossoms, re-opened around the vertices and edges that changed (blossom_matching.hpp).
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "backend/blossom_matching.hpp"

namespace bimdf::detail {

BlossomMatching& BlossomMatching::update_edge(int e, int64_t weight, bool enabled) {
  if (e < 0 || e >= static_cast<int>(end_a_.size()))
    throw std::invalid_argument("blossom matching: no edge " + std::to_string(e));
  const uint64_t magnitude =
      weight < 0 ? uint64_t{0} - static_cast<uint64_t>(weight) : static_cast<uint64_t>(weight);
  if (magnitude >= weight_bound_)
    throw std::invalid_argument("blossom matching: |weight| * (nodes + 1) must stay below 2^58");
  w2_[e] = 2 * weight;
  enabled_[e] = enabled;
  if (kept_) reopened_.insert(reopened_.end(), {end_a_[e], end_b_[e]});
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
// no longer tight unless z was 0, and is given up.
void BlossomMatching::dissolve_top(int b) {
  const int64_t half = z_[b] / 2;
  leaves(b, scratch_);
  for (int x : scratch_) y_[x] += half;
  const int base = base_[b], e = mate_[base];
  if (half != 0 && e >= 0) mate_[base] = mate_[other(e, base)] = -1;
  for (int k : cycle(b).children) {
    link_[k].parent = -1;
    top_[k] = Top{};
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

// Makes every dual even (see the header): odd tops move by ±1 in pairs along their matched
// edge. An edge from a top to one not yet moved is left to the later one's check, and edges to
// even tops have odd slack (≥ 1), which a move of 1 cannot break.
void BlossomMatching::shift_parity() {
  std::vector<int> odd;
  ++mark_stamp_;
  for (int v = 0; v < n_; ++v) {
    const int t = top_of(v);
    if (mark_[t] == mark_stamp_) continue;
    mark_[t] = mark_stamp_;
    if (y_[v] & 1) odd.push_back(t);
  }
  // A blossom of z = 0 cannot give 2 to a move up: expand it (free; nothing changes).
  for (size_t i = 0; i < odd.size(); ++i) {
    const int t = odd[i];
    if (!nontrivial(t) || z_[t] != 0) continue;
    const std::vector<int> kids = cycle(t).children;
    dissolve_top(t);
    odd.insert(odd.end(), kids.begin(), kids.end());
  }
  std::vector<int8_t> moved(link_.size(), 0);  // per top: −1, +1, or 0 (not yet)
  auto fits = [&](int t, int s) {              // no edge to a moved top below feasibility
    leaves(t, scratch_);
    for (int u : scratch_)
      for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
        const int e = adj_edge_[k], v = other(e, u);
        if (!enabled_[e]) continue;
        const int r = top_of(v);
        if (r != t && moved[r] != 0 && y_[u] + s + y_[v] < w2_[e]) return false;
      }
    return true;
  };
  auto move = [&](int t, int s) {
    leaves(t, scratch_);
    for (int x : scratch_) y_[x] += s;
    if (nontrivial(t)) z_[t] -= 2 * s;
    moved[t] = static_cast<int8_t>(s);
  };
  for (int t : odd) {
    const bool expanded = nontrivial(t) && cycle(t).children.empty();
    if (expanded || moved[t] != 0) continue;
    const int base = base_[t], e = mate_[base];
    if (e < 0) {
      move(t, +1);
      continue;
    }
    const int partner = top_of(other(e, base));
    if (fits(t, -1)) {
      move(t, -1);
      move(partner, +1);
    } else if (fits(partner, -1)) {
      move(partner, -1);
      move(t, +1);
    } else {
      move(t, +1);
      move(partner, +1);
      mate_[base] = mate_[other(e, base)] = -1;
    }
  }
}

void BlossomMatching::resume() {
  // Duals as plain values (no offsets, nothing labeled), the clock back at 0.
  std::vector<int64_t> y(n_);
  for (int v = 0; v < n_; ++v) y[v] = dual(v);
  y_ = std::move(y);
  for (Top& t : top_) t = Top{};
  now_ = 0;
  for (int64_t x : y_)
    if (x <= -(int64_t{1} << 60) || x >= (int64_t{1} << 60))
      throw std::invalid_argument("blossom matching: duals beyond 2^60, cannot resume");
  std::vector<int> open;
  ++mark_stamp_;
  for (int v : reopened_)
    if (mark_[v] != mark_stamp_) {
      mark_[v] = mark_stamp_;
      open.push_back(v);
    }
  for (int v : open) {
    while (link_[v].parent >= 0) dissolve_top(top_of(v));
    if (const int e = mate_[v]; e >= 0) mate_[v] = mate_[other(e, v)] = -1;
  }
  // As low as the edges allow, one vertex after another: each sees its neighbours' current
  // duals (v is its own top, so no z applies), so every edge stays feasible. Even, as every
  // dual at a start.
  for (int v : open) {
    int64_t need = std::numeric_limits<int64_t>::min();
    for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k) {
      const int e = adj_edge_[k];
      if (enabled_[e]) need = std::max(need, w2_[e] - y_[other(e, v)]);
    }
    if (need == std::numeric_limits<int64_t>::min()) need = y_[v];
    y_[v] = need + (need & 1);
  }
  // With nothing reopened every vertex stays matched: no tree grows, parity does not matter,
  // and the run only checks the certificate.
  if (!open.empty()) shift_parity();
}

}  // namespace bimdf::detail
