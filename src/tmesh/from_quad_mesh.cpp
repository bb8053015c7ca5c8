// trace_tmesh: a quad mesh's motorcycle graph turned into a T-mesh (from_quad_mesh.hpp).
//
// Order of work: topology and features, seeds, both motorcycle graphs; the completion cuts
// (annuli and self-meeting rectangles cut across); then the patches (face components across
// uncut edges, each checked to be a rectangle of the grid — a region that is not is an input
// the layout cannot be built for, reported with its quads); then the T-mesh
// vertices and arcs (maximal chains of cut edges through straight pass-through vertices); then
// the patch sides as half-arc lists; then the non-zero paths; finally validate_tmesh.
#include "bimdf/tmesh/from_quad_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "io/text_scan.hpp"
#include "tmesh/angle_bounded.hpp"
#include "tmesh/motorcycle.hpp"
#include "tmesh/quad_mesh_topology.hpp"

namespace bimdf::tmesh {
namespace {

using detail::QuadMeshTopology;
namespace text = bimdf::detail;  // the house text scanner (io/text_scan.hpp)

// A patch as mesh half-edges: its grid of quads and its four sides (patch on the left).
struct RegionGrid {
  PatchGrid grid;
  std::array<std::vector<int>, 4> sides;  // mesh half-edges per side
};

// The regions of the cut, each a rectangle (in cut_regions' order), or an InputError.
std::vector<RegionGrid> patches_of(const QuadMeshTopology& topo, const std::vector<uint8_t>& cut,
                                   const std::string& source) {
  detail::RegionScratch scratch(topo);
  std::vector<RegionGrid> patches;
  for (const std::vector<int>& faces : detail::cut_regions(topo, cut)) {
    ++scratch.stamp;
    const detail::RegionBorder border = detail::region_border(topo, cut, faces, scratch);
    detail::RegionRectangle r = detail::region_rectangle(topo, cut, faces, border, scratch, source);
    if (r.repeat[0] >= 0) {
      // complete_to_rectangles cuts such regions; reaching here is a bug, but say what it is.
      const int w1 = r.width + 1;
      auto at = [&](int k) {
        return "(" + std::to_string(k % w1) + ", " + std::to_string(k / w1) + ")";
      };
      throw InputError(source, "",
                       detail::region_name(faces) + " do not form a rectangle of the grid: " +
                           "their grid passes through mesh vertex " +
                           std::to_string(r.vertices[r.repeat[0]]) + " twice, at " +
                           at(r.repeat[0]) + " and " + at(r.repeat[1]));
    }
    RegionGrid g;
    g.grid.width = r.width;
    g.grid.height = r.height;
    g.grid.vertices = std::move(r.vertices);
    g.sides = std::move(r.sides);
    patches.push_back(std::move(g));
  }
  return patches;
}

// Where each mesh edge lies on the T-mesh: its arc and the chain position of its first end.
struct EdgeOnArc {
  std::vector<int> arc, pos;
};

// M1 (§4.1.2): one non-zero path per trace that took at least one edge, along the half-arcs
// it ran on from its seed to where it stopped in the motorcycle graph (cylinder cuts
// included), then one per cylinder half-loop (trace −1). Kept separate so that the rule (e.g.
// Lyon et al.'s paths from the extended graph) can be swapped.
//
// Then one per border or feature curve piece: from every seed along each of its border or
// feature edges, straight on along the curve to the next seed. Traces alone do not keep curves
// apart: a mesh whose every edge is a feature (a cube subdivided once, sharp everywhere), or
// a plain grid whose corners emit no trace, has no trace at all, and without these paths every
// arc could be 0.
std::vector<std::vector<int>> curve_chains(const QuadMeshTopology& topo,
                                           const std::vector<uint8_t>& feature,
                                           const std::vector<int>& seeds) {
  std::vector<char> is_seed(topo.num_vertices(), 0);
  for (int s : seeds) is_seed[s] = 1;
  const auto on_curve = [&](int e) { return topo.is_border_edge(e) || feature[e] != 0; };
  std::vector<std::vector<int>> chains;
  for (int s : seeds)
    for (int e0 : topo.vertex_edges(s)) {
      if (!on_curve(e0)) continue;
      std::vector<int> chain{s};
      int at = s, e = e0;
      // A curve continues straight on at every vertex that is not a seed (feature corners
      // and border corners are seeds); a closed curve returns to s.
      while (e >= 0 && on_curve(e)) {
        at = topo.other_vertex(e, at);
        chain.push_back(at);
        if (is_seed[at] || at == s) break;
        e = topo.straight_on(at, e);
      }
      // Each piece is walked from both of its ends (a closed one both ways from its seed):
      // keep one walk.
      const bool first_walk = chain.front() != chain.back()
                                  ? chain.front() < chain.back()
                                  : chain.size() < 3 || chain[1] <= chain[chain.size() - 2];
      if (first_walk) chains.push_back(std::move(chain));
    }
  return chains;
}

// `chains` (mesh-vertex chains along arcs, with the trace each came from: ≥ 0, or −2 for a
// curve piece) and the cylinder half-loops become the T-mesh's non-zero paths.
void add_nonzero_paths(TracedTMesh& out, std::vector<std::vector<int>> chains,
                       std::vector<int> chain_trace) {
  for (const auto& loop : out.cylinder_half_loops) {
    chains.push_back(loop);
    chain_trace.push_back(-1);
  }
  out.nonzero_path_trace = std::move(chain_trace);
  out.tmesh.nonzero_paths = half_arcs_along(out.tmesh, chains);
}

void add_nonzero_paths_per_trace(TracedTMesh& out, const QuadMeshTopology& topo,
                                 const std::vector<uint8_t>& feature) {
  std::vector<std::vector<int>> chains;
  std::vector<int> chain_trace;
  for (size_t t = 0; t < out.trace_vertices.size(); ++t)
    if (out.trace_vertices[t].size() >= 2) {
      chains.push_back(out.trace_vertices[t]);
      chain_trace.push_back(static_cast<int>(t));
    }
  for (auto& chain : curve_chains(topo, feature, out.seeds)) {
    chains.push_back(std::move(chain));
    chain_trace.push_back(-2);
  }
  add_nonzero_paths(out, std::move(chains), std::move(chain_trace));
}

}  // namespace

std::vector<std::vector<int>> half_arcs_along(const TMesh& tmesh,
                                              const std::vector<std::vector<int>>& chains) {
  auto key = [](int a, int b) {
    return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b));
  };
  std::unordered_map<uint64_t, std::pair<int, int>> on_arc;  // edge → (arc, position)
  for (int a = 0; a < tmesh.num_arcs(); ++a) {
    const auto& chain = tmesh.arc_chain[a];
    for (size_t i = 0; i + 1 < chain.size(); ++i)
      on_arc[key(chain[i], chain[i + 1])] = {a, static_cast<int>(i)};
  }
  std::vector<std::vector<int>> paths;
  for (const auto& chain : chains) {
    std::vector<int> path;
    for (size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto it = on_arc.find(key(chain[i], chain[i + 1]));
      if (it == on_arc.end())
        throw std::invalid_argument("half_arcs_along: mesh vertices " + std::to_string(chain[i]) +
                                    " and " + std::to_string(chain[i + 1]) +
                                    " are not joined by an arc's edge");
      const auto [a, pos] = it->second;
      const int h = 2 * a + (tmesh.arc_chain[a][pos] == chain[i] ? 0 : 1);
      if (path.empty() || path.back() != h) path.push_back(h);
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

TracedTMesh trace_tmesh(const QuadMesh& mesh, const TraceOptions& options,
                        const std::string& source) {
  if (!(options.density > 0) || !std::isfinite(options.density))
    throw std::invalid_argument("trace_tmesh: density must be positive and finite");
  const QuadMeshTopology topo(mesh, source);
  if (!mesh.quads.empty() && !(mean_edge_length(mesh) > 0))
    throw InputError(source, "", kCoincidentVertices);
  const int V = topo.num_vertices(), E = topo.num_edges();
  const std::vector<uint8_t> feature = detail::detect_feature_edges(
      mesh, topo, options.sharp_angle_deg, options.feature_edges, source);
  TracedTMesh out;
  out.feature_corners = detail::feature_corners(topo, feature);
  out.seeds = detail::seed_vertices(topo, feature);
  bool any_border = false, any_feature = false;
  for (int e = 0; e < E; ++e) {
    any_border |= topo.is_border_edge(e);
    any_feature |= feature[e] != 0;
    if (feature[e]) out.feature_edges.push_back(topo.edge_vertices(e));
  }
  if (out.seeds.empty() && !any_border && !any_feature)
    throw InputError(source, "", std::string("the mesh has ") + detail::kClosedGridLines);

  // The plain motorcycle graph, or Lyon et al.'s angle-bounded extended one with its own
  // non-zero paths (angle_bounded.hpp).
  const bool angle_bounded = options.max_angle_deg >= 0;
  detail::MotorcycleGraph graph;
  detail::AngleBoundedGraph bounded;
  if (angle_bounded) {
    bounded = detail::trace_angle_bounded(topo, feature, out.seeds, options.max_angle_deg,
                                          options.cross_features);
    graph.traces = bounded.traces;
    graph.cut = bounded.cut;
  } else {
    graph = detail::trace_motorcycle_graph(topo, feature, out.seeds);
  }
  const std::vector<detail::Trace> extended =
      detail::trace_extended_motorcycle_graph(topo, feature, out.seeds);
  out.traces = static_cast<int>(graph.traces.size());
  out.crossings = bounded.crossings;
  if (angle_bounded) out.feature_traces = options.cross_features ? "cross" : "stop";
  for (const auto& t : graph.traces) out.trace_vertices.push_back(t.vertices);
  std::vector<uint8_t> on_extended(E, 0);
  for (const auto& t : extended) {
    out.extended_trace_vertices.push_back(t.vertices);
    for (int e : t.edges) on_extended[e] = 1;
  }
  std::vector<uint8_t> cut = graph.cut;
  detail::CompletionCuts cylinders = detail::complete_to_rectangles(topo, cut, source);
  out.cylinder_cuts = static_cast<int>(cylinders.traces.size());
  out.traces += out.cylinder_cuts;
  for (auto& t : cylinders.traces) {
    for (size_t i = 0; i + 1 < t.size(); ++i) on_extended[topo.find_edge(t[i], t[i + 1])] = 1;
    out.trace_vertices.push_back(t);
    out.extended_trace_vertices.push_back(std::move(t));
  }
  out.cylinder_half_loops = std::move(cylinders.half_loops);
  out.extended_trace_edges =
      static_cast<int>(std::count(on_extended.begin(), on_extended.end(), 1));

  const std::vector<RegionGrid> regions = patches_of(topo, cut, source);

  // T-mesh vertices: seeds, and vertices where the cut edges do not just pass straight on.
  TMesh& tm = out.tmesh;
  std::vector<int> tvertex(V, -1);
  std::vector<uint8_t> is_seed(V, 0);
  for (int s : out.seeds) is_seed[s] = 1;
  for (int v = 0; v < V; ++v) {
    int degree = 0, first = -1, second = -1;
    for (int e : topo.vertex_edges(v))
      if (cut[e]) (degree++ == 0 ? first : second) = e;
    const bool pass = degree == 2 && topo.straight_on(v, first) == second;
    if (is_seed[v] || (degree > 0 && !pass)) {
      tvertex[v] = tm.num_vertices();
      tm.vertices.push_back(mesh.vertices[v]);
      tm.vertex_mesh_vertex.push_back(v);
    }
  }

  // Arcs: from each T-mesh vertex along each cut edge not yet on an arc, through pass-through
  // vertices (whose other cut edge is straight on) to the next T-mesh vertex.
  EdgeOnArc where{std::vector<int>(E, -1), std::vector<int>(E, -1)};
  for (int c = 0; c < tm.num_vertices(); ++c) {
    const int v = tm.vertex_mesh_vertex[c];
    for (int e0 : topo.vertex_edges(v)) {
      if (!cut[e0] || where.arc[e0] >= 0) continue;
      const int a = tm.num_arcs();
      std::vector<int> chain{v};
      bool all_feature = true;
      for (int e = e0, at = v;;) {
        where.arc[e] = a;
        where.pos[e] = static_cast<int>(chain.size()) - 1;
        all_feature &= feature[e] != 0;
        at = topo.other_vertex(e, at);
        chain.push_back(at);
        if (tvertex[at] >= 0) break;
        e = topo.straight_on(at, e);
      }
      if (chain.back() == v)
        throw std::logic_error("trace_tmesh: an arc closes on mesh vertex " + std::to_string(v));
      tm.arc_ends.push_back({c, tvertex[chain.back()]});
      tm.arc_target.push_back(options.density * double(chain.size() - 1));
      tm.arc_feature.push_back(all_feature ? 1 : 0);
      tm.arc_chain.push_back(std::move(chain));
    }
  }
  for (int e = 0; e < E; ++e)
    if (cut[e] && where.arc[e] < 0)
      throw std::logic_error("trace_tmesh: cut edge " + std::to_string(e) + " is on no arc");

  // Patch sides: consecutive mesh half-edges on the same arc make one half-arc; corners are
  // T-mesh vertices, so every arc on a side lies on it whole.
  for (const RegionGrid& r : regions) {
    std::array<std::vector<int>, 4> sides;
    for (int k = 0; k < 4; ++k)
      for (int h : r.sides[k]) {
        const int e = topo.edge(h), a = where.arc[e];
        const int half = 2 * a + (tm.arc_chain[a][where.pos[e]] == topo.tail(h) ? 0 : 1);
        if (sides[k].empty() || sides[k].back() != half) {
          if (tm.vertex_mesh_vertex[tm.half_arc_tail(half)] != topo.tail(h))
            throw std::logic_error("trace_tmesh: an arc crosses a patch corner");
          sides[k].push_back(half);
        }
      }
    tm.patch_sides.push_back(std::move(sides));
    tm.patch_grid.push_back(r.grid);
  }

  if (angle_bounded) {
    std::vector<int> chain_trace = bounded.nonzero_trace;
    for (int& t : chain_trace) t = t == -1 ? -2 : t < -1 ? -3 : t;  // curve / between curves
    add_nonzero_paths(out, bounded.nonzero_chains, std::move(chain_trace));
  } else {
    add_nonzero_paths_per_trace(out, topo, feature);
  }
  validate_tmesh(tm, source);
  return out;
}

std::vector<std::array<int, 2>> read_quad_feature_file(const std::string& path,
                                                       const QuadMesh& mesh) {
  const std::string content = read_text_file(path);
  text::TextScanner in(content, path);
  const int64_t F = mesh.num_quads();
  const text::Token count_token = in.peek();
  const int64_t n = in.expect_int("the feature edge count");
  if (n < 0 || n > 4 * F)
    in.fail(count_token.line, "the feature edge count " + std::to_string(n) +
                                  " is out of range (expected 0.." + std::to_string(4 * F) + ")");
  std::vector<std::array<int, 2>> edges;
  for (int64_t k = 0; k < n; ++k) {
    const std::string what = "feature edge " + std::to_string(k) + " (face,edge)";
    const text::Token t = in.expect(what);
    const size_t comma = t.text.find(',');
    int64_t f = -1, e = -1;
    if (comma == std::string_view::npos || !text::parse_int64(t.text.substr(0, comma), f) ||
        !text::parse_int64(t.text.substr(comma + 1), e))
      in.fail(t.line,
              what + ": expected two integers separated by a comma, found " + text::quote(t.text));
    if (f < 0 || f >= F || e < 0 || e > 3)
      in.fail(t.line, what + ": face " + std::to_string(f) + " edge " + std::to_string(e) +
                          " is out of range (quads 0.." + std::to_string(F - 1) + ", edges 0..3)");
    edges.push_back({mesh.quads[f][e], mesh.quads[f][(e + 1) % 4]});
  }
  const text::Token rest = in.peek();
  if (!rest.text.empty())
    in.fail(rest.line, "unexpected " + text::quote(rest.text) + " after the last feature edge");
  return edges;
}

void write_quad_feature_file(std::ostream& out, const QuadMesh& mesh,
                             const std::vector<std::array<int, 2>>& edges) {
  std::map<std::pair<int, int>, std::pair<int, int>> first;  // edge → (quad, edge index)
  for (int f = 0; f < mesh.num_quads(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.quads[f][k], b = mesh.quads[f][(k + 1) % 4];
      first.emplace(std::pair{std::min(a, b), std::max(a, b)}, std::pair{f, k});
    }
  std::string text = std::to_string(edges.size()) + "\n";
  for (const auto& [a, b] : edges) {
    const auto it = first.find({std::min(a, b), std::max(a, b)});
    if (it == first.end())
      throw std::invalid_argument("write_quad_feature_file: vertices " + std::to_string(a) +
                                  " and " + std::to_string(b) + " are not an edge of the mesh");
    text += std::to_string(it->second.first) + "," + std::to_string(it->second.second) + "\n";
  }
  out << text;
}

}  // namespace bimdf::tmesh
