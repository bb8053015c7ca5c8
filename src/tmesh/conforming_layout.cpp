// conforming_layout and write_layout_obj (tmesh/collapse.hpp): the base complex of a quad
// mesh, as metrics.cpp computes it, with feature curves cutting too, then each patch's
// boundary walked into four sides.
#include <algorithm>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bimdf/tmesh/collapse.hpp"

namespace bimdf::tmesh {
namespace {

using Edge = std::pair<int, int>;
Edge undirected(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

struct Connectivity {
  std::map<Edge, std::vector<int>> edge_quads;
  std::vector<std::vector<int>> neighbours;
  std::vector<char> on_boundary;
};

Connectivity connectivity(const QuadMesh& mesh) {
  Connectivity c;
  for (int f = 0; f < mesh.num_quads(); ++f)
    for (int a = 0; a < 4; ++a)
      c.edge_quads[undirected(mesh.quads[f][a], mesh.quads[f][(a + 1) % 4])].push_back(f);
  c.neighbours.resize(mesh.num_vertices());
  c.on_boundary.assign(mesh.num_vertices(), 0);
  for (const auto& [e, quads] : c.edge_quads) {
    c.neighbours[e.first].push_back(e.second);
    c.neighbours[e.second].push_back(e.first);
    if (quads.size() != 2) c.on_boundary[e.first] = c.on_boundary[e.second] = 1;
  }
  return c;
}

// The cut edges: border, features, and separatrices traced straight on from every singular
// vertex and feature corner until they reach the border, a singular or irregular vertex, or
// an edge already cut (another separatrix on the same grid line, or a loop closing).
std::set<Edge> cut_edges(const QuadMesh& mesh, const Connectivity& c,
                         const std::vector<std::array<int, 2>>& feature_edges) {
  const int nv = mesh.num_vertices();
  std::set<Edge> cut;
  for (const auto& [e, quads] : c.edge_quads)
    if (quads.size() != 2) cut.insert(e);
  std::vector<std::vector<int>> feature_at(nv);
  for (const auto& [u, v] : feature_edges) {
    const Edge e = undirected(u, v);
    if (u < 0 || v < 0 || u >= nv || v >= nv || !c.edge_quads.count(e))
      throw std::invalid_argument("feature edge (" + std::to_string(u) + ", " + std::to_string(v) +
                                  ") is not an edge of the mesh");
    if (!cut.insert(e).second) continue;  // a border edge, or given twice
    feature_at[u].push_back(v), feature_at[v].push_back(u);
  }
  const auto valence = [&](int v) { return static_cast<int>(c.neighbours[v].size()); };
  const auto share_a_quad = [&](int v, int a, int b) {
    for (int f : c.edge_quads.at(undirected(v, a)))
      for (int g : c.edge_quads.at(undirected(v, b)))
        if (f == g) return true;
    return false;
  };
  std::vector<char> source(nv, 0), singular(nv, 0);
  for (int v = 0; v < nv; ++v) {
    singular[v] = c.on_boundary[v] ? valence(v) != 3 : valence(v) != 4;
    // A feature corner: where a curve ends, branches, meets the border or turns.
    const auto& fe = feature_at[v];
    const bool corner =
        !fe.empty() && (fe.size() != 2 || c.on_boundary[v] || share_a_quad(v, fe[0], fe[1]));
    source[v] = singular[v] || corner;
  }
  // w's two neighbours in quad f.
  const auto beside_in = [&](int w, int f) {
    for (int a = 0; a < 4; ++a)
      if (mesh.quads[f][a] == w)
        return Edge{mesh.quads[f][(a + 1) % 4], mesh.quads[f][(a + 3) % 4]};
    return Edge{-1, -1};
  };
  for (int s = 0; s < nv; ++s) {
    if (!source[s]) continue;
    for (int first : c.neighbours[s]) {
      int from = s, to = first;
      while (cut.insert(undirected(from, to)).second) {
        if (singular[to] || c.on_boundary[to] || valence(to) != 4) break;
        std::set<int> beside{from};
        for (int g : c.edge_quads.at(undirected(from, to))) {
          const Edge n = beside_in(to, g);
          beside.insert(n.first), beside.insert(n.second);
        }
        int next = -1;
        for (int w : c.neighbours[to])
          if (!beside.count(w)) next = w;
        if (next < 0) break;
        from = to, to = next;
      }
    }
  }
  return cut;
}

}  // namespace

ConformingLayout conforming_layout(const QuadMesh& mesh,
                                   const std::vector<std::array<int, 2>>& feature_edges) {
  const Connectivity c = connectivity(mesh);
  const std::set<Edge> cut = cut_edges(mesh, c, feature_edges);
  const int nf = mesh.num_quads(), nv = mesh.num_vertices();
  ConformingLayout layout;
  layout.face_patch.assign(nf, -1);
  std::vector<std::vector<int>> patch_faces;
  for (int f = 0; f < nf; ++f) {
    if (layout.face_patch[f] >= 0) continue;
    const int p = static_cast<int>(patch_faces.size());
    patch_faces.push_back({f});
    layout.face_patch[f] = p;
    for (size_t k = 0; k < patch_faces[p].size(); ++k) {
      const int g = patch_faces[p][k];
      for (int a = 0; a < 4; ++a) {
        const Edge e = undirected(mesh.quads[g][a], mesh.quads[g][(a + 1) % 4]);
        if (cut.count(e)) continue;
        for (int h : c.edge_quads.at(e))
          if (layout.face_patch[h] < 0) layout.face_patch[h] = p, patch_faces[p].push_back(h);
      }
    }
  }
  // Each patch's boundary: the half-edges of its quads across a cut, one loop with the patch
  // on the left; corners are where the patch has a single quad.
  std::vector<int> next(nv, -1), quads_at(nv, 0);
  for (int p = 0; p < static_cast<int>(patch_faces.size()); ++p) {
    const std::string name = "base complex patch " + std::to_string(p) + " (with quad " +
                             std::to_string(patch_faces[p].front()) + ")";
    std::vector<int> touched;
    int boundary_edges = 0;
    for (int f : patch_faces[p])
      for (int a = 0; a < 4; ++a) {
        const int u = mesh.quads[f][a], v = mesh.quads[f][(a + 1) % 4];
        if (quads_at[u]++ == 0) touched.push_back(u);
        if (!cut.count(undirected(u, v))) continue;
        if (next[u] >= 0)
          throw CollapseError(name + " is not a disk: its boundary passes vertex " +
                              std::to_string(u) + " twice");
        next[u] = v, ++boundary_edges;
      }
    int start = std::numeric_limits<int>::max(), corners = 0;
    for (int v : touched)
      if (next[v] >= 0 && quads_at[v] == 1) start = std::min(start, v), ++corners;
    std::array<std::vector<int>, 4> sides;
    int walked = 0, k = -1;
    if (corners == 4) {
      int v = start;
      do {
        if (quads_at[v] == 1) {
          ++k;
          if (k > 0) sides[k - 1].push_back(v);
        }
        sides[k].push_back(v);
        v = next[v], ++walked;
      } while (v >= 0 && v != start && walked <= boundary_edges);
      sides[3].push_back(start);
    }
    std::array<int64_t, 4> length{};
    for (int s = 0; s < 4; ++s) length[s] = static_cast<int64_t>(sides[s].size()) - 1;
    for (int v : touched) next[v] = -1, quads_at[v] = 0;
    if (corners != 4)
      throw CollapseError(name + " has " + std::to_string(corners) + " corners, expected 4");
    if (walked != boundary_edges || length[0] != length[2] || length[1] != length[3] ||
        length[0] * length[1] != static_cast<int64_t>(patch_faces[p].size()))
      throw CollapseError(name + " is not a rectangle of the grid: sides " +
                          std::to_string(length[0]) + ", " + std::to_string(length[1]) + ", " +
                          std::to_string(length[2]) + ", " + std::to_string(length[3]) +
                          " around " + std::to_string(patch_faces[p].size()) + " quads");
    layout.patch_corners.push_back({sides[0][0], sides[1][0], sides[2][0], sides[3][0]});
    layout.patch_side_length.push_back(length);
    layout.patch_side_chain.push_back(std::move(sides));
  }
  return layout;
}

void write_layout_obj(std::ostream& out, const QuadMesh& mesh, const ConformingLayout& layout) {
  out.precision(std::numeric_limits<double>::max_digits10);
  for (const auto& v : mesh.vertices) out << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  for (size_t p = 0; p < layout.patch_corners.size(); ++p) {
    const auto& length = layout.patch_side_length[p];
    const auto& corner = layout.patch_corners[p];
    out << "g patch_" << p << "\n# sides " << length[0] << ' ' << length[1] << ' ' << length[2]
        << ' ' << length[3] << "\nf " << corner[0] + 1 << ' ' << corner[1] + 1 << ' '
        << corner[2] + 1 << ' ' << corner[3] + 1 << '\n';
    for (const auto& chain : layout.patch_side_chain[p]) {
      out << 'l';
      for (int v : chain) out << ' ' << v + 1;
      out << '\n';
    }
  }
}

}  // namespace bimdf::tmesh
