// The standalone layout pipeline: field, motorcycle graph, cut, patches (generate.hpp).
#include "bimdf/layout/generate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "layout/face_frames.hpp"
#include "layout/feature_flags.hpp"
#include "layout/mesh_cutting.hpp"
#include "layout/patches.hpp"
#include "layout/seamless.hpp"
#include "layout/singularity_pairs.hpp"
#include "layout/surface_topology.hpp"
#include "layout/trace_selection.hpp"
#include "layout/tracing.hpp"

namespace bimdf::layout {
namespace {

std::pair<int, int> edge_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Per vertex of the cut mesh: the input edge it was inserted on, or −1 (an input vertex, or a
// point inside a face).
std::vector<int> inserted_on_edge(const SurfaceTopology& input, const CutMesh& cut) {
  const TriangleMesh& in = input.mesh();
  const int V0 = in.num_vertices();
  std::vector<int> face_of(cut.mesh.num_vertices(), -1);
  for (int f = 0; f < cut.mesh.num_faces(); ++f)
    for (int v : cut.mesh.faces[f]) face_of[v] = cut.parent_face[f];
  std::vector<int> edge(cut.mesh.num_vertices(), -1);
  for (int v = V0; v < cut.mesh.num_vertices(); ++v) {
    const int f = face_of[v];
    if (f < 0) continue;
    const detail::Vec3& x = cut.mesh.vertices[v];
    // The edge of f the point is closest to, if it is on it (relative distance 1e-9).
    double best = std::numeric_limits<double>::infinity();
    int best_h = -1;
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i;
      const detail::Vec3 &a = in.vertices[input.from(h)], &b = in.vertices[input.to(h)];
      const detail::Vec3 ab = detail::sub(b, a);
      const double len = detail::norm(ab);
      const double d = detail::norm(detail::cross(ab, detail::sub(x, a))) / (len * len);
      if (d < best) best = d, best_h = h;
    }
    if (best < 1e-9) edge[v] = input.edge(best_h);
  }
  return edge;
}

// Two seeds in every patch that is not a disk: the patch's input vertex farthest (in edges)
// from its boundary, then the one farthest from the boundary and the first seed. Only input
// vertices (the cut mesh numbers them first) that are regular and inside the patch qualify.
std::vector<int> seeds_for_non_disks(const SurfaceTopology& cut, const Patches& patches,
                                     int input_vertices, const std::vector<int>& quarter_index) {
  const TriangleMesh& m = cut.mesh();
  const int F = m.num_faces();
  std::vector<int> seeds;
  std::vector<std::vector<int>> faces_of(patches.problem.size());
  for (int f = 0; f < F; ++f)
    if (!patches.problem[patches.face_patch[f]].empty())
      faces_of[patches.face_patch[f]].push_back(f);
  for (size_t p = 0; p < faces_of.size(); ++p) {
    if (faces_of[p].empty()) continue;
    // Vertices of the patch, and which lie on its boundary (an edge whose other side is another
    // patch, or the mesh border).
    std::vector<int> verts, frontier;
    std::vector<std::vector<int>> neighbours;
    std::map<int, int> index;
    for (int f : faces_of[p])
      for (int v : m.faces[f])
        if (index.emplace(v, static_cast<int>(verts.size())).second) verts.push_back(v);
    neighbours.resize(verts.size());
    std::vector<bool> boundary(verts.size(), false);
    for (int f : faces_of[p])
      for (int i = 0; i < 3; ++i) {
        const int h = 3 * f + i, g = cut.opposite(h);
        const int a = index[cut.from(h)], b = index[cut.to(h)];
        neighbours[a].push_back(b);
        if (g < 0 || patches.face_patch[g / 3] != static_cast<int>(p))
          boundary[a] = boundary[b] = true;
      }
    for (int round = 0; round < 2; ++round) {
      std::vector<int> d(verts.size(), -1), queue;
      for (size_t i = 0; i < verts.size(); ++i)
        if (boundary[i] || (round == 1 && !seeds.empty() && verts[i] == seeds.back()))
          d[i] = 0, queue.push_back(static_cast<int>(i));
      for (size_t q = 0; q < queue.size(); ++q)
        for (int n : neighbours[queue[q]])
          if (d[n] < 0) d[n] = d[queue[q]] + 1, queue.push_back(n);
      int best = -1;
      for (size_t i = 0; i < verts.size(); ++i)
        if (verts[i] < input_vertices && quarter_index[verts[i]] == 0 && d[i] >= 1 &&
            (best < 0 || d[i] > d[best]))
          best = static_cast<int>(i);
      if (best < 0) {
        // A ring one triangle wide (e.g. between two feature loops): seeds on its boundary,
        // traced across it (tracing.cpp), the second as far from the first as the ring goes.
        std::vector<int> from_first(verts.size(), -1), order;
        for (size_t i = 0; i < verts.size() && order.empty(); ++i)
          if (verts[i] < input_vertices && quarter_index[verts[i]] == 0)
            from_first[i] = 0, order.push_back(static_cast<int>(i));
        for (size_t q = 0; q < order.size(); ++q)
          for (int n : neighbours[order[q]])
            if (from_first[n] < 0) from_first[n] = from_first[order[q]] + 1, order.push_back(n);
        int far = -1;
        for (int i : order)
          if (verts[i] < input_vertices && quarter_index[verts[i]] == 0 &&
              (far < 0 || from_first[i] > from_first[far]))
            far = i;
        if (!order.empty()) seeds.push_back(verts[order[0]]);
        if (far >= 0 && far != order[0]) seeds.push_back(verts[far]);
        break;
      }
      seeds.push_back(verts[best]);
    }
  }
  return seeds;
}

// The field's quarter turns around each vertex of the cut mesh (inserted vertices are
// regular), and the T-junctions: a vertex where exactly one trace ends, no trace starts, and
// the ending trace is not all that passes (another trace goes through, or a curve).
CornerHints corner_hints(const SurfaceTopology& cut_top, const CutMesh& cut,
                         const std::map<std::pair<int, int>, int>& edge_of,
                         const std::vector<Trace>& traces, const std::vector<int>& quarter_index,
                         int input_vertices) {
  const int V = cut.mesh.num_vertices();
  CornerHints hints;
  hints.field_quarters.resize(V);
  for (int v = 0; v < V; ++v)
    hints.field_quarters[v] =
        (cut_top.on_border(v) ? 2 : 4) - (v < input_vertices ? quarter_index[v] : 0);
  hints.ending_edge.assign(V, -1);
  std::vector<int> ends(V, 0), starts(V, 0), last(V, -1);
  for (size_t i = 0; i < traces.size() && i < cut.polyline_vertices.size(); ++i) {
    const std::vector<int>& chain = cut.polyline_vertices[i];
    if (chain.size() < 2) continue;
    ++starts[chain.front()];
    ++ends[chain.back()];
    last[chain.back()] = edge_of.at(edge_key(chain[chain.size() - 2], chain.back()));
  }
  for (int v = 0; v < V; ++v)
    if (ends[v] == 1 && starts[v] == 0) hints.ending_edge[v] = last[v];
  return hints;
}

// Per half-edge of the cut mesh: its face's angle at its origin in the parameter plane, in
// quarter turns (CornerHints::parameter_quarters); negative in a folded face.
std::vector<double> parameter_quarters(const SurfaceTopology& cut_top, const CutMesh& cut,
                                       const SeamlessMap& map) {
  const TriangleMesh& m = cut.mesh;
  std::vector<double> out(3 * m.num_faces());
  for (int h = 0; h < 3 * m.num_faces(); ++h) {
    const auto& g = map.gradient[cut.parent_face[h / 3]];
    const detail::Vec3 origin = m.vertices[cut_top.from(h)];
    const detail::Vec3 x = detail::sub(m.vertices[cut_top.to(h)], origin);
    const detail::Vec3 y = detail::sub(m.vertices[cut_top.from(SurfaceTopology::prev(h))], origin);
    const double xu = detail::dot(g[0], x), xv = detail::dot(g[1], x);
    const double yu = detail::dot(g[0], y), yv = detail::dot(g[1], y);
    out[h] = std::atan2(xu * yv - xv * yu, xu * yu + xv * yv) / (M_PI / 2);
  }
  return out;
}

// A layout that cannot be made because a patch cannot be a chart.
struct NotCharts : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The cross field and the seamless map depend on the mesh, the features and
// LayoutOptions::field only — not on the pairing radius, nor on whether the map is traced
// despite its folds: one generate_layout call computes each once (when first needed) and every
// radius and retry takes them from here (blade: 7.5 s of field and map per layout).
struct FieldAndMap {
  std::optional<CrossField> field;
  FieldIndices indices;
  CancelledPairs cancelled;        // close pairs, left out of the parametrization
  FieldIndices cancelled_indices;  // the field's indices without them
  double field_s = 0;
  std::optional<SeamlessMap> map;
  double map_s = 0;
};

// One attempt, tracing as `options` says (with fewer lines where `spare`).
GeneratedLayout generate_layout_once(const TriangleMesh& mesh, const Features& features,
                                     const LayoutOptions& options, double pairing_radius,
                                     bool spare,
                                     const std::function<void(const LayoutProgress&)>& progress,
                                     FieldAndMap& computed) {
  const auto start = std::chrono::steady_clock::now();
  const auto report = [&](const char* stage, const std::string& detail) {
    if (progress) progress({since(start), stage, detail});
  };
  GeneratedLayout out;
  out.pairing_radius = pairing_radius;
  out.spare = spare;
  const SurfaceTopology top(mesh);
  const FaceFrames frames(mesh);
  const std::vector<bool> curve = feature_edge_flags(top, features);
  const std::vector<bool> curve_vertex = vertices_of_edges(top, curve);

  auto t = std::chrono::steady_clock::now();
  if (!computed.field) {
    computed.field = compute_cross_field(mesh, features, options.field);
    computed.indices = field_indices(mesh, *computed.field);
    computed.field_s = since(t);
  }
  const CrossField& field = *computed.field;
  out.indices = computed.indices;
  out.time_field_s = computed.field_s;
  {
    int inside = 0;
    for (const auto& s : out.indices.singularities) inside += !s.on_border;
    report("field", std::to_string(inside) + " singularities inside, index sum " +
                        std::to_string(out.indices.quarter_index_sum) + "/4");
  }
  // The singularities traces start from: the field's, or the map's cones where it is traced.
  const FieldIndices* singular = &out.indices;

  FaceWays ways;
  SeamlessMap map;  // empty unless traced along
  if (options.trace_parametrization) {
    t = std::chrono::steady_clock::now();
    if (!computed.map) {
      computed.cancelled = cancel_close_pairs(top, computed.indices, curve_vertex,
                                              options.cancel_pair_radius * top.mean_edge_length());
      computed.cancelled_indices =
          computed.cancelled.pairs.empty()
              ? computed.indices
              : field_indices(mesh, field, computed.cancelled.matching_offset);
      SeamlessOptions seamless;
      seamless.matching_offset = computed.cancelled.matching_offset;
      computed.map = seamless_parametrization(top, frames, field, curve, seamless);
      computed.map_s = since(t);
    }
    map = *computed.map;
    out.folded_faces = map.folded_faces;
    out.time_parametrization_s = computed.map_s;
    std::ostringstream detail;
    detail << map.folded_faces << " folded faces, mean distortion " << map.mean_distortion;
    if (map.folded_faces > options.max_folded_fraction * mesh.num_faces()) {
      map = SeamlessMap{};
      detail << ": too many folds, tracing the field's streamlines instead";
    } else {
      ways = face_ways(frames, map.iso_direction);
      out.traced_parametrization = true;
      out.cancelled_pairs = static_cast<int>(computed.cancelled.pairs.size());
      singular = &computed.cancelled_indices;
      detail << "; " << out.cancelled_pairs << " close singularity pairs left out";
    }
    report("parametrization", detail.str());
  }
  if (!out.traced_parametrization) {
    std::vector<std::array<detail::Vec3, 2>> cross(mesh.num_faces());
    for (int f = 0; f < mesh.num_faces(); ++f)
      cross[f] = {field.direction[f], detail::cross(frames.normal[f], field.direction[f])};
    ways = face_ways(frames, cross);
  }
  const double snap = out.traced_parametrization ? options.snap : options.streamline_snap;
  const double shallow_deg =
      out.traced_parametrization ? options.shallow_angle_deg : options.streamline_shallow_angle_deg;

  const double short_length = options.short_to_curve_edges * top.mean_edge_length();
  const std::vector<double> to_curve =
      spare ? distance_to_curves(top, curve_vertex) : std::vector<double>{};
  TraceOptions trace;
  trace.snap = snap;
  trace.max_length = options.max_trace_length;
  trace.approach_radius = pairing_radius;
  CutMesh cut;
  Patches patches;
  std::vector<std::array<int, 2>> sharp_pieces;
  // Separatrices may leave a patch that is not a disk (around a handle, between two border
  // loops, a whole torus): such a patch gets two seeds — regular vertices traced in all four
  // directions — and everything is traced again, up to `max_seed_rounds` times.
  for (int round = 0;; ++round) {
    t = std::chrono::steady_clock::now();
    MotorcycleGraph graph;
    // Separatrices that make poor patch borders (trace_selection.hpp: shallow ends, short runs
    // to a curve) are not traced, and everything is traced again without them (which may let
    // other separatrices run on), up to `max_ban_rounds` times.
    for (int ban_round = 0;; ++ban_round) {
      graph = trace_motorcycle_graph(top, frames, ways, singular->quarter_index, curve, trace);
      if (ban_round == options.max_ban_rounds) break;
      size_t before = trace.banned.size();
      ban_shallow_ends(graph.traces, shallow_deg * M_PI / 180,
                       std::max(shallow_deg, options.curve_shallow_angle_deg) * M_PI / 180,
                       trace.seeds, trace.banned);
      ban_short_to_curve(graph.traces, curve_vertex, trace.seeds, short_length, trace.banned);
      ban_seed_loops(graph.traces, curve_vertex, trace.seeds, short_length, trace.banned);
      if (spare)
        ban_along_curves(top, graph.traces, to_curve, trace.seeds,
                         options.beside_curve_edges * top.mean_edge_length(),
                         options.beside_curve_length_edges * top.mean_edge_length(), trace.banned);
      if (trace.banned.size() == before) break;
    }
    out.banned_traces = static_cast<int>(trace.banned.size());
    out.trace_starts = graph.starts;
    out.removed_traces = drop_dangling(graph.traces);
    out.traces = static_cast<int>(graph.traces.size());
    out.time_trace_s = since(t);
    report("traced", std::to_string(out.traces) + " separatrices from " +
                         std::to_string(out.trace_starts) + " vertices, " +
                         std::to_string(out.banned_traces) +
                         " not traced (shallow or short ends), " +
                         std::to_string(out.removed_traces) + " removed");

    t = std::chrono::steady_clock::now();
    std::vector<std::vector<SurfacePoint>> polylines;
    for (const Trace& tr : graph.traces) polylines.push_back(tr.points);
    cut = cut_along_polylines(top, polylines);
    out.time_cut_s = since(t);
    report("cut", std::to_string(cut.mesh.num_faces()) + " triangles (" +
                      std::to_string(cut.mesh.num_faces() - mesh.num_faces()) + " more)");

    t = std::chrono::steady_clock::now();
    const SurfaceTopology cut_top(cut.mesh);
    // Patch borders: every trace edge, and the pieces of every input curve edge.
    std::vector<bool> border(cut_top.num_edges(), false);
    std::map<std::pair<int, int>, int> edge_of;
    for (int e = 0; e < cut_top.num_edges(); ++e) {
      const int h = cut_top.edge_half_edge(e);
      edge_of[edge_key(cut_top.from(h), cut_top.to(h))] = e;
    }
    for (const auto& chain : cut.polyline_vertices)
      for (size_t i = 0; i + 1 < chain.size(); ++i) {
        const auto it = edge_of.find(edge_key(chain[i], chain[i + 1]));
        if (it == edge_of.end())
          throw std::logic_error("layout: a cut polyline step is not a mesh edge");
        border[it->second] = true;
      }
    const std::vector<int> on_edge = inserted_on_edge(top, cut);
    const int V0 = mesh.num_vertices();
    std::map<std::pair<int, int>, int> input_edge_of;
    for (int e = 0; e < top.num_edges(); ++e) {
      const int h = top.edge_half_edge(e);
      input_edge_of[edge_key(top.from(h), top.to(h))] = e;
    }
    sharp_pieces.clear();
    for (int e = 0; e < cut_top.num_edges(); ++e) {
      const int h = cut_top.edge_half_edge(e), a = cut_top.from(h), b = cut_top.to(h);
      int input = -1;
      if (a < V0 && b < V0) {
        const auto it = input_edge_of.find(edge_key(a, b));
        if (it != input_edge_of.end()) input = it->second;
      } else {
        const int on = on_edge[a >= V0 ? a : b];
        const int other = a >= V0 ? b : a;
        if (on >= 0) {
          const int g = top.edge_half_edge(on);
          if ((other < V0 && (other == top.from(g) || other == top.to(g))) ||
              (other >= V0 && on_edge[other] == on))
            input = on;
        }
      }
      if (input < 0 || !curve[input]) continue;
      border[e] = true;
      if (top.opposite(top.edge_half_edge(input)) >= 0) sharp_pieces.push_back({a, b});
    }
    CornerHints hints = corner_hints(cut_top, cut, edge_of, graph.traces, singular->quarter_index,
                                     mesh.num_vertices());
    if (!map.gradient.empty()) hints.parameter_quarters = parameter_quarters(cut_top, cut, map);
    if (spare) hints.flat_share = options.flat_sector_quarters;
    patches = label_patches(cut_top, border, hints);
    const std::vector<int> seeds =
        seeds_for_non_disks(cut_top, patches, mesh.num_vertices(), singular->quarter_index);
    if (seeds.empty() || round == options.max_seed_rounds) {
      // What seeds could not cut open (a ring with no regular input vertex in it) is cut
      // across along mesh edges.
      for (int pass = 0; pass < options.max_cut_across; ++pass) {
        const int made = cut_across_non_disks(cut_top, patches, border, hints);
        if (made == 0) break;
        out.cuts_across += made;
        patches = label_patches(cut_top, border, hints);
      }
      if (out.cuts_across > 0)
        report("cut across", std::to_string(out.cuts_across) +
                                 " paths along mesh edges cut what seeds could not");
      {
        int bad = 0, first = -1;
        std::map<std::string, int> kinds;
        for (size_t p = 0; p < patches.problem.size(); ++p)
          if (!patches.problem[p].empty()) {
            if (bad++ == 0) first = static_cast<int>(p);
            ++kinds[patches.problem[p]];
          }
        if (bad > 0) {
          std::string list;
          for (const auto& [what, n] : kinds)
            list += (list.empty() ? "" : ", ") + std::to_string(n) + " × " + what;
          throw NotCharts(std::to_string(bad) + " of " + std::to_string(patches.problem.size()) +
                          " patches cannot be charts (" + list + "; first: patch " +
                          std::to_string(first) + ")");
        }
      }
      break;
    }
    trace.seeds.insert(trace.seeds.end(), seeds.begin(), seeds.end());
    out.seeds = static_cast<int>(trace.seeds.size());
    report("seeds", std::to_string(seeds.size()) + " seeds for patches that are not disks");
  }
  out.layout = quant::build_layout(cut.mesh, patches.face_patch, patches.corners, "<layout>");
  out.layout.feature_edges = std::move(sharp_pieces);
  out.layout.feature_corners = features.corners;  // input vertices keep their ids
  // Density follows the input mesh, not the cut one (cutting adds short edges).
  {
    double sum = 0;
    for (int f = 0; f < mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k)
        sum += detail::norm(detail::sub(mesh.vertices[mesh.faces[f][(k + 1) % 3]],
                                        mesh.vertices[mesh.faces[f][k]]));
    out.layout.average_edge_length = mesh.num_faces() > 0 ? sum / (3 * mesh.num_faces()) : 0;
  }
  out.time_patches_s = since(t);
  out.adjusted_patches = patches.adjusted;
  report("patches", std::to_string(out.layout.charts.size()) + " patches (" +
                        std::to_string(patches.adjusted) + " with corners adjusted)");
  return out;
}

// One pairing radius: the ways of tracing in turn until one gives a layout the check takes.
std::pair<GeneratedLayout, LayoutVerdict> generate_with_retries(
    const TriangleMesh& mesh, const Features& features, const LayoutOptions& options,
    double pairing_radius, bool spare, const std::function<void(const LayoutProgress&)>& report,
    const LayoutCheck& check, int& checks, double& earlier_s,
    std::chrono::steady_clock::time_point start, FieldAndMap& computed) {
  // The two ways of tracing fail in different places (camel: a ring around two adjacent
  // singularities that no seed's trace cuts open): where the first fails, the parametrization
  // is traced despite its folds, then the field's streamlines.
  std::vector<LayoutOptions> attempts{options};
  if (options.trace_parametrization && options.try_other_ways) {
    attempts.push_back(options);
    attempts.back().max_folded_fraction = 1;
    attempts.push_back(options);
    attempts.back().trace_parametrization = false;
  }
  for (size_t i = 0;; ++i) {
    std::string wrong;
    try {
      GeneratedLayout out = generate_layout_once(mesh, features, attempts[i], pairing_radius, spare,
                                                 report, computed);
      out.attempts = static_cast<int>(i) + 1;
      LayoutVerdict verdict;
      if (check) {
        verdict = check(out.layout);
        out.checked = checks++;
      }
      if (verdict.wrong.empty()) return {std::move(out), verdict};
      wrong = verdict.wrong;
      if (i + 1 == attempts.size())
        throw std::runtime_error("no way of tracing gave a layout that passes: " + wrong);
    } catch (const NotCharts& e) {
      if (i + 1 == attempts.size()) throw;
      wrong = e.what();
    }
    earlier_s = since(start);
    report({0, "retry", wrong + "; tracing another way"});
  }
}

}  // namespace

GeneratedLayout generate_layout(const TriangleMesh& mesh, const Features& features,
                                const LayoutOptions& options,
                                const std::function<void(const LayoutProgress&)>& progress,
                                const LayoutCheck& check) {
  const auto valid = [](const std::vector<double>& radii) {
    return std::all_of(radii.begin(), radii.end(),
                       [](double r) { return r >= 0 && std::isfinite(r); });
  };
  if (options.pairing_radii.empty() || !valid(options.pairing_radii))
    throw std::invalid_argument(
        "layout: pairing radii must be a non-empty list of finite values >= 0");
  if (!valid(options.spare_pairing_radii))
    throw std::invalid_argument("layout: spare pairing radii must be finite values >= 0");
  const auto start = std::chrono::steady_clock::now();
  double earlier_s = 0;  // spent on earlier layouts
  const auto report = [&](const LayoutProgress& p) {
    if (progress) progress({earlier_s + p.elapsed_s, p.stage, p.detail});
  };
  // (pairing radius, spare) per layout to make: without a check, only the first.
  std::vector<std::pair<double, bool>> candidates;
  for (double r : options.pairing_radii) candidates.push_back({r, false});
  if (check)
    for (double r : options.spare_pairing_radii) candidates.push_back({r, true});
  else
    candidates.resize(1);
  std::optional<GeneratedLayout> best;
  double best_badness = 0;
  std::exception_ptr first_error;
  int checks = 0, taken = 0;
  FieldAndMap computed;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const auto [radius, spare] = candidates[k];
    if (k > 0) {
      earlier_s = since(start);
      std::ostringstream detail;
      detail << "tracing again with pairing radius " << radius << (spare ? ", fewer lines" : "")
             << " (" << k + 1 << " of " << candidates.size() << ")";
      report({0, "pairing", detail.str()});
    }
    try {
      auto [out, verdict] = generate_with_retries(mesh, features, options, radius, spare, report,
                                                  check, checks, earlier_s, start, computed);
      ++taken;
      if (!best || verdict.badness < best_badness)
        best = std::move(out), best_badness = verdict.badness;
    } catch (const std::runtime_error&) {
      if (!first_error) first_error = std::current_exception();
    }
  }
  if (!best) std::rethrow_exception(first_error);
  best->candidates = taken;
  return std::move(*best);
}

QuadwildFiles to_quadwild_files(const quant::Layout& layout) {
  QuadwildFiles files;
  const TriangleMesh& m = layout.mesh;
  std::ostringstream obj, patch, corners, feature, c_feature;
  obj.precision(std::numeric_limits<double>::max_digits10);
  for (const auto& v : m.vertices) obj << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  for (const auto& f : m.faces)
    obj << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  patch << m.num_faces() << '\n';
  for (int c : layout.face_chart) patch << c << '\n';
  corners << layout.charts.size() << '\n';
  for (const quant::Chart& c : layout.charts) {
    corners << c.corners.size() << '\n';
    for (int v : c.corners) corners << v << '\n';
  }
  // Feature edges as (face, local edge): the first face walking the pair either way.
  std::map<std::pair<int, int>, std::pair<int, int>> face_edge;
  for (int f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      face_edge.emplace(edge_key(m.faces[f][k], m.faces[f][(k + 1) % 3]), std::pair{f, k});
  std::vector<std::pair<int, int>> listed;
  for (const auto& e : layout.feature_edges) {
    const auto it = face_edge.find(edge_key(e[0], e[1]));
    if (it != face_edge.end()) listed.push_back(it->second);
  }
  feature << listed.size() << '\n';
  for (const auto& [f, k] : listed) feature << f << ',' << k << '\n';
  c_feature << layout.feature_corners.size() << '\n';
  for (int v : layout.feature_corners) c_feature << v << '\n';
  files.obj = obj.str();
  files.patch = patch.str();
  files.corners = corners.str();
  files.feature = feature.str();
  files.c_feature = c_feature.str();
  return files;
}

}  // namespace bimdf::layout
