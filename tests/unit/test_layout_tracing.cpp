// The motorcycle graph of separatrices (src/layout/tracing.cpp), the choice of the traces a
// layout keeps (trace_selection.cpp) and the last-resort cuts of patches that are not disks
// (patches.cpp), on grids with hand-made ways, singularities and boundaries, where the right
// answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "layout/face_frames.hpp"
#include "layout/patches.hpp"
#include "layout/surface_topology.hpp"
#include "layout/trace_selection.hpp"
#include "layout/tracing.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

using layout::SurfacePoint;
using layout::Trace;

// The same pair of directions in every face: (cos a, sin a), (−sin a, cos a).
layout::FaceWays uniform_ways(const TriangleMesh& m, const layout::FaceFrames& frames, double a) {
  std::vector<std::array<detail::Vec3, 2>> d(
      m.num_faces(), {detail::Vec3{std::cos(a), std::sin(a), 0}, {-std::sin(a), std::cos(a), 0}});
  return layout::face_ways(frames, d);
}

std::vector<bool> border_edges(const layout::SurfaceTopology& top) {
  std::vector<bool> curve(top.num_edges(), false);
  for (int e = 0; e < top.num_edges(); ++e) curve[e] = top.opposite(top.edge_half_edge(e)) < 0;
  return curve;
}

// The square [0, 8]² as an 8×8 grid; vertex (i, j) at (i, j) is i·9 + j.
int vertex(int i, int j) { return i * 9 + j; }

TEST(LayoutTracing, ACurveThroughAVertexStartsNothingEvenWhereTheWaysAreSkewedToIt) {
  const TriangleMesh m = test::square(8, 8);
  const layout::SurfaceTopology top(m);
  const layout::FaceFrames frames(m);
  // The border and the line y = 4 are curves; the ways are 25° off them (more than the fifth
  // of a quarter that used to tell a way inside a sector from one along its curves), and no
  // vertex is singular: no separatrix starts anywhere.
  std::vector<bool> curve = border_edges(top);
  for (int i = 0; i < 8; ++i)
    for (int h = 0; h < 3 * m.num_faces(); ++h)
      if (top.from(h) == vertex(i, 4) && top.to(h) == vertex(i + 1, 4)) curve[top.edge(h)] = true;
  for (double skew_deg : {0.0, 25.0, -25.0}) {
    const layout::FaceWays ways = uniform_ways(m, frames, skew_deg * M_PI / 180);
    // Corners of the square turn by a quarter: index 1 there.
    std::vector<int> index(m.num_vertices(), 0);
    for (int v : {vertex(0, 0), vertex(0, 8), vertex(8, 0), vertex(8, 8)}) index[v] = 1;
    const layout::MotorcycleGraph g =
        layout::trace_motorcycle_graph(top, frames, ways, index, curve, {});
    EXPECT_EQ(g.starts, 0) << "skew " << skew_deg << "°";
    EXPECT_TRUE(g.traces.empty()) << "skew " << skew_deg << "°";
  }
}

// Two singularities A (2, 4.3) and B (6, 5), head on along x, 0.7 apart across it: A's trace
// towards B is paired with B's towards A. Returns the angle (degrees) between the trace's
// last piece into B and B's separatrix it stands for (along x).
double paired_arrival_deg(double steer_radius) {
  TriangleMesh m = test::square(8, 8);
  m.vertices[vertex(2, 4)][1] = 4.3;
  const layout::SurfaceTopology top(m);
  const layout::FaceFrames frames(m);
  const layout::FaceWays ways = uniform_ways(m, frames, 0);
  std::vector<int> index(m.num_vertices(), 0);
  for (int v : {vertex(0, 0), vertex(0, 8), vertex(8, 0), vertex(8, 8)}) index[v] = 1;
  index[vertex(2, 4)] = index[vertex(6, 5)] = 1;
  layout::TraceOptions options;
  options.steer_radius = steer_radius;
  const layout::MotorcycleGraph g =
      layout::trace_motorcycle_graph(top, frames, ways, index, border_edges(top), options);
  for (const Trace& t : g.traces) {
    const SurfacePoint& last = t.points.back();
    if (t.start_vertex != vertex(2, 4) || last.kind != SurfacePoint::Kind::Vertex ||
        last.id != vertex(6, 5))
      continue;
    EXPECT_EQ(t.end, Trace::End::Singularity);
    const detail::Vec3 d = detail::sub(layout::position(top, last),
                                       layout::position(top, t.points[t.points.size() - 2]));
    return std::atan2(std::fabs(d[1]), d[0]) * 180 / M_PI;
  }
  ADD_FAILURE() << "no trace from A ends at B";
  return 180;
}

TEST(LayoutTracing, APairedTraceSteersOntoItsPartnersSeparatrix) {
  // Stepping straight onto B from the first face next to it turns by atan(0.7) ≈ 35°, which
  // leaves B a sliver sector and a nearly straight one; steering over the last three approach
  // radii arrives nearly along B's separatrix.
  const double unsteered = paired_arrival_deg(0);
  const double steered = paired_arrival_deg(3);
  EXPECT_GT(unsteered, 30);
  EXPECT_LT(steered, 15);
}

// Seeds (regular vertices traced all four ways) `a` and `b` on the 8×8 square, its ways at
// `angle` to x. Returns how far sideways a trace ends from the line its first step took, the
// largest (0 when every trace is straight), and how many traces end at the other seed.
std::pair<double, int> sideways_and_joined(int a, int b, double angle) {
  const TriangleMesh m = test::square(8, 8);
  const layout::SurfaceTopology top(m);
  const layout::FaceFrames frames(m);
  std::vector<int> index(m.num_vertices(), 0);
  for (int v : {vertex(0, 0), vertex(0, 8), vertex(8, 0), vertex(8, 8)}) index[v] = 1;
  layout::TraceOptions options;
  options.seeds = {a, b};
  options.approach_radius = 1.2;  // farther than the neighbouring seed
  const layout::MotorcycleGraph g = layout::trace_motorcycle_graph(
      top, frames, uniform_ways(m, frames, angle), index, border_edges(top), options);
  double worst = 0;
  int joined = 0;
  for (const Trace& t : g.traces) {
    const SurfacePoint& last = t.points.back();
    const int other = t.start_vertex == a ? b : a;
    joined += last.kind == SurfacePoint::Kind::Vertex && last.id == other;
    const detail::Vec3 start = layout::position(top, t.points.front());
    const detail::Vec3 first =
        detail::normalized(detail::sub(layout::position(top, t.points[1]), start));
    const detail::Vec3 whole = detail::sub(layout::position(top, last), start);
    const double ahead = detail::dot(whole, first);
    worst = std::max(worst, std::sqrt(std::max(0.0, detail::dot(whole, whole) - ahead * ahead)));
  }
  return {worst, joined};
}

TEST(LayoutTracing, SeedsSideBySideAreNotJoined) {
  // With the ways at 40°, the seed at (5, 4) lies 0.64 to the side of the way from (4, 4)
  // and 0.77 ahead, within the approach radius: joined, that trace would step sideways onto
  // it — a Z cut with two corners. Each seed cuts straight across instead.
  const auto [beside, beside_joined] =
      sideways_and_joined(vertex(4, 4), vertex(5, 4), 40 * M_PI / 180);
  EXPECT_LT(beside, 1e-6);
  EXPECT_EQ(beside_joined, 0);
  // Head on (each on the other's way along x), seeds are still one trace.
  const auto [apart, apart_joined] = sideways_and_joined(vertex(2, 4), vertex(6, 4), 0);
  EXPECT_LT(apart, 1e-9);
  EXPECT_EQ(apart_joined, 1);
}

Trace ending(int start, int way, int ways, Trace::End end, double length) {
  Trace t;
  t.start_vertex = start;
  t.start_way = way;
  t.start_ways = ways;
  t.end = end;
  t.length = length;
  t.points = {SurfacePoint::at_vertex(start), SurfacePoint::at_vertex(start)};
  return t;
}

TEST(LayoutTraceSelection, OfEachRunOfShortWaysToACurveOnlyTheShortestStays) {
  const std::vector<bool> on_curve = {false, false, false, true};
  std::vector<Trace> traces = {
      // Vertex 0, five ways: all but 2 are short to a curve, one run 3, 4, 0, 1 through the
      // wrap-around.
      ending(0, 4, 5, Trace::End::Curve, 0.5), ending(0, 0, 5, Trace::End::Curve, 0.2),
      ending(0, 1, 5, Trace::End::Curve, 0.9), ending(0, 2, 5, Trace::End::Curve, 7),
      ending(0, 3, 5, Trace::End::Curve, 0.1),
      // Vertex 1: ways 0 and 2 of three are short, and consecutive through the wrap-around;
      // way 1 ends on a trace.
      ending(1, 0, 3, Trace::End::Curve, 0.4), ending(1, 2, 3, Trace::End::Curve, 0.3),
      ending(1, 1, 3, Trace::End::Trace, 0.1),
      // Vertex 2: short ways 0 and 2 of four, not consecutive.
      ending(2, 0, 4, Trace::End::Curve, 0.1), ending(2, 2, 4, Trace::End::Curve, 0.1),
      // Vertex 3 is on a curve: its short ways are its own business.
      ending(3, 0, 4, Trace::End::Curve, 0.1), ending(3, 1, 4, Trace::End::Curve, 0.1)};
  std::vector<std::array<int, 2>> banned;
  layout::ban_short_to_curve(traces, on_curve, {}, 1.0, banned);
  std::sort(banned.begin(), banned.end());
  // Vertex 0 keeps way 3 (the shortest of its run), vertex 1 way 2.
  const std::vector<std::array<int, 2>> expected = {{0, 0}, {0, 1}, {0, 4}, {1, 0}};
  EXPECT_EQ(banned, expected);
  banned.clear();
  layout::ban_short_to_curve(traces, on_curve, {}, 0, banned);
  EXPECT_TRUE(banned.empty());
  layout::ban_short_to_curve(traces, on_curve, {0, 1}, 1.0, banned);  // seeds
  EXPECT_TRUE(banned.empty());
}

// A trace ending on a curve at a shallow angle ran alongside it (curves are not iso-lines):
// banned below its own bound, a seed's too; ending on a trace has another bound, and there a
// seed's trace stays.
TEST(LayoutTraceSelection, ShallowEndsOnCurvesAndOnTracesHaveTheirOwnBounds) {
  std::vector<Trace> traces = {
      ending(0, 0, 4, Trace::End::Curve, 1), ending(0, 1, 4, Trace::End::Curve, 1),
      ending(0, 2, 4, Trace::End::Trace, 1), ending(0, 3, 4, Trace::End::Singularity, 1),
      ending(1, 0, 4, Trace::End::Curve, 1), ending(1, 1, 4, Trace::End::Trace, 1)};
  for (Trace& t : traces) t.end_angle = 0.3;
  traces[1].end_angle = 0.9;  // steeper than the curve bound
  std::vector<std::array<int, 2>> banned;
  layout::ban_shallow_ends(traces, 0, M_PI / 4, {1}, banned);  // vertex 1 is a seed
  EXPECT_EQ(banned, (std::vector<std::array<int, 2>>{{0, 0}, {1, 0}}));
  banned.clear();
  layout::ban_shallow_ends(traces, 0.5, 0, {1}, banned);
  EXPECT_EQ(banned, (std::vector<std::array<int, 2>>{{0, 2}}));
}

TEST(LayoutTraceSelection, ASeedThatCutsAcrossLosesItsLoop) {
  const std::vector<bool> on_curve(4, false);
  const std::vector<Trace> traces = {
      // Seed 0: ways 1 and 3 reach curves near by (across its thin ring); 0 and 2 go round.
      ending(0, 0, 4, Trace::End::Trace, 5), ending(0, 1, 4, Trace::End::Curve, 1),
      ending(0, 2, 4, Trace::End::Singularity, 5), ending(0, 3, 4, Trace::End::Curve, 1),
      // Seed 3: both ways across reach curves, but one of them far: a wide ring, all stay.
      ending(3, 0, 4, Trace::End::Curve, 1), ending(3, 2, 4, Trace::End::Curve, 4),
      ending(3, 1, 4, Trace::End::Trace, 5), ending(3, 3, 4, Trace::End::Trace, 5),
      // Seed 1: only one way reaches a curve: all stay.
      ending(1, 0, 4, Trace::End::Curve, 1), ending(1, 1, 4, Trace::End::Trace, 1),
      ending(1, 2, 4, Trace::End::Trace, 1), ending(1, 3, 4, Trace::End::Trace, 1),
      // Vertex 2 is no seed.
      ending(2, 0, 4, Trace::End::Curve, 1), ending(2, 2, 4, Trace::End::Curve, 1),
      ending(2, 1, 4, Trace::End::Trace, 1)};
  std::vector<std::array<int, 2>> banned;
  layout::ban_seed_loops(traces, on_curve, {0, 1, 3}, 2.0, banned);
  std::sort(banned.begin(), banned.end());
  const std::vector<std::array<int, 2>> expected = {{0, 0}, {0, 2}};
  EXPECT_EQ(banned, expected);
}

// A trace along the points (i, j) of the 8×8 grid, from its first to its last vertex.
Trace through(int way, const std::vector<std::array<int, 2>>& ij) {
  Trace t;
  t.start_vertex = vertex(ij[0][0], ij[0][1]);
  t.start_way = way;
  t.start_ways = 4;
  t.end = Trace::End::Curve;
  for (const auto& [i, j] : ij) t.points.push_back(SurfacePoint::at_vertex(vertex(i, j)));
  t.length = static_cast<double>(ij.size() - 1);
  return t;
}

TEST(LayoutTraceSelection, ATraceAlongACurveCloseByIsBannedOneAcrossIsNot) {
  const TriangleMesh m = test::square(8, 8);
  const layout::SurfaceTopology top(m);
  std::vector<bool> on_curve(m.num_vertices(), false);
  for (int i = 0; i <= 8; ++i) on_curve[vertex(i, 0)] = true;  // the bottom side alone
  const std::vector<double> to_curve = layout::distance_to_curves(top, on_curve);
  EXPECT_DOUBLE_EQ(to_curve[vertex(3, 0)], 0);
  EXPECT_DOUBLE_EQ(to_curve[vertex(3, 1)], 1);
  EXPECT_DOUBLE_EQ(to_curve[vertex(5, 7)], 7);
  const std::vector<Trace> traces = {
      // 1 from the curve, 6 along it: a band one edge wide.
      through(0, {{1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}, {7, 1}}),
      // 3 from it, as long: wide enough.
      through(1, {{1, 3}, {2, 3}, {3, 3}, {4, 3}, {5, 3}, {6, 3}, {7, 3}}),
      // Straight down onto it from 6 away: near it over its last stretch only.
      through(2, {{4, 6}, {4, 5}, {4, 4}, {4, 3}, {4, 2}, {4, 1}, {4, 0}}),
      // A seed's, 1 from the curve: seeds are left alone.
      through(3, {{2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}, {7, 1}})};
  std::vector<std::array<int, 2>> banned;
  layout::ban_along_curves(top, traces, to_curve, {vertex(2, 1)}, 1.5, 3, banned);
  EXPECT_EQ(banned, (std::vector<std::array<int, 2>>{{vertex(1, 1), 0}}));
  // Closer than 3.5 for longer than 4.5, no seeds: all but the one down (near for 3).
  banned.clear();
  layout::ban_along_curves(top, traces, to_curve, {}, 3.5, 4.5, banned);
  EXPECT_EQ(banned, (std::vector<std::array<int, 2>>{
                        {vertex(1, 1), 0}, {vertex(1, 3), 1}, {vertex(2, 1), 3}}));
}

TEST(LayoutTraceSelection, TracesEndingOnADroppedTraceAreDroppedToo) {
  std::vector<Trace> traces = {
      ending(0, 0, 4, Trace::End::Unfinished, 1), ending(1, 0, 4, Trace::End::Trace, 1),
      ending(2, 0, 4, Trace::End::Trace, 1), ending(3, 0, 4, Trace::End::Singularity, 1)};
  traces[1].end_trace = 0;  // on the unfinished one: goes with it
  traces[2].end_trace = 1;  // on that one: goes too
  traces[3].end_trace = 0;  // at a singularity: stays
  EXPECT_EQ(layout::drop_dangling(traces), 3);
  ASSERT_EQ(traces.size(), 1u);
  EXPECT_EQ(traces[0].start_vertex, 3);
}

// Labels the cylinder's patches with `boundary` (per edge) and cuts across what is not a disk,
// as generate.cpp does. Returns the patches and how many cuts were made.
std::pair<layout::Patches, int> cut_until_disks(const layout::SurfaceTopology& top,
                                                std::vector<bool> boundary) {
  const int V = top.mesh().num_vertices();
  layout::CornerHints hints;
  hints.field_quarters.assign(V, 4);
  for (int v = 0; v < V; ++v)
    if (top.on_border(v)) hints.field_quarters[v] = 2;
  hints.ending_edge.assign(V, -1);
  layout::Patches patches = layout::label_patches(top, boundary, hints);
  int cuts = 0;
  for (int pass = 0; pass < 4; ++pass) {
    const int made = layout::cut_across_non_disks(top, patches, boundary, hints);
    if (made == 0) break;
    cuts += made;
    patches = layout::label_patches(top, boundary, hints);
  }
  return {patches, cuts};
}

// Corner hints for a square grid: the field turns 4 quarters inside, 2 on the border, 1 at the
// square's `corners`; no trace ends anywhere; parameter_quarters sized, for the test to fill.
layout::CornerHints square_hints(const layout::SurfaceTopology& top,
                                 const std::vector<int>& corners) {
  const int V = top.mesh().num_vertices();
  layout::CornerHints hints;
  hints.field_quarters.assign(V, 4);
  for (int v = 0; v < V; ++v)
    if (top.on_border(v)) hints.field_quarters[v] = 2;
  for (int v : corners) hints.field_quarters[v] = 1;
  hints.ending_edge.assign(V, -1);
  hints.parameter_quarters.resize(3 * top.mesh().num_faces());
  return hints;
}

TEST(LayoutPatches, WhereTheMapFoldsCornersComeFromTheFieldsTurns) {
  // The square [0, 1]² as one patch; the parameter angles are the true ones but at the middle
  // of its bottom side, where the map is made to fold: a negative angle there must not make a
  // corner (it did: five corners), the sector's share of the field's turns (2) is used.
  const TriangleMesh m = test::square(1, 2);
  const layout::SurfaceTopology top(m);
  std::vector<bool> border(top.num_edges());
  for (int e = 0; e < top.num_edges(); ++e) border[e] = top.opposite(top.edge_half_edge(e)) < 0;
  layout::CornerHints hints = square_hints(top, {0, 2, 6, 8});
  for (int h = 0; h < 3 * m.num_faces(); ++h)
    hints.parameter_quarters[h] = top.from(h) == 3 ? -0.1 : top.corner_angle(h) / (M_PI / 2);
  const layout::Patches patches = layout::label_patches(top, border, hints);
  ASSERT_EQ(patches.corners.size(), 1u);
  std::vector<int> corners = patches.corners[0];
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<int>{0, 2, 6, 8}));
  EXPECT_EQ(patches.problem[0], "");
}

TEST(LayoutPatches, WhereTheSurfaceIsFlatAMapsCornerCanBeOverruled) {
  // The square [0, 4]² cut in two by the line through its middle vertices (i = 2). The map's
  // angles are the true ones but at the line's middle vertex on one side, where it reads 1.3
  // quarters (a map bending round a cone near by): a corner there — five for that patch —
  // unless CornerHints::flat_share overrules it, the sector's share of the field's turns (2)
  // being above it.
  const TriangleMesh m = test::square(4, 4);
  const layout::SurfaceTopology top(m);
  const auto on_line = [](int v) { return v / 5 == 2; };
  const int middle = 2 * 5 + 2;
  std::vector<bool> boundary(top.num_edges());
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e);
    boundary[e] = top.opposite(h) < 0 || (on_line(top.from(h)) && on_line(top.to(h)));
  }
  layout::CornerHints hints = square_hints(top, {0, 4, 20, 24});
  for (int h = 0; h < 3 * m.num_faces(); ++h) {
    const auto& f = m.faces[h / 3];
    const bool low_side = f[0] / 5 + f[1] / 5 + f[2] / 5 < 6;  // the faces with i < 2
    hints.parameter_quarters[h] =
        top.corner_angle(h) / (M_PI / 2) * (top.from(h) == middle && low_side ? 0.65 : 1);
  }
  const auto corners_at_middle = [&](double flat_share) {
    hints.flat_share = flat_share;
    const layout::Patches patches = layout::label_patches(top, boundary, hints);
    EXPECT_EQ(patches.corners.size(), 2u);
    int n = 0;
    for (const auto& c : patches.corners) n += std::count(c.begin(), c.end(), middle);
    return n;
  };
  EXPECT_EQ(corners_at_middle(0), 1);
  EXPECT_EQ(corners_at_middle(1.9), 0);
  EXPECT_EQ(corners_at_middle(2.1), 1);  // the share, 2, is not above it
}

TEST(LayoutPatches, AnAnnulusIsCutAcrossIntoDisks) {
  const TriangleMesh m = test::cylinder(2, 12, 4);
  const layout::SurfaceTopology top(m);
  const std::vector<bool> none(top.num_edges(), false);
  ASSERT_TRUE(
      layout::label_patches(
          top, none,
          {std::vector<int>(m.num_vertices(), 4), std::vector<int>(m.num_vertices(), -1), {}})
          .not_disk[0]);
  // The first cut leaves one patch on both sides of it (a slit); the second, elsewhere,
  // makes two disks.
  const auto [patches, cuts] = cut_until_disks(top, none);
  EXPECT_EQ(cuts, 2);
  ASSERT_EQ(patches.problem.size(), 2u);
  EXPECT_FALSE(patches.not_disk[0]);
  EXPECT_FALSE(patches.not_disk[1]);
}

TEST(LayoutPatches, AnAnnulusSlitOpenByATraceIsCutIntoTwoDisks) {
  // A trace from one border circle to the other (the line at angle 0) leaves one patch on
  // both of its sides: not a chart. One more cut, elsewhere, makes two disks.
  const TriangleMesh m = test::cylinder(2, 12, 4);
  const layout::SurfaceTopology top(m);
  std::vector<bool> slit(top.num_edges(), false);
  for (int h = 0; h < 3 * m.num_faces(); ++h)
    if (top.from(h) < 4 && top.to(h) == top.from(h) + 1) slit[top.edge(h)] = true;
  const auto [patches, cuts] = cut_until_disks(top, slit);
  EXPECT_EQ(cuts, 1);
  ASSERT_EQ(patches.problem.size(), 2u);
  EXPECT_FALSE(patches.not_disk[0]);
  EXPECT_FALSE(patches.not_disk[1]);
}

}  // namespace
}  // namespace bimdf
