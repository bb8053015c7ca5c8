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

constexpr int kTightPasses = 3;
constexpr int kRepairPasses = 4;
constexpr int64_t kInf = std::numeric_limits<int64_t>::max();
// Potentials stay below 2^61 in magnitude and costs below 2^60/(n + 1): reduced costs and
// distances (path costs plus two potentials) then stay below 2^63.
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
  __int128 total = 0;
  for (int64_t s : supply_) {
    supply_sum += s > 0 ? s : 0;
    total += s;
  }
  // Supplies that do not sum to 0 leave either surplus or deficit behind however the flow runs:
  // the exact fallback says which answer that is in its conventions.
  if (total != 0) unsupported_ = true;
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
  arc_.resize(2 * static_cast<size_t>(m_));
  pos_.resize(2 * static_cast<size_t>(m_));
  capped_.assign(m_, 0);
  for (int a = 0; a < m_; ++a) {
    const int p = fill[source[a]]++, q = fill[target[a]]++;
    capped_[a] = capacity[a] == kInf;
    arc_[p] = {cost[a], capped_[a] ? cap_b_ : capacity[a], target[a], q};
    arc_[q] = {-cost[a], 0, source[a], p};
    pos_[2 * a] = p;
    pos_[2 * a + 1] = q;
  }
  node_.assign(n_, NodeState{0, kInf, -1, -1});
}

ShortestPathFlow& ShortestPathFlow::initial_potentials(const std::vector<int64_t>& potential) {
  if (static_cast<int>(potential.size()) != n_)
    throw std::invalid_argument("shortest path flow: " + std::to_string(potential.size()) +
                                " initial potentials for " + std::to_string(n_) + " nodes");
  // Potentials too large to keep the bounds during the run: start from zero instead.
  const bool usable = std::all_of(potential.begin(), potential.end(), [](int64_t p) {
    return p <= kPotentialBound / 2 && p >= -kPotentialBound / 2;
  });
  for (int v = 0; v < n_; ++v) node_[v].potential = usable ? potential[v] : 0;
  // An arc of infinite capacity priced negative would be saturated at B (a huge imbalance, all
  // the solver's work). A few Bellman–Ford passes over those arcs lower their heads' potentials
  // until they price them at 0 — potentials of a nearby problem are usually off by little.
  for (int pass = 0; pass < kRepairPasses; ++pass) {
    bool changed = false;
    for (int a = 0; a < m_; ++a) {
      if (!capped_[a]) continue;
      const ResidualArc& forward = arc_[pos_[2 * a]];
      const int64_t lowered = node_[arc_[forward.reverse].head].potential + forward.cost;
      int64_t& head = node_[forward.head].potential;
      if (lowered < head && lowered >= -kPotentialBound / 2) {
        head = lowered;
        changed = true;
      }
    }
    if (!changed) break;
  }
  return *this;
}

std::vector<int64_t> ShortestPathFlow::potential() const {
  std::vector<int64_t> p(n_);
  for (int v = 0; v < n_; ++v) p[v] = node_[v].potential;
  return p;
}

int64_t ShortestPathFlow::start_imbalance() const {
  if (unsupported_) return std::numeric_limits<int64_t>::max();
  std::vector<int64_t> excess = supply_;
  for (int a = 0; a < m_; ++a) {
    const ResidualArc& forward = arc_[pos_[2 * a]];
    const int v = arc_[forward.reverse].head, w = forward.head;
    if (reduced_cost(v, pos_[2 * a]) < 0) {
      const int64_t full = forward.capacity + arc_[forward.reverse].capacity;
      excess[v] -= full;
      excess[w] += full;
    }
  }
  return surplus(excess);
}

int64_t ShortestPathFlow::surplus(const std::vector<int64_t>& excess) {
  __int128 sum = 0;
  for (int64_t e : excess) sum += std::max<int64_t>(e, 0);
  return static_cast<int64_t>(std::min<__int128>(sum, std::numeric_limits<int64_t>::max()));
}

bool ShortestPathFlow::capped_arc_full() const {
  for (int a = 0; a < m_; ++a)
    if (capped_[a] && arc_[pos_[2 * a]].capacity == 0) return true;
  return false;
}

ShortestPathFlow::Status ShortestPathFlow::run() {
  status_ = Status::NotRun;
  if (unsupported_) return status_ = Status::NeedsExactFallback;
  // A previous run may have left potentials beyond the bounds.
  for (const NodeState& x : node_)
    if (x.potential > kPotentialBound / 2 || x.potential < -kPotentialBound / 2)
      return status_ = Status::NeedsExactFallback;
  // Start: saturate every arc priced negative, so that no residual arc is. Capacities are
  // reset here too, so that run() may be called again.
  excess_ = supply_;
  for (int a = 0; a < m_; ++a) {
    ResidualArc& forward = arc_[pos_[2 * a]];
    ResidualArc& backward = arc_[forward.reverse];
    const int v = backward.head, w = forward.head;
    forward.capacity += backward.capacity;
    backward.capacity = 0;
    if (reduced_cost(v, pos_[2 * a]) < 0) {
      std::swap(forward.capacity, backward.capacity);
      excess_[v] -= backward.capacity;
      excess_[w] += backward.capacity;
    }
  }
  initial_imbalance_ = surplus(excess_);
  searches_ = 0;
  work_ = 0;
  tight_routed_ = route_on_tight_arcs();
  if (work_ > work_limit_) return status_ = Status::WorkLimitReached;
  for (int v = 0; v < n_; ++v)
    while (excess_[v] > 0) {
      const Search search = augment_from(v);
      if (search == Search::GaveUp) return status_ = Status::WorkLimitReached;
      if (search == Search::NoDeficit) {
        // No deficit reachable: the nodes reached have more supply than can leave them —
        // unless a capped arc is full, whose true capacity would let more out.
        return status_ = capped_arc_full() ? Status::NeedsExactFallback : Status::Infeasible;
      }
      if (status_ == Status::NeedsExactFallback) return status_;
    }
  if (capped_arc_full()) return status_ = Status::NeedsExactFallback;
  if (!verify()) throw std::logic_error("shortest path flow: the optimality check failed");
  return status_ = Status::Optimal;
}

ShortestPathFlow::Search ShortestPathFlow::augment_from(int s) {
  ++searches_;
  if (search_mark_ >= std::numeric_limits<int>::max() - 2) {
    for (NodeState& x : node_) x.mark = -1;
    search_mark_ = 0;
  }
  search_mark_ += 2;
  const int reached = search_mark_, settled = search_mark_ + 1;
  // A binary min-heap of (distance, node) with stale entries skipped on pop.
  auto& heap = heap_;
  const auto later = std::greater<std::pair<int64_t, int>>();
  heap.clear();
  std::vector<int>& settled_order = settled_order_;
  settled_order.clear();
  // Nodes reached at the distance being settled skip the heap: with good potentials most
  // residual arcs are tight, and a search mostly walks them.
  std::vector<int>& level = level_;
  level.clear();
  int64_t d = 0;
  node_[s].dist = 0;
  node_[s].mark = reached;
  level.push_back(s);
  int t = -1;
  while (true) {
    if (work_ > work_limit_) return Search::GaveUp;
    int u;
    if (!level.empty()) {
      u = level.back();
      level.pop_back();
    } else {
      if (heap.empty()) break;
      std::pop_heap(heap.begin(), heap.end(), later);
      d = heap.back().first;
      u = heap.back().second;
      heap.pop_back();
    }
    NodeState& x = node_[u];
    if (x.mark == settled || d != x.dist) continue;
    x.mark = settled;
    settled_order.push_back(u);
    if (excess_[u] < 0) {
      t = u;
      break;
    }
    const int64_t base = d + x.potential;
    work_ += first_[u + 1] - first_[u];
    for (int p = first_[u]; p < first_[u + 1]; ++p) {
      const ResidualArc& a = arc_[p];
      if (a.capacity == 0) continue;
      NodeState& y = node_[a.head];
      if (y.mark == settled) continue;
      const int64_t nd = base + a.cost - y.potential;
      if (y.mark != reached || nd < y.dist) {
        y.mark = reached;
        y.dist = nd;
        y.pred = p;
        if (nd == d) {
          level.push_back(a.head);
        } else {
          heap.push_back({nd, a.head});
          std::push_heap(heap.begin(), heap.end(), later);
        }
      }
    }
  }
  if (t < 0) return Search::NoDeficit;
  // Potentials: settled nodes drop by their shortfall to t's distance; with the others
  // unchanged, every residual reduced cost stays ≥ 0 and the path to t becomes tight.
  const int64_t dt = node_[t].dist;
  for (int v : settled_order) {
    node_[v].potential += node_[v].dist - dt;
    if (node_[v].potential < -kPotentialBound) status_ = Status::NeedsExactFallback;
  }
  int64_t delta = std::min(excess_[s], -excess_[t]);
  for (int v = t; v != s; v = tail(node_[v].pred))
    delta = std::min(delta, arc_[node_[v].pred].capacity);
  for (int v = t; v != s; v = tail(node_[v].pred)) {
    ResidualArc& a = arc_[node_[v].pred];
    a.capacity -= delta;
    arc_[a.reverse].capacity += delta;
  }
  excess_[s] -= delta;
  excess_[t] += delta;
  return Search::Augmented;
}

int64_t ShortestPathFlow::route_on_tight_arcs() {
  // Depth-first searches over tight arcs, one from each surplus in turn. Any tight path keeps
  // the reduced-cost conditions, so nothing here needs to be complete: nodes whose search
  // failed stay dead for the rest of the pass, arc pointers never go back, and a few passes
  // leave whatever remains to the shortest-path searches.
  int64_t routed = 0;
  std::vector<int> path, current(n_);
  std::vector<char> state(n_);  // 0 unseen this pass, 1 on the path, 2 dead, 3 seen
  auto tight = [&](int u, int p) { return arc_[p].capacity > 0 && reduced_cost(u, p) == 0; };
  for (int pass = 0; pass < kTightPasses; ++pass) {
    int64_t routed_in_pass = 0;
    std::fill(state.begin(), state.end(), 0);
    for (int s = 0; s < n_ && work_ <= work_limit_; ++s) {
      while (excess_[s] > 0 && work_ <= work_limit_) {
        if (state[s] == 0) current[s] = first_[s];
        if (state[s] == 2) break;
        state[s] = 1;
        path.clear();
        int v = s;
        while (!(v != s && excess_[v] < 0)) {
          int& p = current[v];
          for (; p < first_[v + 1]; ++p) {
            ++work_;
            const int w = arc_[p].head;
            if (state[w] != 1 && state[w] != 2 && tight(v, p)) break;
          }
          if (p < first_[v + 1]) {
            const int w = arc_[p].head;
            if (state[w] == 0) current[w] = first_[w];
            state[w] = 1;
            path.push_back(p);
            v = w;
            continue;
          }
          state[v] = 2;  // dead end
          if (path.empty()) break;
          path.pop_back();
          v = path.empty() ? s : arc_[path.back()].head;
          ++current[v];
        }
        if (v == s) break;  // s's search failed: it is dead now
        int64_t delta = std::min(excess_[s], -excess_[v]);
        for (int p : path) delta = std::min(delta, arc_[p].capacity);
        for (int p : path) {
          arc_[p].capacity -= delta;
          arc_[arc_[p].reverse].capacity += delta;
          state[arc_[p].head] = 3;
        }
        excess_[s] -= delta;
        excess_[v] += delta;
        routed_in_pass += delta;
        work_ += static_cast<int64_t>(path.size());
      }
      if (state[s] == 1) state[s] = 3;
    }
    routed += routed_in_pass;
    if (routed_in_pass == 0) break;
  }
  return routed;
}

bool ShortestPathFlow::verify() const {
  std::vector<int64_t> balance(n_, 0);
  for (int a = 0; a < m_; ++a) {
    const ResidualArc& forward = arc_[pos_[2 * a]];
    const ResidualArc& backward = arc_[forward.reverse];
    const int v = backward.head, w = forward.head;
    if (forward.capacity < 0 || backward.capacity < 0) return false;
    const int64_t reduced = reduced_cost(v, pos_[2 * a]);
    if ((forward.capacity > 0 && reduced < 0) || (backward.capacity > 0 && reduced > 0))
      return false;
    balance[v] += backward.capacity;  // the flow
    balance[w] -= backward.capacity;
  }
  return balance == supply_;
}

std::vector<int64_t> ShortestPathFlow::flow() const {
  std::vector<int64_t> f(m_);
  for (int a = 0; a < m_; ++a) f[a] = arc_[pos_[2 * a + 1]].capacity;
  return f;
}

}  // namespace bimdf::detail
