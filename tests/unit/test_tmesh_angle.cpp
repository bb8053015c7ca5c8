// The angle-bounded extended motorcycle graph and its non-zero paths (tmesh/angle_bounded.hpp):
// termination, independence of the seeds' order, rectangles, straight non-zero chains,
// monotonicity in the angle, and small cases worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "tmesh/angle_bounded.hpp"
#include "tmesh/motorcycle.hpp"
#include "tmesh/quad_mesh_topology.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh::detail {
namespace {

// A mesh ready for tracing: topology, feature flags and seeds.
struct Prepared {
  QuadMesh mesh;
  std::optional<QuadMeshTopology> topo;
  std::vector<uint8_t> feature;
  std::vector<int> seeds;
};

Prepared prepare(QuadMesh mesh, double sharp_angle_deg = 35) {
  Prepared p;
  p.mesh = std::move(mesh);
  p.topo.emplace(p.mesh, "test");
  p.feature = detect_feature_edges(p.mesh, *p.topo, sharp_angle_deg, {}, "test");
  p.seeds = seed_vertices(*p.topo, p.feature);
  return p;
}

AngleBoundedGraph trace(const Prepared& p, double angle) {
  return trace_angle_bounded(*p.topo, p.feature, p.seeds, angle);
}

// The unit cells (x, y), 0 ≤ x < w, 0 ≤ y < h, outside every removed block [x0, x1) × [y0, y1),
// as a planar mesh; `vertex` maps (x, y) to its id.
struct Blocks {
  QuadMesh mesh;
  std::map<std::pair<int, int>, int> vertex;
  int at(int x, int y) const { return vertex.at({x, y}); }
};
Blocks grid_without(int w, int h, const std::vector<std::array<int, 4>>& removed) {
  Blocks b;
  auto id = [&](int x, int y) {
    auto [it, added] = b.vertex.emplace(std::pair{x, y}, b.mesh.num_vertices());
    if (added) b.mesh.vertices.push_back({double(x), double(y), 0});
    return it->second;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool gone = false;
      for (const auto& r : removed) gone |= x >= r[0] && x < r[1] && y >= r[2] && y < r[3];
      if (!gone) b.mesh.quads.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return b;
}

// Re-splits the hexagon of quads f and g (sharing an edge) along another diagonal: the ends of
// the shared edge lose a quad (valence 4 → 3), the two opposite hexagon vertices gain one (5).
void rotate_edge(QuadMesh& mesh, int f, int g) {
  auto& a = mesh.quads[f];
  auto& b = mesh.quads[g];
  for (int r = 0; r < 4; ++r) {
    for (int s = 0; s < 4; ++s)
      if (a[3] == b[0] && a[0] == b[3]) {
        const std::array<int, 6> hex{a[0], a[1], a[2], a[3], b[1], b[2]};
        a = {hex[1], hex[2], hex[3], hex[4]};
        b = {hex[4], hex[5], hex[0], hex[1]};
        return;
      } else {
        std::rotate(b.begin(), b.begin() + 1, b.end());
      }
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  FAIL() << "quads " << f << " and " << g << " share no edge";
}

int traced_edges(const AngleBoundedGraph& g) {
  std::set<int> edges;
  for (const auto& t : g.traces) edges.insert(t.edges.begin(), t.edges.end());
  return static_cast<int>(edges.size());
}

// Every property that holds for any mesh; a failure description, empty when all hold.
std::string check_graph(const Prepared& p, const AngleBoundedGraph& g) {
  const QuadMeshTopology& topo = *p.topo;
  const int E = topo.num_edges();
  std::set<int> seeds(p.seeds.begin(), p.seeds.end());
  std::vector<uint8_t> cut(E, 0);
  for (int e = 0; e < E; ++e) cut[e] = topo.is_border_edge(e) || p.feature[e];
  size_t moves = 0;
  for (size_t t = 0; t < g.traces.size(); ++t) {
    const Trace& tr = g.traces[t];
    const std::string name = "trace " + std::to_string(t);
    if (tr.edges.empty() || tr.vertices.size() != tr.edges.size() + 1) return name + ": shape";
    if (!seeds.count(tr.vertices[0]) || tr.seed != tr.vertices[0]) return name + ": no seed";
    for (size_t k = 0; k < tr.edges.size(); ++k) {
      if (topo.find_edge(tr.vertices[k], tr.vertices[k + 1]) != tr.edges[k])
        return name + ": edge " + std::to_string(k);
      if (k > 0 && topo.straight_on(tr.vertices[k], tr.edges[k - 1]) != tr.edges[k])
        return name + ": turns at " + std::to_string(tr.vertices[k]);
      cut[tr.edges[k]] = 1;
    }
    moves += tr.edges.size();
  }
  if (moves > 2 * size_t(E)) return "more moves than directed edges";
  if (cut != g.cut) return "cut is not traces ∪ border ∪ features";
  // Where a cut line only passes straight on (2 cut edges, straight) is no T-mesh vertex;
  // a single cut edge or two at a right angle would be a dead end or an L.
  auto cut_at = [&](int v) {
    std::vector<int> es;
    for (int e : topo.vertex_edges(v))
      if (g.cut[e]) es.push_back(e);
    return es;
  };
  auto passes = [&](int v) {
    const auto es = cut_at(v);
    return es.size() == 2 && topo.straight_on(v, es[0]) == es[1];
  };
  for (size_t t = 0; t < g.traces.size(); ++t) {
    const int v = g.traces[t].vertices.back();
    const auto es = cut_at(v);
    if (!seeds.count(v) &&
        (es.size() < 2 || (es.size() == 2 && !passes(v) && !topo.is_border_vertex(v))))
      return "trace " + std::to_string(t) + " ends in a dead end or L at " + std::to_string(v);
  }

  // Raw regions: rectangles, or annuli left for complete_to_rectangles; then rectangles.
  RegionScratch scratch(topo);
  for (const auto& faces : cut_regions(topo, g.cut)) {
    ++scratch.stamp;
    const RegionBorder b = region_border(topo, g.cut, faces, scratch);
    const bool rectangle = b.loops.size() == 1 && b.corners == 4 && b.reflex == 0;
    const bool annulus = b.loops.size() >= 2 && b.corners == 0 && b.reflex == 0;
    if (!rectangle && !annulus)
      return region_name(faces) + ": " + std::to_string(b.loops.size()) + " loops, " +
             std::to_string(b.corners) + " corners, " + std::to_string(b.reflex) + " reflex";
  }
  std::vector<uint8_t> completed = g.cut;
  try {
    complete_to_rectangles(topo, completed, "test");
    for (const auto& faces : cut_regions(topo, completed)) {
      ++scratch.stamp;
      const RegionBorder b = region_border(topo, completed, faces, scratch);
      const RegionRectangle r = region_rectangle(topo, completed, faces, b, scratch, "test");
      if (r.repeat[0] >= 0) return region_name(faces) + ": meets itself after completion";
    }
  } catch (const std::exception& e) {
    return std::string("completion: ") + e.what();
  }

  // Non-zero chains: straight chains of cut edges from a seed — or, for a piece of trace t
  // between two curves (nonzero_trace −2 − t), from a curve to the next along t — none
  // implied by another.
  if (g.nonzero_chains.size() != g.nonzero_trace.size()) return "nonzero_trace size";
  if (!std::is_sorted(g.nonzero_chains.begin(), g.nonzero_chains.end())) return "not sorted";
  std::vector<uint8_t> on_curve(topo.num_vertices(), 0);
  for (int e = 0; e < E; ++e)
    if (topo.is_border_edge(e) || p.feature[e])
      for (int v : topo.edge_vertices(e)) on_curve[v] = 1;
  std::vector<std::set<int>> edge_sets;
  for (size_t c = 0; c < g.nonzero_chains.size(); ++c) {
    const auto& ch = g.nonzero_chains[c];
    const std::string name = "chain " + std::to_string(c);
    if (const int t = g.nonzero_trace[c]; t <= -2) {
      const std::vector<int>& along = g.traces[-2 - t].vertices;
      const auto at = std::search(along.begin(), along.end(), ch.begin(), ch.end());
      if (ch.size() < 2 || at == along.end()) return name + ": not a piece of its trace";
      if (!on_curve[ch.front()] || !on_curve[ch.back()]) return name + ": not curve to curve";
      for (size_t k = 1; k + 1 < ch.size(); ++k)
        if (on_curve[ch[k]]) return name + ": passes a curve";
    } else if (ch.size() < 2 || !seeds.count(ch[0])) {
      return name + ": not from a seed";
    }
    std::set<int> es;
    for (size_t k = 0; k + 1 < ch.size(); ++k) {
      const int e = topo.find_edge(ch[k], ch[k + 1]);
      if (e < 0 || !g.cut[e]) return name + ": not along cut edges";
      if (k > 0 && topo.straight_on(ch[k], topo.find_edge(ch[k - 1], ch[k])) != e)
        return name + ": turns";
      es.insert(e);
    }
    if (passes(ch.back()) && !seeds.count(ch.back())) return name + ": ends inside an arc";
    const int t = g.nonzero_trace[c];
    if (t >= 0 && !std::equal(ch.begin(), ch.end(), g.traces[t].vertices.begin()))
      return name + ": not a prefix of its trace";
    edge_sets.push_back(std::move(es));
  }
  for (size_t a = 0; a < edge_sets.size(); ++a)
    for (size_t b = 0; b < edge_sets.size(); ++b)
      if (a != b && std::includes(edge_sets[a].begin(), edge_sets[a].end(), edge_sets[b].begin(),
                                  edge_sets[b].end()))
        return "chain " + std::to_string(a) + " implied by chain " + std::to_string(b);
  // Every piece of a trace between two curves it reaches holds a chain (or one implying it).
  for (size_t t = 0; t < g.traces.size(); ++t) {
    const Trace& tr = g.traces[t];
    for (size_t from = 0, k = 1; k < tr.vertices.size(); ++k) {
      if (!on_curve[tr.vertices[k]]) continue;
      if (on_curve[tr.vertices[from]]) {
        const std::set<int> piece(tr.edges.begin() + from, tr.edges.begin() + k);
        if (std::none_of(edge_sets.begin(), edge_sets.end(), [&](const std::set<int>& es) {
              return std::includes(piece.begin(), piece.end(), es.begin(), es.end());
            }))
          return "trace " + std::to_string(t) + ": no chain between the curves at " +
                 std::to_string(tr.vertices[from]) + " and " + std::to_string(tr.vertices[k]);
      }
      from = k;
    }
  }
  return "";
}

// The result keyed by what does not depend on emission order.
struct Canonical {
  std::map<std::pair<int, int>, std::vector<int>> traces;  // (seed, first edge) → edges
  std::vector<uint8_t> cut;
  std::vector<std::vector<int>> chains;
  int crossings;
  bool operator==(const Canonical&) const = default;
};
Canonical canonical(const AngleBoundedGraph& g) {
  Canonical c{{}, g.cut, g.nonzero_chains, g.crossings};
  for (const auto& t : g.traces) c.traces[{t.seed, t.edges[0]}] = t.edges;
  return c;
}

bool has_chain(const AngleBoundedGraph& g, const std::vector<int>& chain) {
  std::vector<int> reversed(chain.rbegin(), chain.rend());
  for (const auto& c : g.nonzero_chains)
    if (c == chain || c == reversed) return true;
  return false;
}

const Trace& trace_from(const AngleBoundedGraph& g, int seed, int next) {
  for (const auto& t : g.traces)
    if (t.seed == seed && t.vertices[1] == next) return t;
  throw std::logic_error("no such trace");
}

TEST(TmeshAngle, FullAngleIsTheExtendedGraph) {
  for (uint64_t seed = 0; seed < 40; ++seed) {
    const Prepared p = prepare(test::random_quad_mesh(seed));
    const std::vector<Trace> ext =
        trace_extended_motorcycle_graph(*p.topo, p.feature, p.seeds, /*cross_features=*/true);
    for (double angle : {90.0, 135.0}) {
      const AngleBoundedGraph g = trace(p, angle);
      ASSERT_EQ(g.traces.size(), ext.size()) << seed;
      for (size_t t = 0; t < ext.size(); ++t) EXPECT_EQ(g.traces[t].edges, ext[t].edges) << seed;
    }
  }
}

TEST(TmeshAngle, RandomMeshesGiveRectanglesAndStraightChains) {
  int checked = 0, stopped_short = 0;
  for (uint64_t seed = 0; seed < 220; ++seed) {
    std::string what;
    const Prepared p = prepare(test::random_quad_mesh(seed, &what));
    const int full = traced_edges(trace(p, 90));
    // Below 90°, smaller angles stop fewer traces; 90° and above is the special case "no
    // angle rule" (the full extended graph), which is not the limit of the others.
    int previous = -1;
    std::vector<size_t> previous_lengths;
    for (double angle : {89.0, 60.0, 45.0, 35.0, 20.0, 10.0, 5.0, 0.0}) {
      const AngleBoundedGraph g = trace(p, angle);
      const std::string failure = check_graph(p, g);
      ASSERT_EQ(failure, "") << "seed " << seed << " (" << what << ") at " << angle << "°";
      const int edges = traced_edges(g);
      EXPECT_GE(edges, previous) << "seed " << seed << " (" << what << ") at " << angle << "°";
      EXPECT_LE(edges, full);
      // Also per trace (the same emission order at every angle).
      for (size_t t = 0; t < previous_lengths.size(); ++t)
        EXPECT_GE(g.traces[t].edges.size(), previous_lengths[t]) << "seed " << seed;
      previous_lengths.clear();
      for (const auto& t : g.traces) previous_lengths.push_back(t.edges.size());
      stopped_short += edges < full;
      previous = edges;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 220 * 8);
  EXPECT_GT(stopped_short, 0);  // the angle rule does stop traces on these meshes
}

TEST(TmeshAngle, IndependentOfSeedOrder) {
  for (uint64_t seed = 0; seed < 120; ++seed) {
    const Prepared p = prepare(test::random_quad_mesh(seed));
    std::vector<int> reversed(p.seeds.rbegin(), p.seeds.rend());
    std::vector<int> shuffled = p.seeds;
    std::mt19937 rng(static_cast<unsigned>(seed));
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    for (double angle : {10.0, 30.0, 45.0, 90.0}) {
      const Canonical base = canonical(trace(p, angle));
      EXPECT_TRUE(base == canonical(trace_angle_bounded(*p.topo, p.feature, reversed, angle)))
          << "seed " << seed << " at " << angle << "°";
      EXPECT_TRUE(base == canonical(trace_angle_bounded(*p.topo, p.feature, shuffled, angle)))
          << "seed " << seed << " at " << angle << "°";
    }
  }
}

TEST(TmeshAngle, TerminatesOnHelicalTori) {
  for (int shift : {0, 1, 5, 7}) {
    QuadMesh mesh = test::torus_mesh(17, 13, shift);
    EXPECT_TRUE(trace(prepare(mesh, 180), 10).traces.empty());  // no seed: nothing to trace
    rotate_edge(mesh, 3 * 17 + 4, 3 * 17 + 5);  // two valence-3 and two valence-5 vertices
    const Prepared p = prepare(mesh, 180);
    ASSERT_EQ(p.seeds.size(), 4u);
    for (double angle : {0.0, 10.0, 45.0, 90.0}) {
      const AngleBoundedGraph g = trace(p, angle);
      EXPECT_EQ(g.traces.size(), 16u);
      EXPECT_EQ(check_graph(p, g), "") << "shift " << shift << " at " << angle << "°";
    }
  }
}

TEST(TmeshAngle, SubdividedCubeTracesRunCornerToCorner) {
  const Prepared p = prepare(test::subdivided_cube(3));
  const AngleBoundedGraph g = trace(p, 20);
  ASSERT_EQ(g.traces.size(), 24u);
  for (const auto& t : g.traces) EXPECT_EQ(t.edges.size(), 8u);  // a cube edge, 8 quads long
  EXPECT_EQ(g.crossings, 0);
  EXPECT_EQ(g.nonzero_chains.size(), 12u);  // one per cube edge (its two traces coincide)
  EXPECT_EQ(check_graph(p, g), "");
}

// Traces cross feature curves: the subdivided cube with two grid loops round it marked as
// features, one and seven rows from the corners at one end of a cube edge. The cube edges
// along which the loops run round are unaffected; the four crossing them still run corner to
// corner, through both loops (a trace that stopped at a feature would leave the middle of the
// separatrix outside the T-mesh, free to bend in a coarsening), and the piece between the
// loops is a non-zero chain (the strip between the features cannot collapse there).
TEST(TmeshAngle, TracesCrossFeatureLoopsAndKeepThemApart) {
  Prepared p = prepare(test::subdivided_cube(3), 180);
  const QuadMeshTopology& topo = *p.topo;
  const int e0 = topo.vertex_edges(0)[0];
  const auto mark_loop = [&](int offset) {
    int at = 0, e = e0;
    for (int k = 0; k < offset; ++k) {
      at = topo.other_vertex(e, at);
      if (k + 1 < offset) e = topo.straight_on(at, e);
    }
    const auto ring = topo.vertex_edges(at);
    const int i = static_cast<int>(std::find(ring.begin(), ring.end(), e) - ring.begin());
    int edge = ring[(i + 1) % 4], v = at, edges = 0;
    do {
      p.feature[edge] = 1, ++edges;
      v = topo.other_vertex(edge, v);
      edge = topo.straight_on(v, edge);
    } while (v != at && edges < topo.num_edges());
    return edges;
  };
  ASSERT_EQ(mark_loop(1), 32);
  ASSERT_EQ(mark_loop(7), 32);
  p.seeds = seed_vertices(topo, p.feature);
  ASSERT_EQ(p.seeds.size(), 8u);  // the loops are straight: no feature corners
  for (double angle : {10.0, 45.0}) {
    const AngleBoundedGraph g = trace(p, angle);
    ASSERT_EQ(g.traces.size(), 24u);
    int crossing = 0;
    for (const auto& t : g.traces) {
      EXPECT_EQ(t.edges.size(), 8u) << angle;  // a cube edge, corner to corner
      crossing += std::any_of(t.edges.begin(), t.edges.end(), [&](int e) {
        return std::find(p.seeds.begin(), p.seeds.end(), topo.edge_vertices(e)[0]) ==
                   p.seeds.end() &&
               std::any_of(topo.vertex_edges(topo.edge_vertices(e)[0]).begin(),
                           topo.vertex_edges(topo.edge_vertices(e)[0]).end(),
                           [&](int f) { return p.feature[f] != 0; });
      });
    }
    EXPECT_EQ(crossing, 8) << angle;  // 4 cube edges, a trace from each end
    EXPECT_EQ(check_graph(p, g), "") << angle;
  }
  // Ending at feature curves instead (cross_features false, Lyon et al.'s rule): those 8 traces
  // end one edge out, on the loop nearest their corner; the graph stays valid.
  for (double angle : {10.0, 45.0}) {
    const AngleBoundedGraph g = trace_angle_bounded(topo, p.feature, p.seeds, angle, false);
    ASSERT_EQ(g.traces.size(), 24u);
    int short_traces = 0;
    for (const auto& t : g.traces) {
      EXPECT_TRUE(t.edges.size() == 1 || t.edges.size() == 8) << t.edges.size();
      short_traces += t.edges.size() == 1;
    }
    EXPECT_EQ(short_traces, 8) << angle;
    EXPECT_EQ(check_graph(p, g), "") << angle;
  }
}

// Reflex border corners A = (3, 3) and B = (8, 4), offset (5, 1): A's trace east along y = 3
// crosses B's trace south along x = 8 at (8, 3) (l_A = 5, l_B = 1, 11.3° at A), and B's trace
// west along y = 4 crosses A's trace north at (3, 4) (11.3° at B).
TEST(TmeshAngle, OffsetOneCollapseForbiddenOnlyBelowItsAngle) {
  const Blocks b = grid_without(12, 8, {{0, 3, 0, 3}, {8, 12, 4, 8}});
  const Prepared p = prepare(b.mesh, 180);
  const std::vector<int> b_down{b.at(8, 4), b.at(8, 3)}, a_up{b.at(3, 3), b.at(3, 4)};
  const AngleBoundedGraph narrow = trace(p, 10);
  EXPECT_EQ(check_graph(p, narrow), "");
  EXPECT_TRUE(has_chain(narrow, b_down));
  EXPECT_TRUE(has_chain(narrow, a_up));
  EXPECT_EQ(narrow.crossings, 2);
  for (double angle : {12.0, 45.0, 90.0}) {
    const AngleBoundedGraph wide = trace(p, angle);
    EXPECT_EQ(check_graph(p, wide), "");
    EXPECT_FALSE(has_chain(wide, b_down)) << angle;
    EXPECT_FALSE(has_chain(wide, a_up)) << angle;
    // (1): A's east trace up to (8, 3), B's seed being inside its 90° sector.
    std::vector<int> a_east;
    for (int x = 3; x <= 8; ++x) a_east.push_back(b.at(x, 3));
    EXPECT_TRUE(has_chain(wide, a_east)) << angle;
  }
}

// The fixture's thin strip: A = (3, 3), B = (7, 4), offset (4, 1), 14.0° at each.
TEST(TmeshAngle, ThinStripIsProtectedOnlyBelowFourteenDegrees) {
  const Prepared p = prepare(test::thin_strip_mesh(), 180);
  const std::vector<int> b_down{test::thin_strip_vertex(7, 4), test::thin_strip_vertex(7, 3)};
  EXPECT_TRUE(has_chain(trace(p, 13.5), b_down));
  EXPECT_FALSE(has_chain(trace(p, 14.5), b_down));
}

// P = (3, 5) runs east along y = 5; Q = (10, 6) runs south across it at (10, 5) from its left
// (l_P = 7, l_Q = 1: 8.1°), R = (12, 4) north across it at (12, 5) from its right (l_P = 9,
// l_R = 1: 6.3°). R's trace has passed (12, 5) long before P gets there.
TEST(TmeshAngle, TraceStopsAfterCrossingOnBothSidesWithinTheAngle) {
  const Blocks b = grid_without(16, 10, {{0, 3, 0, 5}, {10, 16, 6, 10}, {12, 16, 0, 4}});
  const Prepared p = prepare(b.mesh, 180);
  auto p_east = [&](double angle) {
    const AngleBoundedGraph g = trace(p, angle);
    EXPECT_EQ(check_graph(p, g), "") << angle;
    return trace_from(g, b.at(3, 5), b.at(4, 5)).vertices.back();
  };
  EXPECT_EQ(p_east(10), b.at(12, 5));
  EXPECT_EQ(p_east(8.5), b.at(12, 5));
  EXPECT_EQ(p_east(7.5), b.at(16, 5));  // Q's crossing is outside the angle: no left one
  EXPECT_EQ(p_east(5), b.at(16, 5));
  EXPECT_EQ(p_east(90), b.at(16, 5));
}

TEST(TmeshAngle, CurvePathsKeepAFeatureOnlyMeshApart) {
  // A grid has only border corners, which emit no trace: the border curves between the
  // corners are the only paths.
  const Prepared p = prepare(test::grid_mesh(5, 3), 180);
  const AngleBoundedGraph g = trace(p, 20);
  EXPECT_TRUE(g.traces.empty());
  ASSERT_EQ(g.nonzero_chains.size(), 4u);
  for (const auto& c : g.nonzero_chains) EXPECT_TRUE(c.size() == 6 || c.size() == 4);
  EXPECT_EQ(check_graph(p, g), "");
}

// A feature curve along y = 3 from (2, 3) to (8, 3) (its ends are seeds) and the reflex corner
// J = (5, 5) of a removed block, whose trace runs down across the curve at (5, 3): 2 edges from
// J, 3 along the curve from either end. (2) against curves: below atan(3/2) = 56.3° the curve's
// ends may not slide onto J's line (their curve paths up to (5, 3) are paths of their own).
// (J's path down to the curve is a path at every angle here: (4), J being on the border.)
TEST(TmeshAngle, SeedsKeepTheirAngleToFeatureCurves) {
  const Blocks b = grid_without(12, 8, {{0, 5, 5, 8}});
  Prepared p = prepare(b.mesh, 180);
  for (int x = 2; x < 8; ++x) p.feature[p.topo->find_edge(b.at(x, 3), b.at(x + 1, 3))] = 1;
  p.seeds = seed_vertices(*p.topo, p.feature);
  const std::vector<int> j_down{b.at(5, 5), b.at(5, 4), b.at(5, 3)};
  const std::vector<int> from_east{b.at(8, 3), b.at(7, 3), b.at(6, 3), b.at(5, 3)};
  const std::vector<int> from_west{b.at(2, 3), b.at(3, 3), b.at(4, 3), b.at(5, 3)};
  for (double angle : {30.0, 40.0, 50.0, 60.0}) {
    const AngleBoundedGraph g = trace(p, angle);
    EXPECT_EQ(check_graph(p, g), "") << angle;
    EXPECT_TRUE(has_chain(g, j_down)) << angle;
    EXPECT_EQ(has_chain(g, from_east), angle < 56.3) << angle;
    EXPECT_EQ(has_chain(g, from_west), angle < 56.3) << angle;
  }
}

TEST(TmeshAngle, RejectsBadArguments) {
  const Prepared p = prepare(test::grid_mesh(2, 2), 180);
  EXPECT_THROW(trace_angle_bounded(*p.topo, {}, p.seeds, 10), std::invalid_argument);
  EXPECT_THROW(trace_angle_bounded(*p.topo, p.feature, {99}, 10), std::invalid_argument);
  EXPECT_THROW(trace_angle_bounded(*p.topo, p.feature, p.seeds, -1), std::invalid_argument);
  EXPECT_THROW(trace_angle_bounded(*p.topo, p.feature, p.seeds, std::nan("")),
               std::invalid_argument);
}

}  // namespace
}  // namespace bimdf::tmesh::detail
