// Deflating the two-gons of a half-arc quantization into an arc-quantized T-mesh (paper
// Appendix A, Fig. 19; tmesh/half_arc.hpp). Along each two-gon the vertices of both copies of
// the path are merged by their quantized positions — the topological part of the paper's
// subject re-attachment, done for all T-junctions of a path at once, so that no processing order
// exists to depend on.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "bimdf/tmesh/half_arc.hpp"

namespace bimdf::tmesh {
namespace {

// One two-gon closed: its nodes in order along the path (T' vertex ids) and their positions.
struct Line {
  std::vector<int> node;
  std::vector<int64_t> position;
  std::vector<int> left_index, right_index;  // per path vertex 0..n: its node's index in `node`
  int reordered = 0;
};

// `anchored`: per T' vertex, whether it stays a T-mesh vertex on its own — arcs other than the
// line's attached, or a non-zero path ending there. `merge_into`: receives, per right copy
// merged into its left copy, the left copy.
Line close_two_gon(const TMesh& cut, const TwoGon& g, const std::vector<int64_t>& length,
                   const std::vector<char>& anchored, std::vector<int>& merge_into) {
  const size_t n = g.left.size();
  std::vector<int> u(n + 1), w(n + 1);
  std::vector<int64_t> pu(n + 1, 0), pw(n + 1, 0);
  u[0] = cut.half_arc_tail(g.left[0]), w[0] = cut.half_arc_tail(g.right[0]);
  for (size_t i = 0; i < n; ++i) {
    u[i + 1] = cut.half_arc_head(g.left[i]), w[i + 1] = cut.half_arc_head(g.right[i]);
    pu[i + 1] = pu[i] + length[TMesh::arc_of(g.left[i])];
    pw[i + 1] = pw[i] + length[TMesh::arc_of(g.right[i])];
  }
  if (u[0] != w[0] || u[n] != w[n] || pu[n] != pw[n])
    throw std::invalid_argument("deflate_two_gons: the two-gon of path " +
                                std::to_string(g.paths[0]) + " does not close (its sides differ)");
  // Interior path vertices, each side's copy at its position; a copy with nothing attached on
  // its side (only the path's two arcs) and no non-zero path ending there (the second path of an
  // overlapping pair starts at a right copy) is no T-mesh vertex any more and drops out, and both
  // copies at one position stay one vertex. Ties by place along the path keep each side's order.
  struct Item {
    int64_t position;
    size_t index;
    int side;  // 0 left, 1 right
  };
  std::vector<Item> items;
  for (size_t i = 1; i < n; ++i) {
    const bool left = anchored[u[i]], right = anchored[w[i]];
    if (left || (right && pu[i] == pw[i])) items.push_back({pu[i], i, 0});
    if (right && pu[i] != pw[i]) items.push_back({pw[i], i, 1});
    if (right && pu[i] == pw[i]) merge_into[w[i]] = u[i];
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return std::tie(a.position, a.index, a.side) < std::tie(b.position, b.index, b.side);
  });
  Line line;
  line.left_index.assign(n + 1, -1), line.right_index.assign(n + 1, -1);
  line.node.push_back(u[0]), line.position.push_back(0);
  line.left_index[0] = line.right_index[0] = 0;
  int left_seen = 0;  // left nodes before the current item along the line
  for (const Item& it : items) {
    const int idx = static_cast<int>(line.node.size());
    line.node.push_back(it.side == 0 ? u[it.index] : w[it.index]);
    line.position.push_back(it.position);
    if (it.side == 0) {
      line.left_index[it.index] = idx, ++left_seen;
      if (merge_into[w[it.index]] == u[it.index]) line.right_index[it.index] = idx;
    } else {
      line.right_index[it.index] = idx;
      // Before the deflation it had exactly the left nodes of smaller index before it.
      int before = 0;
      for (const Item& other : items) before += other.side == 0 && other.index < it.index;
      line.reordered += before != left_seen;
    }
  }
  line.node.push_back(u[n]), line.position.push_back(pu[n]);
  line.left_index[n] = line.right_index[n] = static_cast<int>(line.node.size()) - 1;
  return line;
}

}  // namespace

DeflatedTMesh deflate_two_gons(const InflatedTMesh& inflated,
                               const std::vector<int64_t>& arc_length) {
  const TMesh& cut = inflated.tmesh;
  if (static_cast<int>(arc_length.size()) != cut.num_arcs())
    throw std::invalid_argument("deflate_two_gons: " + std::to_string(arc_length.size()) +
                                " lengths for " + std::to_string(cut.num_arcs()) + " arcs");
  std::vector<int> degree(cut.num_vertices(), 0);
  for (const auto& ends : cut.arc_ends) ++degree[ends[0]], ++degree[ends[1]];
  std::vector<char> anchored(cut.num_vertices(), 0);
  for (int v = 0; v < cut.num_vertices(); ++v) anchored[v] = degree[v] > 2;
  for (const auto& path : cut.nonzero_paths)
    if (!path.empty())
      anchored[cut.half_arc_tail(path.front())] = anchored[cut.half_arc_head(path.back())] = 1;
  std::vector<int> merge_into(cut.num_vertices(), -1);
  std::vector<Line> lines;
  // Per T' half-arc on a two-gon: (two-gon, index along the path, side 0 left / 1 right).
  std::vector<std::array<int, 3>> on_two_gon(cut.num_half_arcs(), {-1, -1, -1});
  DeflatedTMesh out;
  for (size_t t = 0; t < inflated.two_gons.size(); ++t) {
    const TwoGon& g = inflated.two_gons[t];
    lines.push_back(close_two_gon(cut, g, arc_length, anchored, merge_into));
    out.reordered_junctions += lines.back().reordered;
    for (size_t i = 0; i < g.left.size(); ++i) {
      const int ti = static_cast<int>(t), ii = static_cast<int>(i);
      for (int h : {g.left[i], TMesh::opposite(g.left[i])}) on_two_gon[h] = {ti, ii, 0};
      for (int h : {g.right[i], TMesh::opposite(g.right[i])}) on_two_gon[h] = {ti, ii, 1};
    }
  }

  // Arcs: T''s off the two-gons, then each line's runs between consecutive nodes.
  TMesh& o = out.tmesh;
  std::vector<int> new_arc(cut.num_arcs(), -1);
  const auto add_arc = [&](int a, int b, double target, uint8_t feature, int64_t length) {
    o.arc_ends.push_back({a, b});
    o.arc_target.push_back(target);
    if (!cut.arc_feature.empty()) o.arc_feature.push_back(feature);
    out.arc_length.push_back(length);
  };
  for (int a = 0; a < cut.num_arcs(); ++a)
    if (on_two_gon[2 * a][0] < 0) {
      new_arc[a] = o.num_arcs();
      add_arc(cut.arc_ends[a][0], cut.arc_ends[a][1], cut.arc_target[a],
              cut.arc_feature.empty() ? 0 : cut.arc_feature[a], arc_length[a]);
    }
  std::vector<int> first_line_arc;
  for (const Line& line : lines) {
    first_line_arc.push_back(o.num_arcs());
    for (size_t k = 0; k + 1 < line.node.size(); ++k) {
      const int64_t x = line.position[k + 1] - line.position[k];
      add_arc(line.node[k], line.node[k + 1], static_cast<double>(x), 0, x);
    }
  }
  for (auto& ends : o.arc_ends)
    for (int& v : ends)
      if (merge_into[v] >= 0) v = merge_into[v];

  // The line's half-arcs from node index `from` to `to`, either way.
  const auto along = [&](int line, int from, int to, std::vector<int>& into) {
    for (int k = from; k < to; ++k) into.push_back(2 * (first_line_arc[line] + k));
    for (int k = from; k > to; --k) into.push_back(2 * (first_line_arc[line] + k - 1) + 1);
  };
  // A chain of T' half-arcs with runs along two-gons replaced by the line's half-arcs.
  const auto map_chain = [&](const std::vector<int>& chain) {
    std::vector<int> mapped;
    for (size_t i = 0; i < chain.size();) {
      const int h = chain[i];
      if (on_two_gon[h][0] < 0) {
        mapped.push_back(2 * new_arc[TMesh::arc_of(h)] + (h & 1));
        ++i;
        continue;
      }
      const auto [t, first, side] = on_two_gon[h];
      const TwoGon& g = inflated.two_gons[t];
      const std::vector<int>& copy = side == 0 ? g.left : g.right;
      const bool forward = h == copy[first];
      size_t j = i;
      while (j < chain.size() && on_two_gon[chain[j]][0] == t && on_two_gon[chain[j]][2] == side)
        ++j;
      const int last = on_two_gon[chain[j - 1]][1];
      const std::vector<int>& index = side == 0 ? lines[t].left_index : lines[t].right_index;
      if (forward)
        along(t, index[first], index[last + 1], mapped);
      else
        along(t, index[first + 1], index[last], mapped);
      i = j;
    }
    // A path detouring around a line's end in T' (inflate_two_gons) goes there and back.
    std::vector<int> direct;
    for (int h : mapped)
      if (!direct.empty() && direct.back() == TMesh::opposite(h))
        direct.pop_back();
      else
        direct.push_back(h);
    return direct;
  };
  o.patch_sides.resize(cut.num_patches());
  for (int p = 0; p < cut.num_patches(); ++p)
    for (int k = 0; k < 4; ++k) o.patch_sides[p][k] = map_chain(cut.patch_sides[p][k]);
  for (const auto& path : cut.nonzero_paths) o.nonzero_paths.push_back(map_chain(path));

  // Vertices still used, in T' order.
  std::vector<int> new_vertex(cut.num_vertices(), -1);
  for (const auto& ends : o.arc_ends)
    for (int v : ends) new_vertex[v] = 0;
  for (int v = 0; v < cut.num_vertices(); ++v) {
    if (new_vertex[v] < 0) continue;
    new_vertex[v] = o.num_vertices();
    o.vertices.push_back(cut.vertices[v]);
    if (!cut.vertex_mesh_vertex.empty()) o.vertex_mesh_vertex.push_back(cut.vertex_mesh_vertex[v]);
  }
  for (auto& ends : o.arc_ends)
    for (int& v : ends) v = new_vertex[v];
  return out;
}

}  // namespace bimdf::tmesh
