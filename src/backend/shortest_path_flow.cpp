#include "backend/shortest_path_flow.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace bimdf::detail {
namespace {

constexpr int64_t kInf = std::numeric_limits<int64_t>::max();
// Potentials stay below 2^61 in magnitude, costs below 2^60: reduced costs and distances
// (path costs plus two potentials) then stay below 2^63.
constexpr int64_t kPotentialBound = int64_t{1} << 61;

}  // namespace

ShortestPathFlow::ShortestPathFlow(const std::vector<int64_t>& supply,
                                   const std::vector<int>& source, const std::vector<int>& target,
                                   const std::vector<int64_t>& capacity,
                                   const std::vector<int64_t>& cost)
    : n_(static_cast<int>(supply.size())), m_(static_cast<int>(source.size())) {
  if (target.size() != source.size() || capacity.size() != source.size() ||
      cost.size() != source.size())
    throw std::invalid_argument("shortest path flow: arc arrays of different sizes");
  supply_.assign(supply.begin(), supply.end());
  // The cap B for infinite capacities, and the overflow bounds, in 128 bits.
  __int128 cap_sum = 1, supply_sum = 0;
  const __int128 cost_limit = (__int128{1} << 60) / (static_cast<__int128>(n_) + 1);
  for (int a = 0; a < m_; ++a) {
    if (source[a] < 0 || source[a] >= n_ || target[a] < 0 || target[a] >= n_)
      throw std::invalid_argument("shortest path flow: arc " + std::to_string(a) +
                                  " has an end out of range");
    if (capacity[a] < 0)
      throw std::invalid_argument("shortest path flow: arc " + std::to_string(a) +
                                  " has a negative capacity");
    if (capacity[a] != kInf) cap_sum += capacity[a];
    if (cost[a] > cost_limit || -static_cast<__int128>(cost[a]) > cost_limit) unsupported_ = true;
  }
  for (int64_t s : supply_) supply_sum += s > 0 ? s : 0;
  const __int128 b = cap_sum + supply_sum;
  if (b >= (__int128{1} << 62)) unsupported_ = true;
  cap_b_ = unsupported_ ? 0 : static_cast<int64_t>(b);

  // Residual network in compressed rows: count half-arcs per tail, then place them.
  first_.assign(n_ + 1, 0);
  for (int a = 0; a < m_; ++a) {
    ++first_[source[a] + 1];
    ++first_[target[a] + 1];
  }
  for (int v = 0; v < n_; ++v) first_[v + 1] += first_[v];
  std::vector<int> fill(first_.begin(), first_.end() - 1);
  head_.resize(2 * m_);
  cost_.resize(2 * m_);
  residual_.resize(2 * m_);
  half_of_pos_.resize(2 * m_);
  pos_.resize(2 * m_);
  capped_.assign(m_, 0);
  for (int a = 0; a < m_; ++a) {
    const int p = fill[source[a]]++, q = fill[target[a]]++;
    capped_[a] = capacity[a] == kInf;
    head_[p] = target[a];
    cost_[p] = cost[a];
    residual_[p] = capped_[a] ? cap_b_ : capacity[a];
    head_[q] = source[a];
    cost_[q] = -cost[a];
    residual_[q] = 0;
    half_of_pos_[p] = 2 * a;
    half_of_pos_[q] = 2 * a + 1;
    pos_[2 * a] = p;
    pos_[2 * a + 1] = q;
  }
  potential_.assign(n_, 0);
}

ShortestPathFlow& ShortestPathFlow::initial_potentials(const std::vector<int64_t>& potential) {
  if (static_cast<int>(potential.size()) != n_)
    throw std::invalid_argument("shortest path flow: " + std::to_string(potential.size()) +
                                " initial potentials for " + std::to_string(n_) + " nodes");
  for (int64_t p : potential)
    if (p > kPotentialBound / 2 || p < -kPotentialBound / 2) {
      // Too large to keep the bounds during the run: start from zero instead.
      potential_.assign(n_, 0);
      return *this;
    }
  potential_.assign(potential.begin(), potential.end());
  return *this;
}

int64_t ShortestPathFlow::start_imbalance() const {
  std::vector<int64_t> excess = supply_;
  for (int v = 0; v < n_; ++v)
    for (int p = first_[v]; p < first_[v + 1]; ++p) {
      if (half_of_pos_[p] & 1) continue;
      const int w = head_[p];
      if (cost_[p] + potential_[v] - potential_[w] < 0) {
        const int64_t full = residual_[p] + residual_[pos_[half_of_pos_[p] + 1]];
        excess[v] -= full;
        excess[w] += full;
      }
    }
  int64_t sum = 0;
  for (int64_t e : excess) sum += std::max<int64_t>(e, 0);
  return sum;
}

ShortestPathFlow::Status ShortestPathFlow::run() {
  if (unsupported_) return status_ = Status::NeedsExactFallback;
  // Start: saturate every arc priced negative, so that no residual arc is.
  excess_ = supply_;
  for (int v = 0; v < n_; ++v)
    for (int p = first_[v]; p < first_[v + 1]; ++p) {
      if (half_of_pos_[p] & 1) continue;
      const int w = head_[p];
      const int q = pos_[half_of_pos_[p] + 1];
      // Rows are reset here too, so that run() may be called again.
      residual_[p] += residual_[q];
      residual_[q] = 0;
      if (cost_[p] + potential_[v] - potential_[w] < 0) {
        residual_[q] = residual_[p];
        residual_[p] = 0;
        excess_[v] -= residual_[q];
        excess_[w] += residual_[q];
      }
    }
  initial_imbalance_ = 0;
  for (int64_t e : excess_) initial_imbalance_ += std::max<int64_t>(e, 0);
  searches_ = 0;
  dist_.assign(n_, kInf);
  pred_pos_.assign(n_, -1);
  settled_.assign(n_, 0);
  touched_.clear();
  tight_routed_ = route_on_tight_arcs();
  for (int v = 0; v < n_; ++v)
    while (excess_[v] > 0) {
      if (!augment_from(v)) {
        // No deficit reachable: the nodes reached have more supply than can leave them —
        // unless a capped arc is full, whose true capacity would let more out.
        for (int a = 0; a < m_; ++a)
          if (capped_[a] && residual_[pos_[2 * a]] == 0)
            return status_ = Status::NeedsExactFallback;
        return status_ = Status::Infeasible;
      }
      if (status_ == Status::NeedsExactFallback) return status_;
    }
  for (int a = 0; a < m_; ++a)
    if (capped_[a] && residual_[pos_[2 * a]] == 0) return status_ = Status::NeedsExactFallback;
  if (!verify()) throw std::logic_error("shortest path flow: the optimality check failed");
  return status_ = Status::Optimal;
}

bool ShortestPathFlow::augment_from(int s) {
  ++searches_;
  // A binary min-heap of (distance, node) with stale entries skipped on pop.
  auto& heap = heap_;
  const auto later = std::greater<std::pair<int64_t, int>>();
  heap.clear();
  dist_[s] = 0;
  touched_.push_back(s);
  heap.push_back({0, s});
  int t = -1;
  std::vector<int>& settled_order = settled_order_;
  settled_order.clear();
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, u] = heap.back();
    heap.pop_back();
    if (settled_[u] || d != dist_[u]) continue;
    settled_[u] = 1;
    settled_order.push_back(u);
    if (excess_[u] < 0) {
      t = u;
      break;
    }
    const int64_t pu = potential_[u];
    for (int p = first_[u]; p < first_[u + 1]; ++p) {
      if (residual_[p] == 0) continue;
      const int w = head_[p];
      if (settled_[w]) continue;
      const int64_t nd = d + (cost_[p] + pu - potential_[w]);
      if (nd < dist_[w]) {
        if (dist_[w] == kInf) touched_.push_back(w);
        dist_[w] = nd;
        pred_pos_[w] = p;
        heap.push_back({nd, w});
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
  if (t >= 0) {
    // Potentials: settled nodes drop by their shortfall to t's distance; with the others
    // unchanged, every residual reduced cost stays ≥ 0 and the path to t becomes tight.
    const int64_t dt = dist_[t];
    for (int v : settled_order) {
      potential_[v] += dist_[v] - dt;
      if (potential_[v] < -kPotentialBound) status_ = Status::NeedsExactFallback;
    }
    int64_t delta = std::min(excess_[s], -excess_[t]);
    for (int v = t; v != s;) {
      const int p = pred_pos_[v];
      delta = std::min(delta, residual_[p]);
      v = head_[pos_[half_of_pos_[p] ^ 1]];
    }
    for (int v = t; v != s;) {
      const int p = pred_pos_[v];
      const int q = pos_[half_of_pos_[p] ^ 1];
      residual_[p] -= delta;
      residual_[q] += delta;
      v = head_[q];
    }
    excess_[s] -= delta;
    excess_[t] += delta;
  }
  for (int v : touched_) {
    dist_[v] = kInf;
    settled_[v] = 0;
    pred_pos_[v] = -1;
  }
  touched_.clear();
  return t >= 0;
}

int64_t ShortestPathFlow::route_on_tight_arcs() {
  int64_t routed = 0;
  std::vector<int>& level = level_;
  std::vector<int> queue, path;
  std::vector<int> current(n_);
  auto tight = [&](int u, int p) {
    return residual_[p] > 0 && cost_[p] + potential_[u] - potential_[head_[p]] == 0;
  };
  while (true) {
    // Levels by breadth-first search from every surplus over tight residual arcs.
    level.assign(n_, -1);
    queue.clear();
    for (int v = 0; v < n_; ++v)
      if (excess_[v] > 0) {
        level[v] = 0;
        queue.push_back(v);
      }
    bool reached = false;
    for (size_t i = 0; i < queue.size(); ++i) {
      const int u = queue[i];
      if (excess_[u] < 0) reached = true;
      for (int p = first_[u]; p < first_[u + 1]; ++p)
        if (level[head_[p]] < 0 && tight(u, p)) {
          level[head_[p]] = level[u] + 1;
          queue.push_back(head_[p]);
        }
    }
    if (!reached) return routed;
    // A blocking flow along level-increasing tight arcs, by depth-first search with a current
    // arc per node; dead ends leave the level graph.
    for (int v = 0; v < n_; ++v) current[v] = first_[v];
    for (int s = 0; s < n_; ++s) {
      if (level[s] != 0) continue;
      path.clear();
      int v = s;
      while (excess_[s] > 0) {
        if (v != s && excess_[v] < 0) {
          int64_t delta = std::min(excess_[s], -excess_[v]);
          for (int p : path) delta = std::min(delta, residual_[p]);
          for (int p : path) {
            residual_[p] -= delta;
            residual_[pos_[half_of_pos_[p] ^ 1]] += delta;
          }
          excess_[s] -= delta;
          excess_[v] += delta;
          routed += delta;
          path.clear();
          v = s;
          continue;
        }
        int& p = current[v];
        while (p < first_[v + 1] && !(level[head_[p]] == level[v] + 1 && tight(v, p))) ++p;
        if (p < first_[v + 1]) {
          path.push_back(p);
          v = head_[p];
          continue;
        }
        level[v] = -1;  // dead end
        if (path.empty()) break;
        const int back = path.back();
        path.pop_back();
        v = head_[pos_[half_of_pos_[back] ^ 1]];
        ++current[v];
      }
    }
  }
}

bool ShortestPathFlow::verify() const {
  std::vector<int64_t> balance(n_, 0);
  for (int v = 0; v < n_; ++v)
    for (int p = first_[v]; p < first_[v + 1]; ++p) {
      const int w = head_[p];
      if (residual_[p] < 0) return false;
      if (residual_[p] > 0 && cost_[p] + potential_[v] - potential_[w] < 0) return false;
      if ((half_of_pos_[p] & 1) == 0) {
        const int64_t f = residual_[pos_[half_of_pos_[p] + 1]];
        balance[v] += f;
        balance[w] -= f;
      }
    }
  for (int v = 0; v < n_; ++v)
    if (balance[v] != supply_[v]) return false;
  return true;
}

std::vector<int64_t> ShortestPathFlow::flow() const {
  std::vector<int64_t> f(m_);
  for (int a = 0; a < m_; ++a) f[a] = residual_[pos_[2 * a + 1]];
  return f;
}

}  // namespace bimdf::detail
