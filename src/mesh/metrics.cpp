#include "bimdf/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/union_find.hpp"
#include "mesh/closest_point.hpp"
#include "mesh/quad_adjacency.hpp"
#include "mesh/quad_quality.hpp"
#include "mesh/vec3.hpp"

namespace bimdf {

int QuadMeshMetrics::singular_vertices() const {
  int n = 0;
  for (const auto& [valence, count] : interior_singularities) n += count;
  for (const auto& [valence, count] : boundary_singularities) n += count;
  return n;
}

namespace {

using detail::dot;
using detail::norm;
using detail::sub;
using detail::Vec3;

using Edge = std::pair<int, int>;
Edge undirected(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Connected pieces of a set of edges on vertices 0..n−1; on a manifold mesh the boundary
// edges' pieces are its border loops.
int edge_pieces(int n, const std::vector<Edge>& edges) {
  detail::SmallestRootUnionFind classes(n);
  int pieces = 0;
  std::vector<char> touched(n, 0);
  for (const auto& [a, b] : edges) {
    pieces += !touched[a] + !touched[b];
    touched[a] = touched[b] = 1;
    if (classes.find(a) != classes.find(b)) classes.unite(a, b), --pieces;
  }
  return pieces;
}

// measure_quad_mesh, and (when `patch_of` is given) each quad's base-complex patch.
QuadMeshMetrics measure(const QuadMesh& mesh, const TriangleMesh* reference,
                        std::vector<int>* patch_of) {
  QuadMeshMetrics m;
  const int nv = mesh.num_vertices(), nf = mesh.num_quads();
  m.faces = nf;
  // Edges with their quads and directions.
  std::map<Edge, std::vector<std::pair<int, bool>>> edges;  // edge → (quad, walks a → b)
  for (int f = 0; f < nf; ++f)
    for (int a = 0; a < 4; ++a) {
      const int u = mesh.quads[f][a], v = mesh.quads[f][(a + 1) % 4];
      edges[undirected(u, v)].push_back({f, u < v});
    }
  m.edges = static_cast<int>(edges.size());
  std::vector<std::vector<int>> neighbours(nv);
  std::vector<char> on_boundary(nv, 0), used(nv, 0);
  std::vector<Edge> boundary;
  for (const auto& [e, quads] : edges) {
    neighbours[e.first].push_back(e.second);
    neighbours[e.second].push_back(e.first);
    used[e.first] = used[e.second] = 1;
    if (quads.size() == 1) {
      ++m.boundary_edges;
      boundary.push_back(e);
      on_boundary[e.first] = on_boundary[e.second] = 1;
    } else if (quads.size() > 2 || quads[0].second == quads[1].second) {
      ++m.non_manifold_edges;
    }
  }
  int used_vertices = 0;
  for (char u : used) used_vertices += u;
  m.vertices = used_vertices;
  m.euler_characteristic = used_vertices - m.edges + nf;
  m.border_loops = edge_pieces(nv, boundary);

  // Fans: quads around a vertex connected through the edges at that vertex.
  const std::vector<std::vector<int>> vertex_quads = detail::quads_at_vertices(mesh);
  for (int v = 0; v < nv; ++v) {
    if (vertex_quads[v].empty()) continue;
    std::set<int> seen{vertex_quads[v][0]};
    std::vector<int> stack{vertex_quads[v][0]};
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int a = 0; a < 4; ++a) {
        if (mesh.quads[f][a] != v) continue;
        for (int w : {mesh.quads[f][(a + 1) % 4], mesh.quads[f][(a + 3) % 4]})
          for (const auto& [g, dir] : edges[undirected(v, w)])
            if (seen.insert(g).second) stack.push_back(g);
      }
    }
    if (seen.size() != vertex_quads[v].size()) ++m.non_manifold_vertices;
  }

  std::vector<char> singular(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    const int valence = static_cast<int>(neighbours[v].size());
    if (on_boundary[v] && valence != 3) ++m.boundary_singularities[valence], singular[v] = 1;
    if (!on_boundary[v] && valence != 4) ++m.interior_singularities[valence], singular[v] = 1;
  }

  // Scaled Jacobians.
  std::vector<double> sj(nf);
  double sum = 0;
  for (int f = 0; f < nf; ++f) {
    sj[f] = detail::scaled_jacobian(mesh, mesh.quads[f]);
    sum += sj[f];
    const bool flat = detail::degenerate(mesh, mesh.quads[f]);
    m.degenerate += flat;
    m.inverted += !flat && sj[f] < 0;
  }
  if (nf > 0) {
    m.scaled_jacobian_mean = sum / nf;
    std::vector<double> sorted = sj;
    std::sort(sorted.begin(), sorted.end());
    m.scaled_jacobian_min = sorted.front();
    m.scaled_jacobian_p5 = sorted[static_cast<size_t>(0.05 * (nf - 1))];
  }

  // Base complex: trace separatrices straight through regular interior vertices.
  std::set<Edge> cut;
  for (const auto& [e, quads] : edges)
    if (quads.size() != 2) cut.insert(e);
  const auto quad_neighbours_of = [&](int w, int f) {  // w's two neighbours in quad f
    for (int a = 0; a < 4; ++a)
      if (mesh.quads[f][a] == w)
        return Edge{mesh.quads[f][(a + 1) % 4], mesh.quads[f][(a + 3) % 4]};
    return Edge{-1, -1};
  };
  for (int s = 0; s < nv; ++s) {
    if (!singular[s]) continue;
    for (int first : neighbours[s]) {
      int from = s, to = first;
      while (cut.insert(undirected(from, to)).second) {
        if (singular[to] || on_boundary[to] || neighbours[to].size() != 4) break;
        // The edge at `to` opposite (from, to): not in either quad beside (from, to).
        std::set<int> beside{from};
        for (const auto& [g, dir] : edges[undirected(from, to)]) {
          const Edge n = quad_neighbours_of(to, g);
          beside.insert(n.first), beside.insert(n.second);
        }
        int next = -1;
        for (int w : neighbours[to])
          if (!beside.count(w)) next = w;
        if (next < 0) break;
        from = to, to = next;
      }
    }
  }
  std::vector<int> patch(nf, -1);
  for (int f = 0; f < nf; ++f) {
    if (patch[f] >= 0) continue;
    patch[f] = m.base_complex_faces++;
    std::vector<int> stack{f};
    while (!stack.empty()) {
      const int g = stack.back();
      stack.pop_back();
      for (int a = 0; a < 4; ++a) {
        const Edge e = undirected(mesh.quads[g][a], mesh.quads[g][(a + 1) % 4]);
        if (cut.count(e)) continue;
        for (const auto& [h, dir] : edges[e])
          if (patch[h] < 0) patch[h] = patch[f], stack.push_back(h);
      }
    }
  }

  if (patch_of) *patch_of = patch;

  if (reference && reference->num_faces() > 0) {
    const detail::TriangleTree tree(*reference);
    Vec3 lo = reference->vertices[0], hi = lo;
    for (const Vec3& p : reference->vertices)
      for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
    m.hausdorff = 0;
    const auto sample = [&](const Vec3& p) { m.hausdorff = tree.farther(p, m.hausdorff); };
    // The reference's unit normal at each vertex's closest point. Vertices lie on the surface
    // (distance ~0), so unlike a quad's centre they cannot pick the far side of a thin part.
    std::vector<Vec3> vertex_normal(nv, Vec3{0, 0, 0});
    for (int v = 0; v < nv; ++v) {
      if (!used[v]) continue;
      const detail::TriangleTree::Hit hit = tree.closest(mesh.vertices[v]);
      m.hausdorff = std::max(m.hausdorff, hit.distance);
      vertex_normal[v] = detail::normalized(detail::triangle_normal(*reference, hit.face));
    }
    for (const auto& [e, quads] : edges) {
      const Vec3& a = mesh.vertices[e.first];
      const Vec3& b = mesh.vertices[e.second];
      sample({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
    }
    for (const auto& q : mesh.quads) {
      sample(detail::quad_centre(mesh, q));
      Vec3 normal{0, 0, 0};
      for (int v : q)
        for (int d = 0; d < 3; ++d) normal[d] += vertex_normal[v][d];
      m.flipped += dot(normal, detail::newell_normal(mesh, q)) < 0;
    }
    const double diagonal = norm(sub(hi, lo));
    m.hausdorff_relative = diagonal > 0 ? m.hausdorff / diagonal : 0;
  }
  return m;
}

}  // namespace

QuadMeshMetrics measure_quad_mesh(const QuadMesh& mesh, const TriangleMesh* reference) {
  return measure(mesh, reference, nullptr);
}

std::vector<int> base_complex_patches(const QuadMesh& mesh) {
  std::vector<int> patch_of;
  measure(mesh, nullptr, &patch_of);
  return patch_of;
}

std::string topology_difference(const QuadMeshMetrics& quads, const TriangleMesh& surface) {
  std::map<Edge, int> faces_at;
  std::vector<char> used(surface.num_vertices(), 0);
  for (const auto& t : surface.faces)
    for (int k = 0; k < 3; ++k) {
      ++faces_at[undirected(t[k], t[(k + 1) % 3])];
      used[t[k]] = 1;
    }
  std::vector<Edge> boundary;
  for (const auto& [e, n] : faces_at)
    if (n == 1) boundary.push_back(e);
  int vertices = 0;
  for (char u : used) vertices += u;
  const int euler = vertices - static_cast<int>(faces_at.size()) + surface.num_faces();
  const int loops = edge_pieces(surface.num_vertices(), boundary);
  std::string out;
  const auto add = [&](const std::string& what) { out += (out.empty() ? "" : "; ") + what; };
  if (!quads.manifold())
    add("not manifold (" + std::to_string(quads.non_manifold_edges) + " edges, " +
        std::to_string(quads.non_manifold_vertices) + " vertices)");
  if (quads.euler_characteristic != euler)
    add("Euler characteristic " + std::to_string(quads.euler_characteristic) + ", the surface's " +
        std::to_string(euler));
  if (quads.border_loops != loops)
    add(std::to_string(quads.border_loops) + " border loops, the surface has " +
        std::to_string(loops));
  return out;
}

}  // namespace bimdf
