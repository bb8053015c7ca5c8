#include "backend/blossom_matching.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace bimdf::detail {
namespace {

constexpr int kEdgeEvent = 0;
constexpr int kExpandEvent = 1;

}  // namespace

void BlossomMatching::push_event(int64_t time, int kind, int id) {
  heap_.push_back({time, kind, id});
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
}

int64_t BlossomMatching::dual(int v) {
  const int b = top_of(v);
  const int64_t t = now_ - label_time_[b];
  const int64_t y = y_[v] + off_[b];
  return label_[b] == kPlus ? y - t : label_[b] == kMinus ? y + t : y;
}

int64_t BlossomMatching::slack(int e) { return dual(end_a_[e]) + dual(end_b_[e]) - w2_[e]; }

void BlossomMatching::leaves(int b, std::vector<int>& out) const {
  out.clear();
  if (!nontrivial(b)) {
    out.push_back(b);
    return;
  }
  std::vector<int> stack{b};
  while (!stack.empty()) {
    const int x = stack.back();
    stack.pop_back();
    if (nontrivial(x))
      stack.insert(stack.end(), children_[x].begin(), children_[x].end());
    else
      out.push_back(x);
  }
}

// Folds the dual change since the top blossom b was labeled into its offset (and its own z),
// so that b can change label or structure: O(1), whatever b's size.
void BlossomMatching::bring_up_to_date(int b) {
  const int64_t t = now_ - label_time_[b];
  if (label_[b] != kNone && t != 0) {
    const int64_t sign = label_[b] == kPlus ? -1 : 1;
    off_[b] += sign * t;
    if (nontrivial(b)) z_[b] -= 2 * sign * t;
  }
  label_time_[b] = now_;
}

// The top blossom of v, found by walking up the blossom forest. Each id remembers a jump to
// an ancestor found earlier (path compression); a jump is trusted only while its target lives
// (same generation: only top blossoms are expanded, so a living target still contains it).
int BlossomMatching::top_of(int v) {
  int x = v;
  path_.clear();
  while (true) {
    const int j = jump_[x];
    const int next = j >= 0 && jump_gen_[x] == gen_[j] ? j : parent_[x];
    if (next < 0) break;
    path_.push_back(x);
    x = next;
  }
  for (int p : path_) {
    jump_[p] = x;
    jump_gen_[p] = gen_[x];
  }
  return x;
}

void BlossomMatching::set_label(int b, Label label, int edge, int from, int to, int tree) {
  bring_up_to_date(b);
  tree_[b] = tree;
  tree_tops_[tree].push_back(b);
  label_[b] = label;
  label_edge_[b] = edge;
  label_from_[b] = from;
  label_to_[b] = to;
  if (label == kPlus) scan_plus(b);
  if (label == kMinus && nontrivial(b)) {
    push_event(now_ + z_[b] / 2, kExpandEvent, b);
  }
}

// Queues the moment each edge from the (now positive) blossom b becomes tight.
void BlossomMatching::scan_plus(int b) {
  leaves(b, scratch_);
  for (int u : scratch_) {
    for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
      const int e = adj_edge_[k], v = other(e, u);
      const int bv = top_of(v);
      if (bv == top_of(u) || label_[bv] == kMinus) continue;
      const int64_t s = slack(e);
      if (label_[bv] == kPlus && (s & 1))
        throw std::logic_error("blossom matching: odd slack between two positive vertices");
      push_event(now_ + (label_[bv] == kPlus ? s / 2 : s), kEdgeEvent, e);
    }
  }
}

// b just left the tree: edges from positive vertices towards it now lose slack.
void BlossomMatching::push_edge_events_towards(int b) {
  std::vector<int> vs;
  leaves(b, vs);
  for (int v : vs)
    for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k) {
      const int e = adj_edge_[k];
      if (label_[top_of(other(e, v))] != kPlus) continue;
      push_event(now_ + slack(e), kEdgeEvent, e);
    }
}

int BlossomMatching::tree_parent(int b) { return label_edge_[b] < 0 ? -1 : top_of(label_from_[b]); }

int BlossomMatching::new_blossom_id() {
  if (!free_ids_.empty()) {
    const int id = free_ids_.back();
    free_ids_.pop_back();
    return id;
  }
  const int id = static_cast<int>(parent_.size());
  parent_.push_back(-1);
  base_.push_back(-1);
  children_.emplace_back();
  cyc_edge_.emplace_back();
  cyc_from_.emplace_back();
  cyc_to_.emplace_back();
  z_.push_back(0);
  off_.push_back(0);
  size_.push_back(0);
  jump_.push_back(-1);
  jump_gen_.push_back(0);
  gen_.push_back(0);
  label_.push_back(kNone);
  label_edge_.push_back(-1);
  label_from_.push_back(-1);
  label_to_.push_back(-1);
  label_time_.push_back(0);
  tree_.push_back(-1);
  mark_.push_back(0);
  return id;
}

void BlossomMatching::grow(int u, int v, int e) {
  const int bv = top_of(v);
  const int tree = tree_[top_of(u)];
  set_label(bv, kMinus, e, u, v, tree);
  const int base = base_[bv];
  const int w = other(mate_[base], base);
  set_label(top_of(w), kPlus, mate_[base], base, w, tree);
}

// Positive u and v in different blossoms of the same tree, joined by a tight edge: the cycle
// through their common ancestor becomes one positive blossom.
void BlossomMatching::make_blossom(int u, int v, int e) {
  const int bu = top_of(u), bv = top_of(v);
  ++mark_stamp_;
  int a = bu, c = bv, lca = -1;
  while (lca < 0) {
    if (a >= 0) {
      if (mark_[a] == mark_stamp_) lca = a;
      mark_[a] = mark_stamp_;
      a = tree_parent(a);
    }
    if (lca >= 0) break;
    if (c >= 0) {
      if (mark_[c] == mark_stamp_) lca = c;
      mark_[c] = mark_stamp_;
      c = tree_parent(c);
    }
  }
  std::vector<int> path_u, path_v;
  for (int x = bu; x != lca; x = tree_parent(x)) path_u.push_back(x);
  for (int x = bv; x != lca; x = tree_parent(x)) path_v.push_back(x);

  const int b = new_blossom_id();
  std::vector<int>& kids = children_[b];
  std::vector<int>&cedge = cyc_edge_[b], &cfrom = cyc_from_[b], &cto = cyc_to_[b];
  kids.assign(1, lca);
  for (auto it = path_u.rbegin(); it != path_u.rend(); ++it) {
    kids.push_back(*it);
    cedge.push_back(label_edge_[*it]);
    cfrom.push_back(label_from_[*it]);
    cto.push_back(label_to_[*it]);
  }
  cedge.push_back(e);
  cfrom.push_back(u);
  cto.push_back(v);
  for (int x : path_v) {
    kids.push_back(x);
    cedge.push_back(label_edge_[x]);
    cfrom.push_back(label_to_[x]);
    cto.push_back(label_from_[x]);
  }
  // The largest child hosts the new blossom: its vertices keep their offset and cached top;
  // only the others are rebased, so a blossom costs the size of its smaller children.
  std::vector<int> were_minus;
  int host = lca;
  for (int k : kids) {
    bring_up_to_date(k);
    if (label_[k] == kMinus) were_minus.push_back(k);
    if (size_[k] > size_[host]) host = k;
  }
  off_[b] = off_[host];
  size_[b] = 0;
  std::vector<int> vs;
  for (int k : kids) {
    size_[b] += size_[k];
    if (k != host) {
      leaves(k, vs);
      for (int x : vs) y_[x] += off_[k] - off_[b];
    }
    label_[k] = kNone;
    parent_[k] = b;
  }
  base_[b] = base_[lca];
  z_[b] = 0;
  parent_[b] = -1;
  label_[b] = kPlus;
  label_time_[b] = now_;
  label_edge_[b] = label_edge_[lca];
  label_from_[b] = label_from_[lca];
  label_to_[b] = label_to_[lca];
  tree_[b] = tree_[lca];
  tree_tops_[tree_[b]].push_back(b);
  for (int k : were_minus) scan_plus(k);
}

// A negative blossom whose z reached 0 dissolves into its children: those on the even path from
// the entering child to the base child stay in the tree (alternately − and +), the rest leave it.
void BlossomMatching::expand(int b) {
  bring_up_to_date(b);
  if (z_[b] != 0) throw std::logic_error("blossom matching: expanding a blossom with z != 0");
  int c = label_to_[b];
  while (parent_[c] != b) c = parent_[c];
  const std::vector<int> kids = std::move(children_[b]);
  const std::vector<int> cedge = std::move(cyc_edge_[b]), cfrom = std::move(cyc_from_[b]),
                         cto = std::move(cyc_to_[b]);
  const int len = static_cast<int>(kids.size());
  const int j = static_cast<int>(std::find(kids.begin(), kids.end(), c) - kids.begin());
  for (int k : kids) {
    parent_[k] = -1;
    label_[k] = kNone;
    label_time_[k] = now_;
    off_[k] = off_[b];
  }
  const int in_edge = label_edge_[b], in_from = label_from_[b], in_to = label_to_[b];
  const int tree = tree_[b];
  children_[b].clear();
  cyc_edge_[b].clear();
  cyc_from_[b].clear();
  cyc_to_[b].clear();
  label_[b] = kNone;
  ++gen_[b];  // jumps to b are no longer trusted
  free_ids_.push_back(b);

  std::vector<char> on_path(len, 0);
  on_path[j] = 1;
  set_label(kids[j], kMinus, in_edge, in_from, in_to, tree);
  // Walk the even side of the cycle from the entering child to the base child (index 0):
  // backwards when j is even, forwards when odd; labels alternate +, −, ..., −.
  for (int i = j, count = 1; i != 0; ++count) {
    const bool back = j % 2 == 0;
    const int next = back ? i - 1 : (i + 1) % len;
    const int k = back ? next : i;  // cycle edge k joins kids[k] (cfrom) and kids[k + 1] (cto)
    const int in_i = back ? cto[k] : cfrom[k], in_next = back ? cfrom[k] : cto[k];
    on_path[next] = 1;
    set_label(kids[next], count % 2 == 1 ? kPlus : kMinus, cedge[k], in_i, in_next, tree);
    i = next;
  }
  for (int i = 0; i < len; ++i)
    if (!on_path[i]) push_edge_events_towards(kids[i]);
}

// Makes vertex x the base of blossom b, flipping the matching along the even path inside.
// Leaves mate_[x] to the caller.
void BlossomMatching::rotate_to(int b, int x) {
  if (b == x || base_[b] == x) return;
  // Bottom-up along x's blossoms inside b: each makes the child holding x its base child.
  std::vector<int> path;
  for (int c = x; c != b; c = parent_[c]) path.push_back(c);
  path.push_back(b);
  for (size_t level = 1; level < path.size(); ++level) {
    const int blossom = path[level], c = path[level - 1];
    if (base_[blossom] == x) continue;
    std::vector<int>& kids = children_[blossom];
    const int len = static_cast<int>(kids.size());
    const int j = static_cast<int>(std::find(kids.begin(), kids.end(), c) - kids.begin());
    auto match = [&](int k) {
      const int e = cyc_edge_[blossom][k], from = cyc_from_[blossom][k], to = cyc_to_[blossom][k];
      rotate_to(kids[k], from);
      rotate_to(kids[(k + 1) % len], to);
      mate_[from] = mate_[to] = e;
    };
    if (j % 2 == 0) {
      for (int k = j - 2; k >= 0; k -= 2) match(k);
    } else {
      for (int k = j + 1; k < len; k += 2) match(k);
    }
    std::rotate(kids.begin(), kids.begin() + j, kids.end());
    std::rotate(cyc_edge_[blossom].begin(), cyc_edge_[blossom].begin() + j,
                cyc_edge_[blossom].end());
    std::rotate(cyc_from_[blossom].begin(), cyc_from_[blossom].begin() + j,
                cyc_from_[blossom].end());
    std::rotate(cyc_to_[blossom].begin(), cyc_to_[blossom].begin() + j, cyc_to_[blossom].end());
    base_[blossom] = x;
  }
}

// Flips the matching along the tree path from the positive vertex x to its root, leaving x
// (now the base of its blossom) for the caller to match; `pairs` collects the new matched edges.
void BlossomMatching::flip_to_root(int x, std::vector<int>& pairs) {
  while (true) {
    const int bx = top_of(x);
    const int up_from = label_from_[bx];
    const bool root = label_edge_[bx] < 0;
    rotate_to(bx, x);
    if (root) return;
    const int minus = top_of(up_from);
    const int mx = label_to_[minus], medge = label_edge_[minus], pfrom = label_from_[minus];
    rotate_to(minus, mx);
    pairs.insert(pairs.end(), {mx, pfrom, medge});
    x = pfrom;
  }
}

// Positive u and v of two different trees joined by a tight edge: an augmenting path from one
// root to the other. Both trees are then taken apart.
void BlossomMatching::augment(int u, int v, int e) {
  const int tree_u = tree_[top_of(u)], tree_v = tree_[top_of(v)];
  std::vector<int> pairs{u, v, e};  // (x, y, edge) to match once all rotations are done
  flip_to_root(u, pairs);
  flip_to_root(v, pairs);
  for (size_t i = 0; i < pairs.size(); i += 3) mate_[pairs[i]] = mate_[pairs[i + 1]] = pairs[i + 2];
  std::vector<int> were_minus;
  dissolve_tree(tree_u, were_minus);
  dissolve_tree(tree_v, were_minus);
  for (int b : were_minus) push_edge_events_towards(b);
}

// Unlabels every top blossom of a tree and collects the negative ones: edges from other trees'
// positive vertices towards those now lose slack and must be queued (towards former positive
// ones they lose it more slowly than before, so their queued events come early and are
// re-checked).
// vertices now lose slack, so they are queued.
void BlossomMatching::dissolve_tree(int tree, std::vector<int>& were_minus) {
  for (int b : tree_tops_[tree])
    if (parent_[b] < 0 && label_[b] != kNone && tree_[b] == tree) {
      bring_up_to_date(b);
      if (label_[b] == kMinus) were_minus.push_back(b);
      label_[b] = kNone;
      tree_[b] = -1;
    }
  tree_tops_[tree].clear();
}

// Grows an alternating tree from every free vertex at once, all with the same dual change.
// Returns false when the events run out with vertices still free: the dual is then unbounded,
// so no perfect matching exists.
bool BlossomMatching::grow_forest() {
  now_ = 0;
  int64_t free_vertices = 0;
  for (int v = 0; v < n_; ++v)
    if (mate_[v] < 0) {
      ++free_vertices;
      set_label(v, kPlus, -1, -1, -1, v);
    }
  free_after_start_ = free_vertices;
  while (free_vertices > 0 && !heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const Event ev = heap_.back();
    heap_.pop_back();
    if (ev.time < now_) throw std::logic_error("blossom matching: event in the past");
    now_ = ev.time;
    if (ev.kind == kExpandEvent) {
      const int b = ev.id;
      if (parent_[b] != -1 || children_[b].empty() || label_[b] != kMinus) continue;
      const int64_t z = z_[b] - 2 * (now_ - label_time_[b]);
      if (z < 0) throw std::logic_error("blossom matching: negative blossom dual");
      if (z > 0) {
        push_event(now_ + z / 2, kExpandEvent, b);
      } else {
        expand(b);
      }
      continue;
    }
    const int e = ev.id;
    int u = end_a_[e], v = end_b_[e];
    int bu = top_of(u), bv = top_of(v);
    if (bu == bv) continue;
    if (label_[bu] != kPlus) {
      std::swap(u, v);
      std::swap(bu, bv);
    }
    const Label lv = label_[bv];
    if (label_[bu] != kPlus || lv == kMinus) continue;
    const int64_t s = slack(e);
    if (s < 0) throw std::logic_error("blossom matching: an edge lost dual feasibility");
    if (s > 0) {
      if (lv == kPlus && (s & 1))
        throw std::logic_error("blossom matching: odd slack between two positive vertices");
      push_event(now_ + (lv == kPlus ? s / 2 : s), kEdgeEvent, e);
      continue;
    }
    if (lv == kNone) {
      grow(u, v, e);
    } else if (tree_[bu] == tree_[bv]) {
      make_blossom(u, v, e);
    } else {
      augment(u, v, e);
      free_vertices -= 2;
    }
  }
  heap_.clear();
  return free_vertices == 0;
}

}  // namespace bimdf::detail
