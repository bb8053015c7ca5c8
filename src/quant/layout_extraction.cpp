// Charts, sides and subsides of a patch layout (layout.hpp), following the boundary walk of
// ../shared/reference/quadwild_modeling.md §1.2: each chart's border half-edges form one loop
// (a disk), split into sides at the chart's corners and into subsides wherever the neighbour
// changes or the neighbour has a corner (a T-junction). Both charts of a shared subside must
// find the same piece; a disagreement means the files are inconsistent and is reported.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <string>

#include "bimdf/error.hpp"
#include "bimdf/quant/layout.hpp"
#include "quant/triangle_connectivity.hpp"

namespace bimdf::quant {
namespace {

// Edge lengths in single precision, as QuadWild computes them (its meshes store float
// coordinates; it sums a subside's edges in double but the average edge length in a float
// running sum, then divides in float). The float sum's rounding error (~1e-6 relative on 10⁴
// faces) shifts every target; reproducing it makes targets bit-identical to the reference
// quantizer's and optima agree to ~1e-8, so results stay comparable.
float distance_single(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const float x = static_cast<float>(a[0]) - static_cast<float>(b[0]);
  const float y = static_cast<float>(a[1]) - static_cast<float>(b[1]);
  const float z = static_cast<float>(a[2]) - static_cast<float>(b[2]);
  return std::sqrt(x * x + y * y + z * z);
}

}  // namespace

Layout build_layout(TriangleMesh mesh, std::vector<int> face_chart,
                    const std::vector<std::vector<int>>& corners, const std::string& source) {
  Layout layout;
  const int F = mesh.num_faces(), V = mesh.num_vertices();
  const int P = static_cast<int>(corners.size());
  if (static_cast<int>(face_chart.size()) != F)
    throw InputError(
        source, "",
        std::to_string(face_chart.size()) + " patch labels for " + std::to_string(F) + " faces");
  for (int f = 0; f < F; ++f)
    if (face_chart[f] < 0 || face_chart[f] >= P)
      throw InputError(source, "",
                       "face " + std::to_string(f) + " has patch " + std::to_string(face_chart[f]) +
                           ", expected 0.." + std::to_string(P - 1));

  {
    std::vector<std::pair<int, int>> conflicts;
    const Connectivity first = connect(mesh, source, &conflicts);
    if (!conflicts.empty()) layout.flipped_faces = orient_coherently(mesh, first, source);
  }
  const Connectivity conn = connect(mesh, source, nullptr);

  float edge_sum = 0;
  for (int h = 0; h < 3 * F; ++h)
    edge_sum +=
        distance_single(mesh.vertices[from_vertex(mesh, h)], mesh.vertices[to_vertex(mesh, h)]);
  layout.average_edge_length = F > 0 ? edge_sum / static_cast<float>(3 * F) : 0;
  // A zero length would make every target length infinite; --edge-length would instead build a
  // mesh of degenerate quads after minutes of smoothing.
  if (F > 0 && !(layout.average_edge_length > 0)) throw InputError(source, "", kCoincidentVertices);

  std::vector<std::vector<int>> corner_charts(V);  // which charts have v as a corner
  for (int c = 0; c < P; ++c)
    for (int v : corners[c]) {
      if (v < 0 || v >= V)
        throw InputError(source, "",
                         "chart " + std::to_string(c) + ": corner vertex " + std::to_string(v) +
                             " is out of range (" + std::to_string(V) + " vertices)");
      if (std::find(corner_charts[v].begin(), corner_charts[v].end(), c) == corner_charts[v].end())
        corner_charts[v].push_back(c);
    }
  auto is_corner = [&](int v, int c) {
    return std::find(corner_charts[v].begin(), corner_charts[v].end(), c) != corner_charts[v].end();
  };
  auto neighbour = [&](int h) {
    return conn.opposite[h] < 0 ? -1 : face_chart[conn.opposite[h] / 3];
  };

  layout.charts.resize(P);
  for (int f = 0; f < F; ++f) layout.charts[face_chart[f]].faces.push_back(f);

  std::vector<int> outgoing(V, -1);  // the chart's border half-edge leaving v
  std::vector<int> subside_of_edge(conn.num_edges, -1);
  std::vector<int> seen_vertex(V, -1);  // for the chart's Euler characteristic
  std::vector<int> expected_neighbour;  // per subside: the chart across it, −1 on the border
  for (int c = 0; c < P; ++c) {
    Chart& chart = layout.charts[c];
    if (chart.empty()) continue;
    const std::string name = "chart " + std::to_string(c);
    std::vector<int> border;
    int chart_vertices = 0;
    for (int f : chart.faces)
      for (int i = 0; i < 3; ++i) {
        const int h = 3 * f + i, v = from_vertex(mesh, h);
        if (seen_vertex[v] != c) seen_vertex[v] = c, ++chart_vertices;
        if (neighbour(h) == c) continue;
        if (outgoing[v] >= 0) {
          for (int b : border) outgoing[from_vertex(mesh, b)] = -1;
          throw InputError(source, "",
                           name + " is not a disk: its boundary passes twice through vertex " +
                               std::to_string(v));
        }
        outgoing[v] = h;
        border.push_back(h);
      }
    auto reset = [&] {
      for (int b : border) outgoing[from_vertex(mesh, b)] = -1;
    };
    const int num_faces = static_cast<int>(chart.faces.size());
    const int chart_edges = (3 * num_faces + static_cast<int>(border.size())) / 2;
    const int euler = chart_vertices - chart_edges + num_faces;
    if (border.empty() || euler != 1) {
      reset();
      throw InputError(
          source, "",
          name + " is not a disk: " +
              (border.empty() ? std::string("it has no boundary")
                              : "Euler characteristic " + std::to_string(euler) + ", expected 1"));
    }
    // One loop through all border half-edges.
    std::vector<int> loop;
    for (int h = border.front();;) {
      loop.push_back(h);
      h = outgoing[to_vertex(mesh, h)];
      if (h < 0 || static_cast<int>(loop.size()) > static_cast<int>(border.size())) break;
      if (h == border.front()) break;
    }
    if (loop.size() != border.size()) {
      reset();
      throw InputError(source, "", name + " is not a disk: its boundary has several loops");
    }
    // Corners off the boundary cannot bound a side. QuadWild's tracer writes a few (camel has
    // one inside chart 61) and its quantizer ignores them; so do we, with a warning.
    std::vector<int> on_boundary;
    for (int v : corners[c]) {
      if (outgoing[v] >= 0) {
        on_boundary.push_back(v);
      } else if (is_corner(v, c)) {  // once, even if listed twice
        layout.warnings.push_back(name + ": corner vertex " + std::to_string(v) +
                                  " is not on the chart's boundary; ignored");
        corner_charts[v].erase(std::find(corner_charts[v].begin(), corner_charts[v].end(), c));
      }
    }
    if (on_boundary.empty()) {
      reset();
      throw InputError(source, "", name + " has no corners on its boundary, expected 3 to 6");
    }
    const auto start = std::find(loop.begin(), loop.end(), outgoing[on_boundary.front()]);
    std::rotate(loop.begin(), start, loop.end());
    reset();

    const int L = static_cast<int>(loop.size());
    int valence = 0;
    for (int h : loop) valence += is_corner(from_vertex(mesh, h), c);
    if (valence < 3 || valence > 6)
      throw InputError(
          source, "",
          name + " has " + std::to_string(valence) + " corners on its boundary, expected 3 to 6");
    for (int i = 0; i < L;) {
      // One piece: from position i up to the next split.
      const int v0 = from_vertex(mesh, loop[i]);
      if (is_corner(v0, c)) {
        chart.corners.push_back(v0);
        chart.sides.emplace_back();
      }
      const int d = neighbour(loop[i]);
      int j = i + 1;
      while (j < L) {
        const int v = from_vertex(mesh, loop[j]);
        if (is_corner(v, c) || neighbour(loop[j]) != d || (d >= 0 && is_corner(v, d))) break;
        ++j;
      }
      const int side = static_cast<int>(chart.sides.size()) - 1;
      std::vector<int> chain;
      double length = 0;
      for (int k = i; k < j; ++k) {
        chain.push_back(from_vertex(mesh, loop[k]));
        length += distance_single(mesh.vertices[from_vertex(mesh, loop[k])],
                                  mesh.vertices[to_vertex(mesh, loop[k])]);
      }
      chain.push_back(to_vertex(mesh, loop[j - 1]));
      const int existing = subside_of_edge[conn.edge[loop[i]]];
      int s = existing;
      if (existing < 0) {
        s = static_cast<int>(layout.subsides.size());
        Subside sub;
        sub.charts = {c, -1};
        sub.sides = {side, -1};
        sub.vertices = chain;
        sub.length = length;
        layout.subsides.push_back(std::move(sub));
        expected_neighbour.push_back(d);
        for (int k = i; k < j; ++k) subside_of_edge[conn.edge[loop[k]]] = s;
      } else {
        Subside& sub = layout.subsides[s];
        std::vector<int> reversed(chain.rbegin(), chain.rend());
        if (sub.charts[0] != d || sub.charts[1] >= 0 || sub.vertices != reversed)
          throw InputError(source, "",
                           "charts " + std::to_string(c) + " and " + std::to_string(d) +
                               " split their shared boundary differently near vertex " +
                               std::to_string(v0) +
                               " (a corner or T-junction is missing "
                               "from one of them)");
        sub.charts[1] = c;
        sub.sides[1] = side;
      }
      chart.sides.back().subsides.push_back(s);
      chart.sides.back().reversed.push_back(existing >= 0);
      chart.sides.back().length += length;
      chart.subsides.push_back(s);
      i = j;
    }
  }
  // A subside whose first chart saw a neighbour must have been walked by it too; otherwise the
  // neighbour's boundary missed it, which only inconsistent data can cause.
  for (size_t s = 0; s < layout.subsides.size(); ++s)
    if (expected_neighbour[s] >= 0 && layout.subsides[s].charts[1] < 0)
      throw InputError(source, "",
                       "chart " + std::to_string(expected_neighbour[s]) +
                           " does not walk the boundary it shares with chart " +
                           std::to_string(layout.subsides[s].charts[0]) + " at vertex " +
                           std::to_string(layout.subsides[s].vertices.front()));
  layout.mesh = std::move(mesh);
  layout.face_chart = std::move(face_chart);
  return layout;
}

}  // namespace bimdf::quant
