#include "tmesh/quad_mesh_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "bimdf/error.hpp"

namespace bimdf::tmesh::detail {
namespace {

std::string edge_name(int a, int b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

}  // namespace

QuadMeshTopology::QuadMeshTopology(const QuadMesh& mesh, const std::string& source) {
  auto fail = [&](const std::string& what) { throw InputError(source, "", what); };
  const int V = mesh.num_vertices(), F = mesh.num_quads();
  if (F == 0) fail("the mesh has no quads");
  head_.resize(4 * size_t(F));
  for (int f = 0; f < F; ++f) {
    const auto& q = mesh.quads[f];
    for (int k = 0; k < 4; ++k) {
      if (q[k] < 0 || q[k] >= V)
        fail("quad " + std::to_string(f) + ": vertex index " + std::to_string(q[k]) +
             " is out of range (the mesh has " + std::to_string(V) + " vertices)");
      for (int j = 0; j < k; ++j)
        if (q[j] == q[k])
          fail("quad " + std::to_string(f) + " repeats vertex " + std::to_string(q[k]) +
               " (a degenerate quad)");
    }
    for (int k = 0; k < 4; ++k) head_[4 * f + k] = q[(k + 1) % 4];
  }

  // Group half-edges by their undirected edge: sorting by (smaller vertex, larger vertex, id)
  // numbers edges in a fixed order and finds the pairs without hashing.
  const int H = num_half_edges();
  auto edge_key = [&](int h) {
    const uint64_t a = static_cast<uint32_t>(tail(h)), b = static_cast<uint32_t>(head(h));
    return std::min(a, b) << 32 | std::max(a, b);
  };
  std::vector<int> order(H);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    const uint64_t kx = edge_key(x), ky = edge_key(y);
    return kx != ky ? kx < ky : x < y;
  });
  opposite_.assign(H, -1);
  edge_.assign(H, -1);
  for (int i = 0; i < H;) {
    int j = i;
    while (j < H && edge_key(order[j]) == edge_key(order[i])) ++j;
    const int h0 = order[i];
    if (j - i > 2) {
      std::string faces;
      for (int k = i; k < j; ++k) faces += (k > i ? ", " : "") + std::to_string(face(order[k]));
      fail(edge_name(tail(h0), head(h0)) + " is shared by " + std::to_string(j - i) + " quads (" +
           faces + "): the mesh is not manifold");
    }
    const int e = num_edges();
    edge_[h0] = e;
    if (j - i == 2) {
      const int h1 = order[i + 1];
      if (tail(h0) == tail(h1))
        fail("quads " + std::to_string(face(h0)) + " and " + std::to_string(face(h1)) +
             " both run from vertex " + std::to_string(tail(h0)) + " to vertex " +
             std::to_string(head(h0)) + " along their shared edge: the mesh is not " +
             "consistently oriented");
      opposite_[h0] = h1;
      opposite_[h1] = h0;
      edge_[h1] = e;
      edge_half_.push_back({h0, h1});
    } else {
      edge_half_.push_back({h0, -1});
    }
    i = j;
  }

  // Per vertex: its outgoing half-edges, and how many of them and of its incoming ones are on
  // the border; a manifold vertex has one fan of quads, hence at most one of each.
  std::vector<int> out_count(V, 0), out_border(V, -1), border_out_count(V, 0),
      border_in_count(V, 0);
  for (int h = 0; h < H; ++h) {
    const int v = tail(h);
    ++out_count[v];
    if (opposite_[h] < 0) {
      ++border_out_count[v];
      ++border_in_count[head(h)];
      out_border[v] = h;
    }
  }
  std::vector<int> first_out(V, -1);
  for (int h = H - 1; h >= 0; --h) first_out[tail(h)] = h;
  border_vertex_.assign(V, 0);
  ring_offset_.assign(V + 1, 0);
  ring_.reserve(H + 2 * size_t(V));
  for (int v = 0; v < V; ++v) {
    ring_offset_[v] = static_cast<int>(ring_.size());
    if (out_count[v] == 0) continue;
    const std::string not_manifold = "the quads around vertex " + std::to_string(v) +
                                     " do not form a single fan: the mesh is not manifold there";
    if (border_out_count[v] > 1 || border_in_count[v] != border_out_count[v]) fail(not_manifold);
    border_vertex_[v] = border_out_count[v] > 0;
    // Counter-clockwise: from an outgoing half-edge h, across its quad to the edge entering v
    // (prev(h)), whose opposite leaves v in the next quad.
    const int start = border_vertex_[v] ? out_border[v] : first_out[v];
    int h = start, visited = 0;
    while (true) {
      ring_.push_back(edge_[h]);
      ++visited;
      const int p = prev(h);
      const int o = opposite_[p];
      if (o < 0) {
        ring_.push_back(edge_[p]);
        break;
      }
      if (o == start || visited > out_count[v]) break;
      h = o;
    }
    if (visited != out_count[v]) fail(not_manifold);
  }
  ring_offset_[V] = static_cast<int>(ring_.size());
}

int QuadMeshTopology::straight_on(int v, int e) const {
  const std::span<const int> ring = vertex_edges(v);
  if (is_border_vertex(v)) {
    if (ring.size() != 3) return -1;
    if (e == ring[0]) return ring[2];
    if (e == ring[2]) return ring[0];
    return -1;
  }
  if (ring.size() != 4) return -1;
  for (int i = 0; i < 4; ++i)
    if (ring[i] == e) return ring[(i + 2) % 4];
  return -1;
}

int QuadMeshTopology::find_edge(int a, int b) const {
  if (a < 0 || a >= num_vertices()) return -1;
  for (int e : vertex_edges(a))
    if (other_vertex(e, a) == b) return e;
  return -1;
}

std::string region_name(const std::vector<int>& faces) {
  return "the " + std::to_string(faces.size()) + " quads connected to quad " +
         std::to_string(faces.front()) + " across uncut edges";
}

std::vector<std::vector<int>> cut_regions(const QuadMeshTopology& topo,
                                          const std::vector<uint8_t>& cut) {
  const int F = topo.num_faces();
  std::vector<int> component(F, -1);
  std::vector<std::vector<int>> regions;
  for (int f0 = 0; f0 < F; ++f0) {
    if (component[f0] >= 0) continue;
    const int id = static_cast<int>(regions.size());
    std::vector<int> faces{f0};
    component[f0] = id;
    for (size_t i = 0; i < faces.size(); ++i)
      for (int k = 0; k < 4; ++k) {
        const int h = 4 * faces[i] + k;
        if (cut[topo.edge(h)]) continue;
        const int g = QuadMeshTopology::face(topo.opposite(h));
        if (component[g] < 0) {
          component[g] = id;
          faces.push_back(g);
        }
      }
    std::sort(faces.begin(), faces.end());
    regions.push_back(std::move(faces));
  }
  return regions;
}

int turn_at_head(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut, int h, int& quads) {
  int c = QuadMeshTopology::next(h);
  quads = 1;
  while (!cut[topo.edge(c)] && quads <= topo.valence(topo.head(h))) {
    c = QuadMeshTopology::next(topo.opposite(c));
    ++quads;
  }
  return c;
}

RegionBorder region_border(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut,
                           const std::vector<int>& faces, RegionScratch& scratch) {
  std::vector<int>& half_edge_stamp = scratch.half_edge;
  const int stamp = scratch.stamp;
  RegionBorder b;
  for (int f : faces)
    for (int k = 0; k < 4; ++k) {
      const int h0 = 4 * f + k;
      if (!cut[topo.edge(h0)] || half_edge_stamp[h0] == stamp) continue;
      std::vector<int> loop;
      for (int h = h0; half_edge_stamp[h] != stamp;) {
        half_edge_stamp[h] = stamp;
        loop.push_back(h);
        int quads = 0;
        const int n = turn_at_head(topo, cut, h, quads);
        if (quads == 1) {
          ++b.corners;
          if (b.corner0_out < 0 || topo.tail(n) < topo.tail(b.corner0_out)) b.corner0_out = n;
        } else if (quads > 2) {
          ++b.reflex;
        }
        h = n;
      }
      b.loops.push_back(std::move(loop));
    }
  return b;
}

RegionRectangle region_rectangle(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut,
                                 const std::vector<int>& faces, const RegionBorder& border,
                                 RegionScratch& scratch, const std::string& source) {
  std::vector<int>& face_stamp = scratch.face;
  std::vector<int>& vertex_stamp = scratch.vertex;
  const int stamp = scratch.stamp;
  const std::string region = region_name(faces);
  auto fail = [&](const std::string& why) {
    throw InputError(source, "", region + " do not form a rectangle of the grid: " + why);
  };
  if (border.loops.empty()) throw InputError(source, "", region + " have " + kClosedGridLines);
  if (border.loops.size() > 1)
    fail("their border is " + std::to_string(border.loops.size()) + " separate closed curves");
  if (border.corners != 4 || border.reflex != 0)
    fail("their border has " + std::to_string(border.corners) + " convex and " +
         std::to_string(border.reflex) + " reflex corners, not 4 and 0");
  const int corner0_out = border.corner0_out;
  const size_t boundary_size = border.loops[0].size();

  // Rows of quads from corner 0: row j's half-edges run along the bottom of its quads.
  RegionRectangle out;
  std::vector<int> row;
  for (int h = corner0_out;;) {
    row.push_back(h);
    int quads = 0;
    const int n = turn_at_head(topo, cut, h, quads);
    if (quads == 1) break;
    h = n;
  }
  const int w = static_cast<int>(row.size());
  std::vector<std::vector<int>> rows;
  while (true) {
    for (int i = 0; i < w; ++i) {
      const int h = row[i], f = QuadMeshTopology::face(h);
      if (face_stamp[f] == stamp) fail("the grid wraps around onto quad " + std::to_string(f));
      face_stamp[f] = stamp;
      const bool left_cut = cut[topo.edge(QuadMeshTopology::prev(h))];
      const bool right_cut = cut[topo.edge(QuadMeshTopology::next(h))];
      if (left_cut != (i == 0) || right_cut != (i == w - 1))
        fail("quad " + std::to_string(f) + " has a cut edge inside the rectangle");
      if (i + 1 < w &&
          topo.opposite(QuadMeshTopology::next(h)) != QuadMeshTopology::prev(row[i + 1]))
        fail("the grid wraps around near quad " + std::to_string(f));
    }
    rows.push_back(row);
    const bool top = cut[topo.edge(QuadMeshTopology::next(QuadMeshTopology::next(row[0])))];
    for (int i = 1; i < w; ++i)
      if (cut[topo.edge(QuadMeshTopology::next(QuadMeshTopology::next(row[i])))] != top)
        fail("quad " + std::to_string(QuadMeshTopology::face(row[i])) +
             " has a cut edge inside the rectangle");
    if (top) break;
    for (int i = 0; i < w; ++i)
      row[i] = topo.opposite(QuadMeshTopology::next(QuadMeshTopology::next(row[i])));
  }
  const int h = static_cast<int>(rows.size());
  if (size_t(w) * h != faces.size() || size_t(2 * (w + h)) != boundary_size)
    fail("a " + std::to_string(w) + " x " + std::to_string(h) + " grid of quads from corner " +
         std::to_string(topo.tail(corner0_out)) + " does not cover them");

  out.width = w;
  out.height = h;
  out.vertices.resize(size_t(w + 1) * (h + 1));
  auto top_edge = [&](int i) {
    return QuadMeshTopology::next(QuadMeshTopology::next(rows[h - 1][i]));
  };
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) out.vertices[j * (w + 1) + i] = topo.tail(rows[j][i]);
    out.vertices[j * (w + 1) + w] = topo.head(rows[j][w - 1]);
  }
  for (int i = 0; i < w; ++i) out.vertices[h * (w + 1) + i] = topo.head(top_edge(i));
  out.vertices[h * (w + 1) + w] = topo.tail(top_edge(w - 1));
  for (size_t k = 0; k < out.vertices.size(); ++k) {
    const int v = out.vertices[k];
    if (vertex_stamp[v] == stamp && out.repeat[0] < 0) {
      const auto first = std::find(out.vertices.begin(), out.vertices.end(), v);
      out.repeat = {static_cast<int>(first - out.vertices.begin()), static_cast<int>(k)};
    }
    vertex_stamp[v] = stamp;
  }
  for (int i = 0; i < w; ++i) out.sides[0].push_back(rows[0][i]);
  for (int j = 0; j < h; ++j) out.sides[1].push_back(QuadMeshTopology::next(rows[j][w - 1]));
  for (int i = w - 1; i >= 0; --i) out.sides[2].push_back(top_edge(i));
  for (int j = h - 1; j >= 0; --j) out.sides[3].push_back(QuadMeshTopology::prev(rows[j][0]));
  return out;
}

}  // namespace bimdf::tmesh::detail
