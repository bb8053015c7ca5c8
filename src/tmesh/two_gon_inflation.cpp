// Two-gon inflation for half-arc quantization (paper §4.3, Fig. 12a; tmesh/half_arc.hpp): which
// non-zero paths may be relaxed, the T-mesh cut open along them, and the independent check of a
// half-arc quantization.
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/tmesh/half_arc.hpp"

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

// Why path m may not be relaxed, or "" (rules (a)–(d) of half_arc.hpp); `on_arc` lists the
// distinct paths running along each arc, `interior_uses` counts those through each vertex.
std::string relax_issue(const TMesh& t, const TMeshIncidence& inc, const PatchBoundary& b,
                        const std::vector<int>& path, const std::vector<std::vector<int>>& on_arc,
                        const std::vector<int>& interior_uses, const std::vector<int>* partner) {
  // An overlapping partner (a pair, OverlapLine) shares arcs and interior vertices with it.
  const auto interior_of_partner = [&](int c) {
    if (!partner) return false;
    for (size_t i = 1; i < partner->size(); ++i)
      if (t.half_arc_tail((*partner)[i]) == c) return true;
    return false;
  };
  if (path.size() < 2) return "it runs along one arc";
  if (arcs_along(path).size() != path.size()) return "it runs along an arc twice";
  if (passes_a_vertex_twice(t, path)) return "it passes a vertex twice";
  for (int h : path) {
    if (inc.is_border(h) || inc.is_border(TMesh::opposite(h))) return "it runs along the border";
    if (!t.arc_feature.empty() && t.arc_feature[TMesh::arc_of(h)])
      return "it runs along a feature curve";
    if (on_arc[TMesh::arc_of(h)].size() > (partner ? 2u : 1u)) return "another path shares its arc";
  }
  for (size_t i = 1; i < path.size(); ++i) {
    const int c = t.half_arc_tail(path[i]);
    if (interior_uses[c] > (interior_of_partner(c) ? 2 : 1))
      return "another path passes its vertex " + std::to_string(c);
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
  std::vector<int> interior_uses(t.num_vertices(), 0);
  std::vector<std::vector<int>> on_arc(t.num_arcs());  // the representative paths along it
  for (size_t m = 0; m < paths.size(); ++m) {
    if (r.representative[m] != static_cast<int>(m)) continue;
    for (int a : arcs_along(paths[m])) on_arc[a].push_back(static_cast<int>(m));
    for (size_t i = 1; i < paths[m].size(); ++i) ++interior_uses[t.half_arc_tail(paths[m][i])];
  }
  // Pairs: two paths sharing arcs with each other only, overlapping partially along one line.
  const auto sharing = [&](int m) {
    std::vector<int> others;
    for (int a : arcs_along(paths[m]))
      for (int q : on_arc[a])
        if (q != m) others.push_back(q);
    std::sort(others.begin(), others.end());
    others.erase(std::unique(others.begin(), others.end()), others.end());
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
      r.issue[m] = relax_issue(t, inc, boundary, paths[m], on_arc, interior_uses,
                               r.partner[m] >= 0 ? &paths[r.partner[m]] : nullptr);
  // A pair is relaxed together or not at all.
  for (size_t m = 0; m < paths.size(); ++m)
    if (r.partner[m] >= 0 && r.issue[m].empty() && !r.issue[r.partner[m]].empty())
      r.issue[m] = "it overlaps path " + std::to_string(r.partner[m]) + ", which cannot be relaxed";
  return r;
}

}  // namespace

std::vector<int> relaxable_paths(const TMesh& tmesh, const TMeshIncidence& incidence) {
  const Relaxability r = relaxability(tmesh, incidence);
  std::vector<int> out;
  for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m)
    if (r.representative[m] == static_cast<int>(m) && r.issue[m].empty())
      out.push_back(static_cast<int>(m));
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
  out.two_gons = std::move(lines);
  return out;
}

Zip two_gon_zip(const TwoGon& two_gon) { return {two_gon.right, reversed(two_gon.left)}; }

std::vector<int64_t> half_arc_lengths(const TMesh& tmesh, const InflatedTMesh& inflated,
                                      const std::vector<int64_t>& arc_length) {
  if (arc_length.size() != inflated.arc_origin.size())
    throw std::invalid_argument("half_arc_lengths: " + std::to_string(arc_length.size()) +
                                " lengths for " + std::to_string(inflated.arc_origin.size()) +
                                " arcs of the inflated T-mesh");
  std::vector<int64_t> out(tmesh.num_half_arcs());
  for (int a = 0; a < tmesh.num_arcs(); ++a) out[2 * a] = out[2 * a + 1] = arc_length[a];
  for (const TwoGon& g : inflated.two_gons)
    for (size_t i = 0; i < g.left.size(); ++i)
      out[TMesh::opposite(g.left[i])] = arc_length[TMesh::arc_of(g.right[i])];
  return out;
}

std::string check_half_arc_quantization(const TMesh& tmesh, const std::vector<TwoGon>& two_gons,
                                        const std::vector<int64_t>& half_arc_length) {
  const auto& H = half_arc_length;
  if (static_cast<int>(H.size()) != tmesh.num_half_arcs())
    return "expected " + std::to_string(tmesh.num_half_arcs()) + " half-arc lengths, got " +
           std::to_string(H.size());
  std::vector<char> on_side(tmesh.num_half_arcs(), 0), cut(tmesh.num_arcs(), 0);
  for (const auto& sides : tmesh.patch_sides)
    for (const auto& side : sides)
      for (int h : side) on_side[h] = 1;
  std::set<std::vector<int>> relaxed;  // the arcs of each relaxed path
  for (const TwoGon& g : two_gons) {
    for (int m : g.paths) {
      if (m < 0 || m >= static_cast<int>(tmesh.nonzero_paths.size()))
        return "no non-zero path " + std::to_string(m);
      relaxed.insert(arcs_along(tmesh.nonzero_paths[m]));
    }
    for (int h : g.left) {
      if (h < 0 || h >= tmesh.num_half_arcs()) return "no half-arc " + std::to_string(h);
      cut[TMesh::arc_of(h)] = 1;
    }
  }
  // A border half-arc has no length of its own: its arc's is the other half's.
  const auto length = [&](int h) { return on_side[h] ? H[h] : H[TMesh::opposite(h)]; };
  for (int h = 0; h < tmesh.num_half_arcs(); ++h)
    if (on_side[h] && H[h] < 0)
      return "half-arc " + std::to_string(h) + ": negative length " + std::to_string(H[h]);
  for (int a = 0; a < tmesh.num_arcs(); ++a)
    if (!cut[a] && length(2 * a) != length(2 * a + 1))
      return "arc " + std::to_string(a) + ": its half-arcs have lengths " +
             std::to_string(length(2 * a)) + " and " + std::to_string(length(2 * a + 1)) +
             " but it lies on no relaxed path";
  for (int p = 0; p < tmesh.num_patches(); ++p)
    for (int k = 0; k < 2; ++k) {
      int64_t x = 0, y = 0;
      for (int h : tmesh.patch_sides[p][k]) x += H[h];
      for (int h : tmesh.patch_sides[p][k + 2]) y += H[h];
      if (x != y)
        return "patch " + std::to_string(p) + ": sides " + std::to_string(k) + " and " +
               std::to_string(k + 2) + " have lengths " + std::to_string(x) + " and " +
               std::to_string(y);
    }
  for (const TwoGon& g : two_gons) {
    const int n = static_cast<int>(g.left.size());
    // Prefix sums of either side along the line: sum[c][i] over its first i half-arcs.
    std::array<std::vector<int64_t>, 2> sum{std::vector<int64_t>(n + 1, 0),
                                            std::vector<int64_t>(n + 1, 0)};
    for (int i = 0; i < n; ++i) {
      sum[0][i + 1] = sum[0][i] + H[g.left[i]];
      sum[1][i + 1] = sum[1][i] + H[TMesh::opposite(g.left[i])];
    }
    const std::string line = "the line of path " + std::to_string(g.paths.front());
    if (sum[0][n] != sum[1][n])
      return line + ": its sides have lengths " + std::to_string(sum[0][n]) + " and " +
             std::to_string(sum[1][n]);
    if (g.paths.size() == 1 && sum[0][n] < 1) return line + ": it has length 0";
    if (g.paths.size() == 2 && sum[0][g.left_end] < 1)
      return "path " + std::to_string(g.paths[0]) + ": its left side has length 0";
    if (g.paths.size() == 2 && sum[1][n] - sum[1][g.right_start] < 1)
      return "path " + std::to_string(g.paths[1]) + ": its right side has length 0";
  }
  for (size_t m = 0; m < tmesh.nonzero_paths.size(); ++m) {
    if (relaxed.count(arcs_along(tmesh.nonzero_paths[m]))) continue;
    int64_t sum = 0;
    for (int h : tmesh.nonzero_paths[m]) sum += length(h);
    if (sum == 0) return "non-zero path " + std::to_string(m) + " has length 0";
  }
  return "";
}

}  // namespace bimdf::tmesh
