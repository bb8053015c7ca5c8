// Two-gon inflation for half-arc quantization (paper §4.3, Fig. 12a; tmesh/half_arc.hpp): which
// non-zero paths may be relaxed, and the T-mesh cut open along them.
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/tmesh/half_arc.hpp"
#include "tmesh/quantize_stages.hpp"

namespace bimdf::tmesh {
namespace {

// Walking around a vertex through the patches of a T-mesh: each half-arc's place in its patch's
// counter-clockwise boundary.
class PatchBoundary {
 public:
  PatchBoundary(const TMesh& tmesh, const TMeshIncidence& incidence)
      : tmesh_(tmesh), incidence_(incidence), index_(tmesh.num_half_arcs(), -1) {
    for (const auto& sides : tmesh.patch_sides)
      for (const auto& side : sides)
        for (size_t i = 0; i < side.size(); ++i) index_[side[i]] = static_cast<int>(i);
  }
  bool on_patch(int h) const { return !incidence_.is_border(h); }
  // Whether h's tail is a corner of h's patch (h starts a side).
  bool starts_side(int h) const { return index_[h] == 0; }
  // The half-arc before h in its patch's boundary: it ends where h starts.
  int previous(int h) const {
    const int p = incidence_.half_arc_patch[h], k = incidence_.half_arc_side[h];
    const auto& sides = tmesh_.patch_sides[p];
    return index_[h] > 0 ? sides[k][index_[h] - 1] : sides[(k + 3) % 4].back();
  }

 private:
  const TMesh& tmesh_;
  const TMeshIncidence& incidence_;
  std::vector<int> index_;
};

// The patches around vertex c = tail(first), from `first`'s patch on, turning through each
// patch's corner or side at c, until the patch whose boundary enters c along `stop`: their
// angle at c (90° at a corner, 180° inside a side) and the half-arcs leaving c between `first`
// and `stop` (the arcs on that side of a path through c). `border`: the walk met the border.
struct Fan {
  int angle = 0;
  std::vector<int> outgoing;
  bool border = false;
};

Fan fan_between(const TMesh& tmesh, const PatchBoundary& boundary, int first, int stop) {
  Fan fan;
  int g = first;
  for (int steps = 0; steps <= tmesh.num_half_arcs(); ++steps) {
    if (!boundary.on_patch(g)) break;
    fan.angle += boundary.starts_side(g) ? 90 : 180;
    const int e = boundary.previous(g);
    if (e == stop) return fan;
    g = TMesh::opposite(e);
    fan.outgoing.push_back(g);
  }
  fan.border = true;
  return fan;
}

// Fans on the left and right of path half-arcs `in` (ending at c) and `out` (leaving c).
Fan left_fan(const TMesh& t, const PatchBoundary& b, int in, int out) {
  return fan_between(t, b, out, in);
}
Fan right_fan(const TMesh& t, const PatchBoundary& b, int in, int out) {
  return fan_between(t, b, TMesh::opposite(in), TMesh::opposite(out));
}

// Whether a chain of half-arcs visits one of its vertices twice.
bool passes_a_vertex_twice(const TMesh& t, const std::vector<int>& half_arcs) {
  std::vector<int> vertices{t.half_arc_tail(half_arcs.front())};
  for (int h : half_arcs) vertices.push_back(t.half_arc_head(h));
  std::sort(vertices.begin(), vertices.end());
  return std::adjacent_find(vertices.begin(), vertices.end()) != vertices.end();
}

// A sequence of half-arcs walked the other way.
std::vector<int> reversed(const std::vector<int>& half_arcs) {
  std::vector<int> out;
  for (auto h = half_arcs.rbegin(); h != half_arcs.rend(); ++h) out.push_back(TMesh::opposite(*h));
  return out;
}

// Why path m may not be relaxed, or "" (rules (a)–(c) of half_arc.hpp; (d) is a choice among the
// paths that pass these, made by relaxability); `on_arc` lists the distinct paths running along
// each arc.
std::string relax_issue(const TMesh& t, const TMeshIncidence& inc, const PatchBoundary& b,
                        const std::vector<int>& path, const std::vector<std::vector<int>>& on_arc,
                        bool has_partner) {
  if (path.size() < 2) return "it runs along one arc";
  if (arcs_along(path).size() != path.size()) return "it runs along an arc twice";
  if (passes_a_vertex_twice(t, path)) return "it passes a vertex twice";
  for (int h : path) {
    if (inc.is_border(h) || inc.is_border(TMesh::opposite(h))) return "it runs along the border";
    if (!t.arc_feature.empty() && t.arc_feature[TMesh::arc_of(h)])
      return "it runs along a feature curve";
    if (on_arc[TMesh::arc_of(h)].size() > (has_partner ? 2u : 1u))
      return "another path shares its arc";
  }
  for (size_t i = 1; i < path.size(); ++i) {
    const int c = t.half_arc_tail(path[i]);
    const Fan left = left_fan(t, b, path[i - 1], path[i]);
    const Fan right = right_fan(t, b, path[i - 1], path[i]);
    if (left.border || right.border) return "its vertex " + std::to_string(c) + " is on the border";
    if (left.angle != 180 || right.angle != 180) return "it turns at vertex " + std::to_string(c);
  }
  return "";
}

// Per path: the index of the path it duplicates (the same arcs; the smallest half-arc sequence
// among them represents them all), or its own.
std::vector<int> representatives(const TMesh& t) {
  const auto& paths = t.nonzero_paths;
  std::map<std::vector<int>, int> first;
  std::vector<int> rep(paths.size());
  for (size_t m = 0; m < paths.size(); ++m) {
    auto [it, inserted] = first.emplace(arcs_along(paths[m]), static_cast<int>(m));
    if (!inserted && paths[m] < paths[it->second]) it->second = static_cast<int>(m);
  }
  for (size_t m = 0; m < paths.size(); ++m) rep[m] = first.at(arcs_along(paths[m]));
  return rep;
}

// Two paths on one line that overlap partially, each reaching past the other's end: their
// union (`line`, oriented canonically: the smaller of its two half-arc sequences), which of the
// two starts at the line's tail (`first`: 0 for a, 1 for b), where it ends (`first_end`, a
// vertex position along the line) and where the other starts (`second_start`).
struct OverlapLine {
  std::vector<int> line;
  int first = 0, first_end = 0, second_start = 0;
};

std::optional<OverlapLine> overlap_line(const TMesh& t, const std::vector<int>& a,
                                        const std::vector<int>& b) {
  for (int swap = 0; swap < 2; ++swap) {
    const std::vector<int>& head = swap ? b : a;  // the one at the union's tail, if any
    for (const std::vector<int>& tail : {swap ? a : b, reversed(swap ? a : b)}) {
      // tail's first arcs repeat head's last ones, from head's position k on.
      for (size_t k = 1; k < head.size(); ++k) {
        const size_t shared = head.size() - k;
        if (tail.size() <= shared || !std::equal(head.begin() + k, head.end(), tail.begin()))
          continue;
        OverlapLine o;
        o.line = head;
        o.line.insert(o.line.end(), tail.begin() + shared, tail.end());
        o.first = swap;
        o.first_end = static_cast<int>(head.size());
        o.second_start = static_cast<int>(k);
        if (passes_a_vertex_twice(t, o.line)) return std::nullopt;
        const std::vector<int> back = reversed(o.line);
        if (back < o.line) {
          const int n = static_cast<int>(o.line.size());
          o.line = back;
          o.first = 1 - o.first;
          const int first_end = n - o.second_start;
          o.second_start = n - o.first_end;
          o.first_end = first_end;
        }
        return o;
      }
    }
  }
  return std::nullopt;
}

struct Relaxability {
  std::vector<int> representative;
  std::vector<int> partner;        // per representative path: the path it overlaps, or −1
  std::vector<std::string> issue;  // per representative path
  // Per pair, at the smaller of its two paths: their union (`first` 0: that path starts it).
  std::map<int, OverlapLine> overlap;
};

Relaxability relaxability(const TMesh& t, const TMeshIncidence& inc) {
  Relaxability r;
  r.representative = representatives(t);
  const auto& paths = t.nonzero_paths;
  std::vector<std::vector<int>> on_arc(t.num_arcs());  // the representative paths along it
  for (size_t m = 0; m < paths.size(); ++m)
    if (r.representative[m] == static_cast<int>(m))
      for (int a : arcs_along(paths[m])) on_arc[a].push_back(static_cast<int>(m));
  // Pairs: two paths sharing arcs with each other only, overlapping partially along one line.
  const auto sharing = [&](int m) {
    std::vector<int> others;
    for (int a : arcs_along(paths[m]))
      for (int q : on_arc[a])
        if (q != m) others.push_back(q);
    detail::sort_unique(others);
    return others;
  };
  r.partner.assign(paths.size(), -1);
  for (int m = 0; m < static_cast<int>(paths.size()); ++m) {
    if (r.representative[m] != m) continue;
    const std::vector<int> others = sharing(m);
    const int q = others.size() == 1 ? others[0] : -1;
    if (q < m || sharing(q) != std::vector<int>{m}) continue;  // each pair once, from its first
    if (std::optional<OverlapLine> line = overlap_line(t, paths[m], paths[q])) {
      r.partner[m] = q, r.partner[q] = m;
      r.overlap[m] = std::move(*line);
    }
  }
  const PatchBoundary boundary(t, inc);
  r.issue.resize(paths.size());
  for (size_t m = 0; m < paths.size(); ++m)
    if (r.representative[m] == static_cast<int>(m))
      r.issue[m] = relax_issue(t, inc, boundary, paths[m], on_arc, r.partner[m] >= 0);
  // A pair is relaxed together or not at all.
  for (size_t m = 0; m < paths.size(); ++m)
    if (r.partner[m] >= 0 && r.issue[m].empty() && !r.issue[r.partner[m]].empty())
      r.issue[m] = "it overlaps path " + std::to_string(r.partner[m]) + ", which cannot be relaxed";
  return r;
}

// The vertices inside a line (all but its ends).
std::vector<int> interior_vertices(const TMesh& t, const std::vector<int>& line) {
  std::vector<int> inside;
  for (size_t i = 1; i < line.size(); ++i) inside.push_back(t.half_arc_tail(line[i]));
  return inside;
}

}  // namespace

std::vector<int> relaxable_paths(const TMesh& tmesh, const TMeshIncidence& incidence,
                                 bool crossed) {
  const Relaxability r = relaxability(tmesh, incidence);
  const auto& paths = tmesh.nonzero_paths;
  // Without `crossed`, per vertex: the distinct paths passing through it.
  std::vector<std::vector<int>> through;
  if (!crossed) {
    through.resize(tmesh.num_vertices());
    for (int m = 0; m < static_cast<int>(paths.size()); ++m)
      if (r.representative[m] == m)
        for (int c : interior_vertices(tmesh, paths[m])) through[c].push_back(m);
  }
  // Rule (d) among the paths that pass (a)–(c): per line to cut (a path alone, or a pair at its
  // smaller path), the lines it crosses. Lines are ranked by their arcs, not by path index, so
  // that the choice does not depend on the order of the paths.
  std::vector<int> line_path;
  std::vector<std::vector<int>> line_arcs;
  std::vector<std::vector<int>> at_vertex(tmesh.num_vertices());
  for (int m = 0; m < static_cast<int>(paths.size()); ++m) {
    if (r.representative[m] != m || !r.issue[m].empty() || (r.partner[m] >= 0 && r.partner[m] < m))
      continue;
    const std::vector<int>& line = r.partner[m] < 0 ? paths[m] : r.overlap.at(m).line;
    const std::vector<int> inside = interior_vertices(tmesh, line);
    if (!crossed && std::any_of(inside.begin(), inside.end(), [&](int c) {
          return std::any_of(through[c].begin(), through[c].end(),
                             [&](int q) { return q != m && q != r.partner[m]; });
        }))
      continue;
    for (int c : inside) at_vertex[c].push_back(static_cast<int>(line_path.size()));
    line_path.push_back(m);
    line_arcs.push_back(arcs_along(line));
  }
  const int n = static_cast<int>(line_path.size());
  std::vector<int> by_rank(n), rank(n);
  for (int l = 0; l < n; ++l) by_rank[l] = l;
  std::sort(by_rank.begin(), by_rank.end(),
            [&](int x, int y) { return line_arcs[x] < line_arcs[y]; });
  for (int k = 0; k < n; ++k) rank[by_rank[k]] = k;
  std::vector<std::vector<int>> crosses(n);
  for (const std::vector<int>& lines : at_vertex)
    for (int x : lines)
      for (int y : lines)
        if (x != y) crosses[x].push_back(y);
  for (auto& c : crosses) detail::sort_unique(c);
  // A maximal set of lines crossing none of each other, greedily: the line crossing the fewest
  // lines still open first (the usual heuristic for a large independent set; a maximum one is
  // NP-hard to find in general, and not needed: every line left out keeps Algorithm 2's bounds).
  std::vector<int> degree(n);
  std::set<std::pair<int, int>> open;  // (degree, rank)
  for (int l = 0; l < n; ++l) {
    degree[l] = static_cast<int>(crosses[l].size());
    open.insert({degree[l], rank[l]});
  }
  enum State : char { kOpen, kChosen, kDropped };
  std::vector<State> state(n, kOpen);
  while (!open.empty()) {
    const int l = by_rank[open.begin()->second];
    open.erase(open.begin());
    state[l] = kChosen;
    for (int x : crosses[l]) {
      if (state[x] != kOpen) continue;
      open.erase({degree[x], rank[x]});
      state[x] = kDropped;
      for (int y : crosses[x])
        if (state[y] == kOpen) {
          open.erase({degree[y], rank[y]});
          open.insert({--degree[y], rank[y]});
        }
    }
  }
  std::vector<int> out;
  for (int l = 0; l < n; ++l)
    if (state[l] == kChosen) {
      out.push_back(line_path[l]);
      if (r.partner[line_path[l]] >= 0) out.push_back(r.partner[line_path[l]]);
    }
  std::sort(out.begin(), out.end());
  return out;
}

InflatedTMesh inflate_two_gons(const TMesh& tmesh, const TMeshIncidence& incidence,
                               const std::vector<int>& paths) {
  const Relaxability r = relaxability(tmesh, incidence);
  for (int m : paths) {
    if (m < 0 || m >= static_cast<int>(tmesh.nonzero_paths.size()))
      throw std::invalid_argument("inflate_two_gons: no non-zero path " + std::to_string(m));
    if (r.representative[m] != m)
      throw std::invalid_argument("inflate_two_gons: path " + std::to_string(m) + " repeats path " +
                                  std::to_string(r.representative[m]));
    if (!r.issue[m].empty())
      throw std::invalid_argument("inflate_two_gons: path " + std::to_string(m) +
                                  " cannot be relaxed: " + r.issue[m]);
    if (r.partner[m] >= 0 && std::find(paths.begin(), paths.end(), r.partner[m]) == paths.end())
      throw std::invalid_argument("inflate_two_gons: path " + std::to_string(m) +
                                  " overlaps path " + std::to_string(r.partner[m]) +
                                  ", which must be relaxed with it");
  }
  // The lines to cut along: a path alone, or a pair's union (once, at its first path).
  std::vector<TwoGon> lines;
  std::vector<std::vector<int>> line_half_arcs;
  for (int m : paths) {
    TwoGon g;
    const int q = r.partner[m];
    if (q < 0) {
      g.paths = {m};
      line_half_arcs.push_back(tmesh.nonzero_paths[m]);
    } else {
      if (q < m && std::find(paths.begin(), paths.end(), q) != paths.end()) continue;
      const int low = std::min(m, q), high = std::max(m, q);
      const OverlapLine& o = r.overlap.at(low);
      g.paths = o.first == 0 ? std::vector<int>{low, high} : std::vector<int>{high, low};
      g.left_end = o.first_end;
      g.right_start = o.second_start;
      line_half_arcs.push_back(o.line);
    }
    lines.push_back(std::move(g));
  }
  // Rule (d): no vertex inside two lines. Per input vertex inside a line: the line, and its
  // position along it.
  std::vector<std::array<int, 2>> inside(tmesh.num_vertices(), {-1, -1});
  for (size_t l = 0; l < lines.size(); ++l) {
    const std::vector<int> interior = interior_vertices(tmesh, line_half_arcs[l]);
    for (size_t k = 0; k < interior.size(); ++k) {
      const int c = interior[k], i = static_cast<int>(k) + 1;
      if (inside[c][0] >= 0)
        throw std::invalid_argument(
            "inflate_two_gons: the lines of paths " + std::to_string(lines[inside[c][0]].paths[0]) +
            " and " + std::to_string(lines[l].paths[0]) + " cross at vertex " + std::to_string(c) +
            "; of two crossing paths at most one can be relaxed");
      inside[c] = {static_cast<int>(l), i};
    }
  }
  InflatedTMesh out;
  TMesh& o = out.tmesh;
  o = tmesh;
  out.arc_origin.resize(tmesh.num_arcs());
  out.vertex_origin.resize(tmesh.num_vertices());
  for (int a = 0; a < tmesh.num_arcs(); ++a) out.arc_origin[a] = a;
  for (int v = 0; v < tmesh.num_vertices(); ++v) out.vertex_origin[v] = v;
  out.twin.assign(tmesh.num_arcs(), -1);
  const bool has_mesh_vertices = !tmesh.vertex_mesh_vertex.empty();
  const bool has_chains = !tmesh.arc_chain.empty();

  // Interior vertices split first: the arcs on a path's right get the new copy, whatever path
  // they belong to, so that right copies made below find their ends already moved.
  const PatchBoundary boundary(tmesh, incidence);
  std::vector<int> right_copy(tmesh.num_vertices(), -1);
  for (size_t l = 0; l < lines.size(); ++l) {
    const std::vector<int>& path = line_half_arcs[l];
    lines[l].crossing.assign(path.size() + 1, 0);
    lines[l].path_crossing.assign(path.size() + 1, 0);
    for (size_t i = 1; i < path.size(); ++i) {
      const int c = tmesh.half_arc_tail(path[i]);
      const int copy = o.num_vertices();
      o.vertices.push_back(tmesh.vertices[c]);
      if (has_mesh_vertices) o.vertex_mesh_vertex.push_back(tmesh.vertex_mesh_vertex[c]);
      out.vertex_origin.push_back(c);
      right_copy[c] = copy;
      const Fan right = right_fan(tmesh, boundary, path[i - 1], path[i]);
      for (int g : right.outgoing) o.arc_ends[TMesh::arc_of(g)][g & 1] = copy;
      lines[l].crossing[i] = !right.outgoing.empty() &&
                             !left_fan(tmesh, boundary, path[i - 1], path[i]).outgoing.empty();
    }
  }
  for (size_t l = 0; l < lines.size(); ++l) {
    const std::vector<int>& path = line_half_arcs[l];
    TwoGon& two_gon = lines[l];
    for (size_t i = 0; i < path.size(); ++i) {
      const int h = path[i], a = TMesh::arc_of(h), copy = o.num_arcs();
      const int from = i == 0 ? o.half_arc_tail(h) : right_copy[tmesh.half_arc_tail(h)];
      const int to = i + 1 == path.size() ? o.half_arc_head(h) : right_copy[tmesh.half_arc_head(h)];
      o.arc_ends.push_back({from, to});
      o.arc_target.push_back(tmesh.arc_target[a]);
      if (!tmesh.arc_feature.empty()) o.arc_feature.push_back(tmesh.arc_feature[a]);
      if (has_chains) {
        std::vector<int> chain = tmesh.arc_chain[a];
        if (h & 1) std::reverse(chain.begin(), chain.end());
        o.arc_chain.push_back(std::move(chain));
      }
      out.arc_origin.push_back(a);
      out.twin[a] = copy;
      out.twin.push_back(a);
      // The patch right of the path now lies on the copy, walked against the path.
      const int opposite = TMesh::opposite(h);
      auto& side =
          o.patch_sides[incidence.half_arc_patch[opposite]][incidence.half_arc_side[opposite]];
      *std::find(side.begin(), side.end(), opposite) = 2 * copy + 1;
      two_gon.left.push_back(h);
      two_gon.right.push_back(2 * copy);
    }
  }
  // The second path of a pair is measured on the right: in T' it runs along the right copies
  // (and so do its duplicates), so that it starts at its own vertex's right copy.
  for (size_t l = 0; l < lines.size(); ++l) {
    const TwoGon& g = lines[l];
    if (g.paths.size() != 2) continue;
    const std::vector<int> along(g.right.begin() + g.right_start, g.right.end());
    for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m)
      if (r.representative[m] == g.paths[1])
        o.nonzero_paths[m] = tmesh.nonzero_paths[m].front() == line_half_arcs[l][g.right_start]
                                 ? along
                                 : reversed(along);
  }
  // A path crossing a line (not relaxed itself: rule (d)) reaches the crossing on one side of the
  // cut and leaves it on the other. T' keeps it a chain by a detour around the line's nearer
  // end, along one side and back along the other: its length only grows, so Algorithm 2's
  // bounds still imply its check, and deflation cancels the detour down to the run between the
  // crossing's two places on the closed line.
  for (auto& path : o.nonzero_paths) {
    std::vector<int> chain{path.front()};
    for (size_t k = 1; k < path.size(); ++k) {
      const int end = o.half_arc_head(path[k - 1]);
      if (end != o.half_arc_tail(path[k])) {
        const auto [l, i] = inside[out.vertex_origin[end]];
        if (l < 0) throw std::logic_error("inflate_two_gons: a non-zero path broke apart");
        TwoGon& g = lines[l];
        g.path_crossing[i] = 1;
        const int n = static_cast<int>(g.left.size());
        const std::vector<int>& from = end == out.vertex_origin[end] ? g.left : g.right;
        const std::vector<int>& to = end == out.vertex_origin[end] ? g.right : g.left;
        if (2 * i <= n) {
          for (int j = i - 1; j >= 0; --j) chain.push_back(TMesh::opposite(from[j]));
          for (int j = 0; j < i; ++j) chain.push_back(to[j]);
        } else {
          for (int j = i; j < n; ++j) chain.push_back(from[j]);
          for (int j = n - 1; j >= i; --j) chain.push_back(TMesh::opposite(to[j]));
        }
      }
      chain.push_back(path[k]);
    }
    path = std::move(chain);
  }
  out.two_gons = std::move(lines);
  return out;
}

Zip two_gon_zip(const TwoGon& two_gon) { return {two_gon.right, reversed(two_gon.left)}; }

}  // namespace bimdf::tmesh
