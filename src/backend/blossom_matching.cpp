#include "backend/blossom_matching.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace bimdf::detail {
namespace {

constexpr int kEdgeEvent = 0;    // id: an edge between two positive tops may be tight
constexpr int kExpandEvent = 1;  // id: a negative blossom whose z may have reached 0
constexpr int kGrowEvent = 2;    // id: an unlabeled top whose grow_edge may be tight
constexpr int64_t kNever = std::numeric_limits<int64_t>::max();

}  // namespace

void BlossomMatching::push_event(int64_t time, int kind, int id) {
  heap_.push_back({time, kind, id});
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
}

int64_t BlossomMatching::dual_in(int v, int b) const {
  const int64_t t = now_ - top_[b].label_time;
  const int64_t y = y_[v] + top_[b].off;
  return top_[b].label == kPlus ? y - t : top_[b].label == kMinus ? y + t : y;
}

int64_t BlossomMatching::dual(int v) { return dual_in(v, top_of(v)); }

int64_t BlossomMatching::slack(int e) { return dual(end_a_[e]) + dual(end_b_[e]) - w2_[e]; }

void BlossomMatching::leaves(int b, std::vector<int>& out) {
  out.clear();
  if (!nontrivial(b)) {
    out.push_back(b);
    return;
  }
  std::vector<int>& stack = leaf_stack_;
  stack.assign(1, b);
  while (!stack.empty()) {
    const int x = stack.back();
    stack.pop_back();
    if (nontrivial(x))
      stack.insert(stack.end(), cycle(x).children.begin(), cycle(x).children.end());
    else
      out.push_back(x);
  }
}

// Folds the dual change since the top blossom b was labeled into its offset (and its own z),
// so that b can change label or structure: O(1), whatever b's size.
void BlossomMatching::bring_up_to_date(int b) {
  const int64_t t = now_ - top_[b].label_time;
  if (top_[b].label != kNone && t != 0) {
    const int64_t sign = top_[b].label == kPlus ? -1 : 1;
    top_[b].off += sign * t;
    if (nontrivial(b)) z_[b] -= 2 * sign * t;
  }
  top_[b].label_time = now_;
}

// The top blossom of v, found by walking up the blossom forest (top_of, in the header, takes
// the common case: v's remembered jump still leads to a living top). Each id remembers a jump to
// an ancestor found earlier (path compression); a jump is trusted only while its target lives
// (same generation: only top blossoms are expanded, so a living target still contains it).
int BlossomMatching::top_of_slow(int v) {
  int x = v;
  path_.clear();
  while (true) {
    const int j = link_[x].jump;
    const int next = j >= 0 && link_[x].jump_gen == link_[j].gen ? j : link_[x].parent;
    if (next < 0) break;
    path_.push_back(x);
    x = next;
  }
  for (int p : path_) {
    link_[p].jump = x;
    link_[p].jump_gen = link_[x].gen;
  }
  return x;
}

void BlossomMatching::set_label(int b, Label label, int edge, int from, int to, int tree) {
  bring_up_to_date(b);
  top_[b].tree = tree;
  tree_tops_[tree].push_back(b);
  top_[b].label = label;
  top_[b].grow_time = kNever;
  label_edge_[b] = edge;
  label_from_[b] = from;
  label_to_[b] = to;
  if (label == kPlus) scan_plus(b);
  if (label == kMinus && nontrivial(b)) {
    push_event(now_ + z_[b] / 2, kExpandEvent, b);
  }
}

// Keeps the earliest moment a positive vertex can grow the unlabeled top b over edge e: only
// that one is queued, and when it turns out stale (its positive end left the forest) b's edges
// are scanned again (push_edge_events_towards). Later candidates can therefore be dropped —
// half of all queued events otherwise, each a heap operation.
void BlossomMatching::consider_grow(int b, int e, int64_t time) {
  if (time >= top_[b].grow_time) return;
  top_[b].grow_time = time;
  top_[b].grow_edge = e;
  push_event(time, kGrowEvent, b);
}

// Queues the moment each edge from the (now positive) blossom b becomes tight.
void BlossomMatching::scan_plus(int b) {
  leaves(b, scratch_);
  const int self = top_of(b);  // b itself, or the new blossom whose child b became
  for (int u : scratch_) {
    const int64_t yu = dual_in(u, self);
    for (int k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
      const Incidence& in = adj_[k];
      if (in.w2 == kDisabled) continue;
      const int e = in.edge, v = in.other;
      const int bv = top_of(v);
      if (bv == self || top_[bv].label == kMinus) continue;
      const int64_t s = yu + dual_in(v, bv) - in.w2;
      if (top_[bv].label == kNone) {
        consider_grow(bv, e, now_ + s);
        continue;
      }
      if (s & 1)
        throw std::logic_error("blossom matching: odd slack between two positive vertices");
      push_event(now_ + s / 2, kEdgeEvent, e);
    }
  }
}

// The unlabeled top b (just out of a tree, or its queued grow edge stale): edges from positive
// vertices towards it lose slack; the earliest becomes its grow event.
void BlossomMatching::push_edge_events_towards(int b) {
  leaves(b, scratch_);
  int64_t earliest = kNever;
  int best = -1;
  for (int v : scratch_) {
    const int64_t yv = dual_in(v, b);
    for (int k = adj_start_[v]; k < adj_start_[v + 1]; ++k) {
      const Incidence& in = adj_[k];
      if (in.w2 == kDisabled) continue;
      const int u = in.other, bu = top_of(u);
      if (top_[bu].label != kPlus) continue;
      const int64_t time = now_ + yv + dual_in(u, bu) - in.w2;
      if (time < earliest) earliest = time, best = in.edge;
    }
  }
  if (best >= 0) consider_grow(b, best, earliest);
}

int BlossomMatching::tree_parent(int b) { return label_edge_[b] < 0 ? -1 : top_of(label_from_[b]); }

int BlossomMatching::new_blossom_id() {
  if (!free_ids_.empty()) {
    const int id = free_ids_.back();
    free_ids_.pop_back();
    return id;
  }
  const int id = static_cast<int>(link_.size());
  link_.emplace_back();
  top_.emplace_back();
  base_.push_back(-1);
  cycle_.emplace_back();
  z_.push_back(0);
  size_.push_back(0);
  label_edge_.push_back(-1);
  label_from_.push_back(-1);
  label_to_.push_back(-1);
  mark_.push_back(0);
  return id;
}

void BlossomMatching::grow(int u, int v, int e) {
  const int bv = top_of(v);
  const int tree = top_[top_of(u)].tree;
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
  std::vector<int>& kids = cycle(b).children;
  std::vector<int>&cedge = cycle(b).edge, &cfrom = cycle(b).from, &cto = cycle(b).to;
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
    if (top_[k].label == kMinus) were_minus.push_back(k);
    if (size_[k] > size_[host]) host = k;
  }
  top_[b].off = top_[host].off;
  size_[b] = 0;
  for (int k : kids) {
    size_[b] += size_[k];
    if (k != host) {
      leaves(k, scratch_);
      for (int x : scratch_) y_[x] += top_[k].off - top_[b].off;
    }
    top_[k].label = kNone;
    link_[k].parent = b;
  }
  base_[b] = base_[lca];
  z_[b] = 0;
  link_[b].parent = -1;
  top_[b].label = kPlus;
  top_[b].label_time = now_;
  top_[b].grow_time = kNever;
  label_edge_[b] = label_edge_[lca];
  label_from_[b] = label_from_[lca];
  label_to_[b] = label_to_[lca];
  top_[b].tree = top_[lca].tree;
  tree_tops_[top_[b].tree].push_back(b);
  for (int k : were_minus) scan_plus(k);
}

// A negative blossom whose z reached 0 dissolves into its children: those on the even path from
// the entering child to the base child stay in the tree (alternately − and +), the rest leave it.
void BlossomMatching::expand(int b) {
  bring_up_to_date(b);
  if (z_[b] != 0) throw std::logic_error("blossom matching: expanding a blossom with z != 0");
  int c = label_to_[b];
  while (link_[c].parent != b) c = link_[c].parent;
  // Copies: b's id (and cycle) may be reused while the children are labeled.
  const std::vector<int> kids = cycle(b).children, cedge = cycle(b).edge, cfrom = cycle(b).from,
                         cto = cycle(b).to;
  const int len = static_cast<int>(kids.size());
  const int j = static_cast<int>(std::find(kids.begin(), kids.end(), c) - kids.begin());
  for (int k : kids) {
    link_[k].parent = -1;
    top_[k].label = kNone;
    top_[k].grow_time = kNever;
    top_[k].label_time = now_;
    top_[k].off = top_[b].off;
  }
  const int in_edge = label_edge_[b], in_from = label_from_[b], in_to = label_to_[b];
  const int tree = top_[b].tree;
  cycle(b).children.clear();
  cycle(b).edge.clear();
  cycle(b).from.clear();
  cycle(b).to.clear();
  top_[b].label = kNone;
  ++link_[b].gen;  // jumps to b are no longer trusted
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
  for (int c = x; c != b; c = link_[c].parent) path.push_back(c);
  path.push_back(b);
  for (size_t level = 1; level < path.size(); ++level) {
    const int blossom = path[level], c = path[level - 1];
    if (base_[blossom] == x) continue;
    Cycle& cyc = cycle(blossom);
    std::vector<int>& kids = cyc.children;
    const int len = static_cast<int>(kids.size());
    const int j = static_cast<int>(std::find(kids.begin(), kids.end(), c) - kids.begin());
    auto match = [&](int k) {
      const int e = cyc.edge[k], from = cyc.from[k], to = cyc.to[k];
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
    std::rotate(cyc.edge.begin(), cyc.edge.begin() + j, cyc.edge.end());
    std::rotate(cyc.from.begin(), cyc.from.begin() + j, cyc.from.end());
    std::rotate(cyc.to.begin(), cyc.to.begin() + j, cyc.to.end());
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
  const int tree_u = top_[top_of(u)].tree, tree_v = top_[top_of(v)].tree;
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
    if (link_[b].parent < 0 && top_[b].label != kNone && top_[b].tree == tree) {
      bring_up_to_date(b);
      if (top_[b].label == kMinus) were_minus.push_back(b);
      top_[b].label = kNone;
      top_[b].tree = -1;
    }
  tree_tops_[tree].clear();
}

// Grows an alternating tree from every free vertex at once, all with the same dual change.
// Returns false when the events run out with vertices still free: the dual is then unbounded,
// so no perfect matching exists.
bool BlossomMatching::grow_forest() {
  now_ = 0;
  int64_t free_vertices = std::count(mate_.begin(), mate_.end(), -1);
  tree_tops_.assign(free_vertices, {});
  // A free vertex is the base of its top blossom (a resumed run keeps blossoms): that top
  // roots the tree.
  for (int v = 0, tree = 0; v < n_; ++v)
    if (mate_[v] < 0) set_label(top_of(v), kPlus, -1, -1, -1, tree++);
  free_after_start_ = free_vertices;
  while (free_vertices > 0 && !heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const Event ev = heap_.back();
    heap_.pop_back();
    if (ev.time < now_) throw std::logic_error("blossom matching: event in the past");
    now_ = ev.time;
    if (ev.kind == kExpandEvent) {
      const int b = ev.id;
      if (link_[b].parent != -1 || cycle(b).children.empty() || top_[b].label != kMinus) continue;
      const int64_t z = z_[b] - 2 * (now_ - top_[b].label_time);
      if (z < 0) throw std::logic_error("blossom matching: negative blossom dual");
      if (z > 0) {
        push_event(now_ + z / 2, kExpandEvent, b);
      } else {
        expand(b);
      }
      continue;
    }
    if (ev.kind == kGrowEvent) {
      const int b = ev.id;
      if (link_[b].parent >= 0 || top_[b].label != kNone || top_[b].grow_time != ev.time) continue;
      top_[b].grow_time = kNever;
      const int e = top_[b].grow_edge;
      const bool a_inside = top_of(end_a_[e]) == b;
      const int u = a_inside ? end_b_[e] : end_a_[e], v = a_inside ? end_a_[e] : end_b_[e];
      const int64_t s = slack(e);
      if (s < 0) throw std::logic_error("blossom matching: an edge lost dual feasibility");
      if (top_[top_of(u)].label == kPlus && s == 0) {
        grow(u, v, e);
      } else {
        push_edge_events_towards(b);  // its positive end left the forest meanwhile
      }
      continue;
    }
    const int e = ev.id;
    int u = end_a_[e], v = end_b_[e];
    int bu = top_of(u), bv = top_of(v);
    if (bu == bv) continue;
    if (top_[bu].label != kPlus) {
      std::swap(u, v);
      std::swap(bu, bv);
    }
    const Label lv = top_[bv].label;
    if (top_[bu].label != kPlus || lv == kMinus) continue;
    const int64_t s = slack(e);
    if (s < 0) throw std::logic_error("blossom matching: an edge lost dual feasibility");
    if (lv == kNone) {  // its other end's tree was taken apart
      consider_grow(bv, e, now_ + s);
      continue;
    }
    if (s > 0) {
      if (s & 1)
        throw std::logic_error("blossom matching: odd slack between two positive vertices");
      push_event(now_ + s / 2, kEdgeEvent, e);
      continue;
    }
    if (top_[bu].tree == top_[bv].tree) {
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
