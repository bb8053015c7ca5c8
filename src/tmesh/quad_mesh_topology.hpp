// Half-edge connectivity of an all-quad mesh (internal to src/tmesh): what motorcycle tracing
// and patch extraction walk on.
//
// Half-edge h = 4f + k runs from quads[f][k] to quads[f][(k + 1) mod 4], with its quad f on the
// left (quads are counter-clockwise). Each undirected mesh edge e has one half-edge (border) or
// two, opposite to each other. Around every used vertex, the edges are kept in
// counter-clockwise order; a border vertex's ring starts with the border edge along which its
// quad fan begins (its outgoing border half-edge) and ends with the other border edge.
// Vertices that no quad uses are allowed and ignored (valence 0).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::tmesh::detail {

class QuadMeshTopology {
 public:
  // Throws InputError naming `source` and the quad, edge or vertex when the mesh has no quads,
  // a quad refers to a missing vertex or repeats one, an edge belongs to more than two quads,
  // two quads run along their shared edge in the same direction (inconsistent orientation), or
  // the quads around a vertex do not form a single fan (non-manifold vertex).
  QuadMeshTopology(const QuadMesh& mesh, const std::string& source);

  int num_vertices() const { return static_cast<int>(ring_offset_.size()) - 1; }
  int num_faces() const { return static_cast<int>(head_.size()) / 4; }
  int num_edges() const { return static_cast<int>(edge_half_.size()); }
  int num_half_edges() const { return static_cast<int>(head_.size()); }

  static int face(int h) { return h >> 2; }
  static int next(int h) { return (h & ~3) | ((h + 1) & 3); }
  static int prev(int h) { return (h & ~3) | ((h + 3) & 3); }
  int head(int h) const { return head_[h]; }
  int tail(int h) const { return head_[prev(h)]; }
  int opposite(int h) const { return opposite_[h]; }  // −1 on the border
  int edge(int h) const { return edge_[h]; }

  // [0] is always a half-edge of e; [1] is its opposite, or −1 for a border edge.
  const std::array<int, 2>& edge_half_edges(int e) const { return edge_half_[e]; }
  bool is_border_edge(int e) const { return edge_half_[e][1] < 0; }
  // (tail, head) of edge_half_edges(e)[0].
  std::array<int, 2> edge_vertices(int e) const {
    const int h = edge_half_[e][0];
    return {tail(h), head(h)};
  }
  int other_vertex(int e, int v) const {
    const auto [a, b] = edge_vertices(e);
    return a == v ? b : a;
  }

  // The edges at v, counter-clockwise (see above); empty for an unused vertex.
  std::span<const int> vertex_edges(int v) const {
    return {ring_.data() + ring_offset_[v], ring_.data() + ring_offset_[v + 1]};
  }
  int valence(int v) const { return ring_offset_[v + 1] - ring_offset_[v]; }
  bool is_used(int v) const { return valence(v) > 0; }
  bool is_border_vertex(int v) const { return border_vertex_[v] != 0; }
  // Interior valence 4 or border valence 3.
  bool is_regular(int v) const { return is_border_vertex(v) ? valence(v) == 3 : valence(v) == 4; }

  // The edge that continues e straight on through v: at an interior vertex of valence 4 the
  // opposite edge of the ring, at a border vertex of valence 3 the other border edge (the
  // inner edge has none). −1 at an irregular vertex or when there is none.
  int straight_on(int v, int e) const;

  // The edge joining a and b, or −1.
  int find_edge(int a, int b) const;

 private:
  std::vector<int> head_;      // per half-edge
  std::vector<int> opposite_;  // per half-edge
  std::vector<int> edge_;      // per half-edge
  std::vector<std::array<int, 2>> edge_half_;
  std::vector<int> ring_offset_, ring_;  // per vertex, CSR
  std::vector<uint8_t> border_vertex_;
};

// ---- Regions of the mesh cut along a set of edges (`cut`: one flag per edge) ----

// The end of the message for a closed grid without anything to cut it.
inline constexpr char kClosedGridLines[] =
    "no irregular vertex, border or feature: its grid lines close on themselves, so there is "
    "no layout to quantize";

// Marks for region walks, sized for one mesh; each walk uses a fresh `stamp` (bump it before
// each region), so nothing is ever cleared.
struct RegionScratch {
  explicit RegionScratch(const QuadMeshTopology& topo)
      : face(topo.num_faces(), -1),
        vertex(topo.num_vertices(), -1),
        half_edge(topo.num_half_edges(), -1) {}
  std::vector<int> face, vertex, half_edge;
  int stamp = 0;
};

// Face components across uncut edges, in order of their smallest quad, each sorted.
std::vector<std::vector<int>> cut_regions(const QuadMeshTopology& topo,
                                          const std::vector<uint8_t>& cut);

// From boundary half-edge h (cut, its quad in the region), around its head through the
// region's quads to the next boundary half-edge; `quads` counts the quads passed (1 at a
// convex corner, 2 on a straight border, 3 at a reflex corner of a regular vertex).
int turn_at_head(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut, int h, int& quads);

// A region's border: its closed curves as boundary half-edges in walking order (region on
// the left), its convex corners and reflex turns.
struct RegionBorder {
  std::vector<std::vector<int>> loops;
  int corners = 0, reflex = 0;
  int corner0_out = -1;  // the boundary half-edge leaving the corner of smallest vertex id
};
RegionBorder region_border(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut,
                           const std::vector<int>& faces, RegionScratch& scratch);

// A region as a rectangle of the grid, from corner 0 = the corner of smallest vertex id:
// `vertices` row-major as PatchGrid (tmesh.hpp), `sides` the boundary half-edges of its four
// sides (counter-clockwise, region on the left). If the rectangle meets itself (its grid
// passes through a mesh vertex twice: a ring crossed by a single cut), repeat[0] < repeat[1]
// are two positions in `vertices` holding the same vertex; else both −1.
struct RegionRectangle {
  int width = 0, height = 0;
  std::vector<int> vertices;
  std::array<std::vector<int>, 4> sides;
  std::array<int, 2> repeat{-1, -1};
};

// Throws InputError naming `source` and the region (by its quad count and smallest quad)
// when it is not a rectangle: no border at all (a closed grid), several border curves, not
// exactly 4 convex and 0 reflex corners, or a grid that does not cover it.
RegionRectangle region_rectangle(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut,
                                 const std::vector<int>& faces, const RegionBorder& border,
                                 RegionScratch& scratch, const std::string& source);

// "the N quads connected to quad F across uncut edges", for messages.
std::string region_name(const std::vector<int>& faces);

}  // namespace bimdf::tmesh::detail
