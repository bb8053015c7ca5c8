// convex_network_simplex.hpp: the primal network simplex over convex piecewise-linear arcs.
#include "backend/convex_network_simplex.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace bimdf::detail {
namespace {

// A slope that no potential difference can beat: |π(u) − π(v)| < 2^62 under the bound on the
// slopes (every tree path from the root holds one artificial arc, ≤ M, and real ones).
constexpr int64_t kBlocked = int64_t{1} << 62;
constexpr int64_t kMaxFinitePoint = int64_t{1} << 62;

}  // namespace

ConvexNetworkSimplex::ConvexNetworkSimplex(const ConvexMcf& mcf) : mcf_(mcf) {
  n_ = mcf.num_nodes();
  m_ = mcf.num_arcs();
  auto bad = [](const std::string& what) {
    throw std::invalid_argument("convex network simplex: " + what);
  };
  if (static_cast<int>(mcf.target.size()) != m_ || static_cast<int>(mcf.start.size()) != m_ ||
      static_cast<int>(mcf.first.size()) != m_ + 1 || mcf.point.size() != mcf.slope.size() ||
      (m_ > 0 && (mcf.first[0] != 0 || mcf.first[m_] != static_cast<int>(mcf.point.size()))))
    bad("array sizes do not match");
  int64_t total = 0;
  for (int64_t b : mcf.supply)
    if (__builtin_add_overflow(total, b, &total)) bad("supplies overflow");
  if (total != 0) bad("supplies sum to " + std::to_string(total) + ", not 0");
  for (int j = 0; j < m_; ++j) {
    const std::string arc = "arc " + std::to_string(j) + ": ";
    if (mcf.source[j] < 0 || mcf.source[j] >= n_ || mcf.target[j] < 0 || mcf.target[j] >= n_)
      bad(arc + "end out of range");
    const int lo = mcf.first[j], hi = mcf.first[j + 1] - 1;
    if (hi - lo < 1) bad(arc + "fewer than two breakpoints");
    for (int k = lo; k <= hi; ++k) {
      const int64_t p = mcf.point[k];
      const bool infinite = (k == lo && p == -kUnboundedPoint) || (k == hi && p == kUnboundedPoint);
      if (!infinite && (p < -kMaxFinitePoint || p > kMaxFinitePoint))
        bad(arc + "breakpoint beyond ±2^62");
      if (k > lo && mcf.point[k - 1] >= p) bad(arc + "breakpoints not increasing");
      if (k > lo && k < hi && mcf.slope[k - 1] > mcf.slope[k]) bad(arc + "slopes not convex");
    }
    if (mcf.start[j] < lo || mcf.start[j] > hi ||
        std::abs(mcf.point[mcf.start[j]]) > kMaxFinitePoint)
      bad(arc + "start not a finite breakpoint");
  }
}

// Breakpoints and slopes of real arc j are mcf_'s; artificial arc m + v has breakpoints 0 and
// +∞ (local indices 0 and 1) and the slope art_cost_[v].
int64_t ConvexNetworkSimplex::point(int j, int k) const {
  if (j >= m_) return k == 0 ? 0 : kUnboundedPoint;
  return mcf_.point[k];
}

void ConvexNetworkSimplex::set_nonbasic(int j, int k) {
  at_[j] = k;
  Priced& p = priced_[j];
  if (j >= m_) {
    p.up = k == 0 ? art_cost_[j - m_] : kBlocked;
    p.down = -kBlocked;
    return;
  }
  p.up = k < mcf_.first[j + 1] - 1 ? mcf_.slope[k] : kBlocked;
  p.down = k > mcf_.first[j] ? mcf_.slope[k - 1] : -kBlocked;
}

void ConvexNetworkSimplex::initialize() {
  root_ = n_;
  const int all = m_ + n_;
  priced_.resize(all);
  x_.assign(all, 0);
  at_.assign(all, 0);
  art_cost_.assign(n_, 0);
  pi_.assign(n_ + 1, 0);
  link_.assign(n_ + 1, Link{-1, 1, -1, false, 0, 0, 0});
  thread_.assign(n_ + 1, 0);
  rev_thread_.assign(n_ + 1, 0);
  last_succ_.assign(n_ + 1, 0);

  int64_t max_slope = 0;
  for (int j = 0; j < m_; ++j)
    for (int k = mcf_.first[j]; k < mcf_.first[j + 1] - 1; ++k)
      max_slope = std::max(max_slope, std::abs(mcf_.slope[k]));
  if (static_cast<double>(max_slope) * (n_ + 1) > 0x1p60)
    throw std::invalid_argument("convex network simplex: slopes beyond 2^60 / (nodes + 1)");
  // Above the cost of any path of real arcs, so artificial flow is a last resort.
  const int64_t big_m = (max_slope + 1) * (n_ + 1);

  std::vector<int64_t> excess = mcf_.supply;  // outflow still owed by each node
  for (int j = 0; j < m_; ++j) {
    priced_[j].source = mcf_.source[j];
    priced_[j].target = mcf_.target[j];
    x_[j] = mcf_.point[mcf_.start[j]];
    if (__builtin_sub_overflow(excess[mcf_.source[j]], x_[j], &excess[mcf_.source[j]]) ||
        __builtin_add_overflow(excess[mcf_.target[j]], x_[j], &excess[mcf_.target[j]]))
      throw std::invalid_argument("convex network simplex: start flows overflow");
    set_nonbasic(j, mcf_.start[j]);
  }
  for (int v = 0; v < n_; ++v) {
    const int a = m_ + v;
    const bool up = excess[v] >= 0;
    art_cost_[v] = up ? 0 : big_m;
    priced_[a] = up ? Priced{v, root_, 0, 0} : Priced{root_, v, big_m, big_m};
  }
  block_size_ = std::max(10, static_cast<int>((getenv("CNS_BF") ? atof(getenv("CNS_BF")) : 2.0) *
                                              std::sqrt(static_cast<double>(m_))));
  next_scan_ = 0;
  start_tree_cuts_ = 0;
  if (static_cast<int>(start_parent_.size()) == n_ && n_ > 0) {
    build_start_tree(excess, big_m);
    return;
  }
  // Every node hangs from the root by its artificial arc, oriented to carry its excess with a
  // non-negative flow: up (cost 0) for a surplus or none, down (cost M) for a deficit. Then
  // every node can send flow to the root, the tree is strongly feasible.
  for (int v = 0; v < n_; ++v) {
    const int a = m_ + v;
    const bool up = excess[v] >= 0;
    at_[a] = 0;
    pi_[v] = up ? 0 : big_m;
    link_[v] = Link{root_, 1, a, up, up ? excess[v] : -excess[v], 0, kUnboundedPoint};
    thread_[v] = v + 1;
    rev_thread_[v + 1] = v;
    last_succ_[v] = v;
  }
  link_[root_].succ_num = n_ + 1;
  thread_[root_] = n_ > 0 ? 0 : root_;
  rev_thread_[thread_[root_]] = root_;
  if (n_ > 0) thread_[n_ - 1] = root_;
  last_succ_[root_] = n_ > 0 ? n_ - 1 : root_;
}

ConvexNetworkSimplex& ConvexNetworkSimplex::start_tree(std::vector<int> parent) {
  start_parent_ = std::move(parent);
  return *this;
}

std::vector<int> ConvexNetworkSimplex::tree_parent() const {
  std::vector<int> parent(n_, -1);
  if (static_cast<int>(link_.size()) != n_ + 1) return parent;
  for (int v = 0; v < n_; ++v) parent[v] = link_[v].parent == root_ ? -1 : link_[v].parent;
  return parent;
}

// The start tree of start_tree(): candidate tree arcs, their flows from the bottom up, cuts
// where a flow leaves its arc's range or could not move towards the root, then the thread,
// sizes and potentials of the tree that is left. `excess` is each node's outflow still owed
// after the non-tree arcs' starts (the start tree arcs' own starts included).
void ConvexNetworkSimplex::build_start_tree(const std::vector<int64_t>& excess, int64_t big_m) {
  // Incident arcs per node, to find an arc to each candidate parent.
  std::vector<int> inc_first(n_ + 1, 0), inc(2 * static_cast<size_t>(m_));
  for (int j = 0; j < m_; ++j) {
    ++inc_first[mcf_.source[j] + 1];
    ++inc_first[mcf_.target[j] + 1];
  }
  for (int v = 0; v < n_; ++v) inc_first[v + 1] += inc_first[v];
  {
    std::vector<int> fill(inc_first.begin(), inc_first.end() - 1);
    for (int j = 0; j < m_; ++j) {
      inc[fill[mcf_.source[j]]++] = j;
      inc[fill[mcf_.target[j]]++] = j;
    }
  }
  std::vector<int> par(n_ + 1, root_), arc(n_, -1);
  par[root_] = -1;
  for (int v = 0; v < n_; ++v) {
    const int p = start_parent_[v];
    if (p < 0 || p >= n_ || p == v) continue;
    for (int i = inc_first[v]; i < inc_first[v + 1]; ++i) {
      const int j = inc[i];
      if (mcf_.source[j] + mcf_.target[j] - v == p) {
        par[v] = p;
        arc[v] = j;
        break;
      }
    }
  }
  // Parents before children (nodes on a cycle of `par` hang from the root instead).
  auto children_of = [&](std::vector<int>& first, std::vector<int>& list) {
    first.assign(n_ + 2, 0);
    list.assign(n_, 0);
    for (int v = 0; v < n_; ++v) ++first[par[v] + 1];
    for (int v = 0; v <= n_; ++v) first[v + 1] += first[v];
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int v = 0; v < n_; ++v) list[fill[par[v]]++] = v;
  };
  std::vector<int> child_first, child, order;
  children_of(child_first, child);
  std::vector<char> seen(n_ + 1, 0);
  auto visit_from = [&](int top) {
    std::vector<int> stack{top};
    seen[top] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (v != root_) order.push_back(v);
      for (int i = child_first[v]; i < child_first[v + 1]; ++i)
        if (!seen[child[i]]) {
          seen[child[i]] = 1;
          stack.push_back(child[i]);
        }
    }
  };
  visit_from(root_);
  for (int v = 0; v < n_; ++v)
    if (!seen[v]) {
      par[v] = root_;
      arc[v] = -1;
      visit_from(v);
    }

  // From the leaves up: the flow each tree arc must carry, kept where it fits.
  std::vector<int64_t> owed = excess;
  std::vector<int> segment(n_, -1);
  for (int i = n_ - 1; i >= 0; --i) {
    const int v = order[i], j = arc[v];
    if (j < 0) continue;
    const bool up = mcf_.source[j] == v;
    int64_t x;
    if (__builtin_add_overflow(x_[j], up ? owed[v] : -owed[v], &x)) x = kUnboundedPoint;
    // A segment that holds x and leaves room towards the root: above x for an up arc
    // (towards the root is more flow), below x for a down arc.
    const int lo = mcf_.first[j], hi = mcf_.first[j + 1] - 1;
    int k = -1;
    for (int t = lo; t < hi; ++t)
      if (up ? mcf_.point[t] <= x && x < mcf_.point[t + 1]
             : mcf_.point[t] < x && x <= mcf_.point[t + 1]) {
        k = t;
        break;
      }
    if (k < 0 || std::abs(x) > kMaxFinitePoint) {
      par[v] = root_;
      arc[v] = -1;
      ++start_tree_cuts_;
      continue;
    }
    segment[v] = k;
    x_[j] = x;
    owed[par[v]] += owed[v];
  }

  // The tree that is left: links, thread in preorder, sizes, and potentials from the root down.
  children_of(child_first, child);
  order.clear();
  std::fill(seen.begin(), seen.end(), 0);
  visit_from(root_);
  std::vector<int> pos(n_ + 1, 0);
  pos[root_] = 0;
  for (int i = 0; i < n_; ++i) pos[order[i]] = i + 1;
  int prev = root_;
  for (int v : order) {
    thread_[prev] = v;
    rev_thread_[v] = prev;
    prev = v;
  }
  thread_[prev] = root_;
  rev_thread_[root_] = prev;
  link_[root_] = Link{-1, n_ + 1, -1, false, 0, 0, 0};
  for (int i = 0; i < n_; ++i) {
    const int v = order[i], j = arc[v];
    if (j < 0) {
      const int a = m_ + v;
      const bool up = owed[v] >= 0;
      art_cost_[v] = up ? 0 : big_m;
      priced_[a] = up ? Priced{v, root_, 0, 0} : Priced{root_, v, big_m, big_m};
      at_[a] = 0;
      x_[a] = 0;
      link_[v] = Link{root_, 1, a, up, up ? owed[v] : -owed[v], 0, kUnboundedPoint};
      pi_[v] = up ? 0 : big_m;
      continue;
    }
    const int k = segment[v];
    const bool up = mcf_.source[j] == v;
    at_[j] = k;
    priced_[j].up = priced_[j].down = mcf_.slope[k];
    link_[v] = Link{par[v], 1, j, up, x_[j], mcf_.point[k], mcf_.point[k + 1]};
    pi_[v] = up ? pi_[par[v]] - mcf_.slope[k] : pi_[par[v]] + mcf_.slope[k];
  }
  for (int i = n_ - 1; i >= 0; --i) link_[par[order[i]]].succ_num += link_[order[i]].succ_num;
  link_[root_].succ_num = n_ + 1;
  for (int i = 0; i < n_; ++i) {
    const int v = order[i];
    last_succ_[v] = order[pos[v] - 1 + link_[v].succ_num - 1];
  }
  last_succ_[root_] = order[n_ - 1];
}

// The subtree S below the tree arc of `leave_node` (a node on the path from u_in up to `apex`)
// leaves the tree and hangs again from v_in by the arc `entering`, rooted at u_in; the
// potentials of S move by `shift`. S's preorder, re-rooted, is the old run of u_in, then for
// each next node p_i on the path up to leave_node its old run without that of p_(i−1): the part
// before it and the part after it. Path nodes end at the new run's last node; sizes change on
// the two paths below the apex only.
void ConvexNetworkSimplex::rehang(int u_in, int v_in, const Link& entering, int leave_node,
                                  int apex, int64_t shift) {
  path_.clear();
  for (int w = u_in;; w = link_[w].parent) {
    path_.push_back(w);
    if (w == leave_node) break;
  }
  const int k = static_cast<int>(path_.size());
  path_last_.resize(k);
  path_after_.resize(k);
  path_before_.resize(k);
  path_size_.resize(k);
  path_link_.resize(k);
  for (int i = 0; i < k; ++i) {
    const int p = path_[i];
    path_last_[i] = last_succ_[p];
    path_after_[i] = thread_[last_succ_[p]];
    path_before_[i] = rev_thread_[p];
    path_size_[i] = link_[p].succ_num;
    path_link_[i] = link_[p];
  }
  const int top = leave_node, last = path_last_[k - 1], size = path_size_[k - 1];
  // Potentials matter up to a common shift: the smaller side moves.
  if (2 * size <= n_ + 1) {
    for (int v = top;; v = thread_[v]) {
      pi_[v] += shift;
      if (v == last) break;
    }
  } else {
    for (int v = thread_[last]; v != top; v = thread_[v]) pi_[v] -= shift;
  }

  // Cut S out of the thread and out of its ancestors' runs.
  const int old_parent = link_[top].parent;
  const int before = path_before_[k - 1], after = path_after_[k - 1];
  thread_[before] = after;
  rev_thread_[after] = before;
  for (int a = old_parent; a != apex; a = link_[a].parent) link_[a].succ_num -= size;
  for (int a = old_parent; a >= 0 && last_succ_[a] == last; a = link_[a].parent)
    last_succ_[a] = before;

  // S's new preorder, linked run by run.
  int tail = path_last_[0];
  auto link = [&](int from, int to) {
    thread_[from] = to;
    rev_thread_[to] = from;
  };
  for (int i = 1; i < k; ++i) {
    link(tail, path_[i]);
    tail = path_before_[i - 1];
    if (path_last_[i] != path_last_[i - 1]) {
      link(tail, path_after_[i - 1]);
      tail = path_last_[i];
    }
  }
  // Turn the path around: each node's parent and tree arc are the ones below it, u_in's are
  // v_in and the entering arc.
  for (int i = 0; i < k; ++i) {
    const int w = path_[i];
    Link& l = link_[w];
    l = i == 0 ? entering : path_link_[i - 1];
    l.parent = i == 0 ? v_in : path_[i - 1];
    l.up = priced_[l.pred].source == w;
    l.succ_num = i == 0 ? size : size - path_size_[i - 1];
    last_succ_[w] = tail;
  }

  // S goes in right after v_in, as its first child.
  const int next = thread_[v_in];
  link(v_in, u_in);
  link(tail, next);
  if (last_succ_[v_in] == v_in)
    for (int a = v_in; a >= 0 && last_succ_[a] == v_in; a = link_[a].parent) last_succ_[a] = tail;
  for (int a = v_in; a != apex; a = link_[a].parent) link_[a].succ_num += size;
}

bool ConvexNetworkSimplex::find_entering(int& arc, int& direction) {
  int64_t best = 0;
  int best_arc = -1, best_direction = 0, left_in_block = block_size_;
  const Priced* priced = priced_.data();
  const int64_t* pi = pi_.data();
  for (int scanned = 0; scanned < m_; ++scanned) {
    const int j = next_scan_;
    if (++next_scan_ == m_) next_scan_ = 0;
    const Priced& p = priced[j];
    const int64_t d = pi[p.source] - pi[p.target];
    // Increasing pays when up + d < 0, decreasing when down + d > 0; tree arcs have
    // up = down = −d, so neither.
    const int64_t gain_up = -(p.up + d), gain_down = p.down + d;
    if (gain_up > best) {
      best = gain_up;
      best_arc = j;
      best_direction = 1;
    }
    if (gain_down > best) {
      best = gain_down;
      best_arc = j;
      best_direction = -1;
    }
    if (--left_in_block == 0) {
      if (best_arc >= 0) break;
      left_in_block = block_size_;
    }
  }
  arc = best_arc;
  direction = best_direction;
  return best_arc >= 0;
}

namespace {

// How far a tree arc can move up (towards hi) or down (towards lo): kUnboundedPoint if no end.
inline int64_t room(int64_t x, int64_t lo, int64_t hi, bool increase) {
  if (increase) return hi == kUnboundedPoint ? kUnboundedPoint : hi - x;
  return lo == -kUnboundedPoint ? kUnboundedPoint : x - lo;
}

}  // namespace

void ConvexNetworkSimplex::pivot(int e, int direction) {
  // The cycle's flow runs along e from `first` to `second`, up the tree to the apex, and down
  // to `first`. (Real arcs only enter: the search skips artificial ones.)
  const int first = direction > 0 ? mcf_.source[e] : mcf_.target[e];
  const int second = direction > 0 ? mcf_.target[e] : mcf_.source[e];
  int a = first, b = second;
  while (a != b) {  // an ancestor's subtree is larger than its descendants'
    if (link_[a].succ_num < link_[b].succ_num)
      a = link_[a].parent;
    else
      b = link_[b].parent;
  }
  const int apex = a;

  const int k = at_[e];
  const int64_t end = mcf_.point[direction > 0 ? k + 1 : k - 1];
  int64_t delta = std::abs(end) == kUnboundedPoint ? kUnboundedPoint : std::abs(end - x_[e]);
  // Cunningham's rule: of the blocking arcs, the last one on the cycle from the apex. Going up
  // from `first` runs against the cycle's order (the deepest tie wins), from `second` with it.
  // Flow runs down from the parent on first's side (an up arc decreases), up on second's.
  int leave_node = -1;
  bool leave_on_first = false;
  for (int w = first; w != apex; w = link_[w].parent) {
    const Link& l = link_[w];
    const int64_t r = room(l.x, l.lo, l.hi, !l.up);
    if (r < delta) {
      delta = r;
      leave_node = w;
      leave_on_first = true;
    }
  }
  for (int w = second; w != apex; w = link_[w].parent) {
    const Link& l = link_[w];
    const int64_t r = room(l.x, l.lo, l.hi, l.up);
    if (r <= delta) {
      delta = r;
      leave_node = w;
      leave_on_first = false;
    }
  }
  if (delta == kUnboundedPoint) {
    status_ = Status::Unbounded;
    return;
  }
  ++pivots_;
  if (delta > 0) {
    x_[e] += direction * delta;
    for (int w = first; w != apex; w = link_[w].parent) link_[w].x += link_[w].up ? -delta : delta;
    for (int w = second; w != apex; w = link_[w].parent) link_[w].x += link_[w].up ? delta : -delta;
  }
  if (leave_node < 0) {  // e reached its next breakpoint and stays out of the tree
    set_nonbasic(e, k + direction);
    return;
  }

  // The leaving arc stops at the end of its segment it reached.
  const Link& out = link_[leave_node];
  x_[out.pred] = out.x;
  set_nonbasic(out.pred, out.x == out.lo ? at_[out.pred] : at_[out.pred] + 1);
  // e enters on the segment it moves into; its potentials will make that slope tight.
  const int segment = direction > 0 ? k : k - 1;
  at_[e] = segment;
  priced_[e].up = priced_[e].down = mcf_.slope[segment];
  const Link entering{-1, 0, e, false, x_[e], mcf_.point[segment], mcf_.point[segment + 1]};

  // The subtree cut off at leave_node hangs now from e: the path from e's end on that side up
  // to leave_node turns around.
  const int u_in = leave_on_first ? first : second;
  const int v_in = leave_on_first ? second : first;
  const int64_t reduced = mcf_.slope[segment] + pi_[mcf_.source[e]] - pi_[mcf_.target[e]];
  rehang(u_in, v_in, entering, leave_node, apex, u_in == mcf_.source[e] ? -reduced : reduced);
}

ConvexNetworkSimplex::Status ConvexNetworkSimplex::run() {
  initialize();
  status_ = Status::NotRun;
  int e, direction;
  const bool trace = getenv("CNS_TRACE") != nullptr;
  while (find_entering(e, direction)) {
    pivot(e, direction);
    if (status_ == Status::Unbounded) return status_;
    if (trace && pivots_ % 5000 == 0) {
      __int128 art = 0;
      double cost = 0;
      for (int v = 0; v < n_; ++v) {
        int a = link_[v].pred;
        if (a >= m_) art += link_[v].x;
      }
      std::vector<int64_t> xx = x_;
      for (int v = 0; v < n_; ++v) xx[link_[v].pred] = link_[v].x;
      for (int j = 0; j < m_; ++j) {
        // cost relative to start: integrate slopes from point[start] to x
        int64_t x = xx[j];
        int k = mcf_.start[j];
        while (k < mcf_.first[j + 1] - 1 && mcf_.point[k + 1] <= x) {
          cost += (double)mcf_.slope[k] * (mcf_.point[k + 1] - mcf_.point[k]);
          ++k;
        }
        if (k < mcf_.first[j + 1] - 1 && x > mcf_.point[k])
          cost += (double)mcf_.slope[k] * (x - mcf_.point[k]);
        k = mcf_.start[j];
        while (k > mcf_.first[j] && mcf_.point[k - 1] >= x) {
          cost -= (double)mcf_.slope[k - 1] * (mcf_.point[k] - mcf_.point[k - 1]);
          --k;
        }
        if (k > mcf_.first[j] && x < mcf_.point[k])
          cost -= (double)mcf_.slope[k - 1] * (mcf_.point[k] - x);
      }
      fprintf(stderr, "   pivot %ld art %.0f cost %.6g\n", (long)pivots_, (double)art, cost);
    }
  }
  for (int v = 0; v < n_; ++v) x_[link_[v].pred] = link_[v].x;
  for (int v = 0; v < n_; ++v)
    if (x_[m_ + v] > 0) return status_ = Status::Infeasible;
  return status_ = Status::Optimal;
}

}  // namespace bimdf::detail
