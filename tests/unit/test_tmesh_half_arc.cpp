// Half-arc quantization (tmesh/half_arc.hpp): which paths become two-gons, the cut-open T-mesh,
// the optimum against a CBC MILP of the half-arc model written directly on the input T-mesh
// (a length per half-arc on the relaxed paths, sharing nothing with the inflation or the
// Bi-MDF model), the three validity conditions of §4.3, and never worse than Algorithm 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "bimdf/tmesh/from_quad_mesh.hpp"
#include "bimdf/tmesh/half_arc.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "test_helpers.hpp"
#include "tmesh_fixtures.hpp"
#include "tmesh_grid_support.hpp"

namespace bimdf::tmesh {
namespace {

using gridsupport::GridTMesh;
using gridsupport::milp_optimum;
using gridsupport::random_grid_tmesh;

// A 3 × 2 grid (random_grid_tmesh without merges or paths: horizontal arcs first, row by row
// — arcs 0–2 at y = 0, 3–5 at y = 1, 6–8 at y = 2 — then vertical ones column by column, two
// per column: arcs 9 + 2i and 10 + 2i at x = i).
GridTMesh three_by_two() {
  std::mt19937 rng(2);
  for (;;) {
    GridTMesh g = random_grid_tmesh(rng, 3, 2, 0);
    if (g.tmesh.num_patches() == 6) return g;  // no cells merged
  }
}

TEST(HalfArc, RelaxablePathsFollowTheRules) {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  t.nonzero_paths = {
      {2 * 3, 2 * 4},          // 0: y = 1 from x = 0 to 2, through the crossing (1, 1): relaxed
      {2 * 0, 2 * 1},          // 1: along the border
      {2 * 5},                 // 2: one arc
      {2 * 4 + 1, 2 * 3 + 1},  // 3: path 0 walked back: the same arcs
      {2 * 13, 2 * 14},        // 4: x = 2 from y = 0 to 2, through (2, 1): path 5 passes there too
      {2 * 4, 2 * 5},          // 5: shares arc 4 with paths 0 and 3
  };
  TMeshIncidence inc = validate_tmesh(t);
  // Path 0 represents itself and path 3 (its half-arc sequence is the smaller), but shares arc
  // 4 with path 5; path 4 crosses path 5 at (2, 1), which is not relaxed: so path 4 is for
  // bounded two-gons (which hold still there), not for exact ones.
  EXPECT_EQ(relaxable_paths(t, inc, true), std::vector<int>{4});
  EXPECT_EQ(relaxable_paths(t, inc, false), std::vector<int>{});
  t.nonzero_paths.pop_back();
  inc = validate_tmesh(t);
  EXPECT_EQ(relaxable_paths(t, inc, false), (std::vector<int>{0, 4}));
  // Order does not matter: the representative of paths 0 and 3 is chosen by its half-arcs.
  std::swap(t.nonzero_paths[0], t.nonzero_paths[3]);
  inc = validate_tmesh(t);
  EXPECT_EQ(relaxable_paths(t, inc, false), (std::vector<int>{3, 4}));
  // A path that turns is not relaxed: up x = 1, then right along y = 2 is on the border, so
  // up x = 1 from y = 0 and right along y = 1.
  t.nonzero_paths = {{2 * 11, 2 * 4}};
  inc = validate_tmesh(t);
  EXPECT_EQ(relaxable_paths(t, inc, true), std::vector<int>{});
  EXPECT_THROW(inflate_two_gons(t, inc, {0}), std::invalid_argument);
}

TEST(HalfArc, OfTwoCrossingPathsOneIsRelaxedAndTheOtherDetoursInTheCut) {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  // y = 1 from x = 1 to 3 and x = 2 from y = 0 to 2: they cross at (2, 1).
  t.nonzero_paths = {{2 * 4, 2 * 5}, {2 * 13, 2 * 14}};
  TMeshIncidence inc = validate_tmesh(t);
  const int crossing = t.half_arc_tail(2 * 5);
  ASSERT_EQ(crossing, t.half_arc_tail(2 * 14));
  // Both cross one line; the first by its arcs (4, 5 < 13, 14) is relaxed, in either order —
  // for bounded two-gons; exact ones take neither.
  EXPECT_EQ(relaxable_paths(t, inc, true), std::vector<int>{0});
  EXPECT_EQ(relaxable_paths(t, inc, false), std::vector<int>{});
  try {
    inflate_two_gons(t, inc, {0, 1});
    ADD_FAILURE() << "crossing paths were both relaxed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "inflate_two_gons: the lines of paths 0 and 1 cross at vertex " +
                  std::to_string(crossing) + "; of two crossing paths at most one can be relaxed");
  }
  const InflatedTMesh inflated = inflate_two_gons(t, inc, {0});
  const TMeshIncidence cut_inc = validate_tmesh(inflated.tmesh);  // every path a chain again
  const TwoGon& line = inflated.two_gons.at(0);
  // The crossing path reaches the right copy of (2, 1) from below, detours around the line's
  // tail (1, 1) and leaves the left copy upwards.
  EXPECT_EQ(inflated.tmesh.nonzero_paths[1],
            (std::vector<int>{2 * 13, TMesh::opposite(line.right[0]), line.left[0], 2 * 14}));
  EXPECT_EQ(line.path_crossing, (std::vector<char>{0, 1, 0}));
  EXPECT_EQ(drift_pins(line, false), (std::vector<char>{0, 1, 0}));
  // Deflated, the detour shrinks to the run between the crossing's two places on the line:
  // here none, as lengths that keep the crossing give it one place.
  std::vector<int64_t> length(inflated.tmesh.num_arcs(), 1);
  const DeflatedTMesh d = deflate_two_gons(inflated, length);
  EXPECT_EQ(check_quantization(d.tmesh, d.arc_length), "");
  EXPECT_EQ(d.tmesh.nonzero_paths[1].size(), 2u);
  // Split: the line's upper side 1 + 2, its lower side 2 + 1 (the rows' widths follow). The
  // crossing path's halves meet the line at 1 and 2 and, deflated, run along it in between.
  for (auto [a, x] : {std::pair{1, 2}, {2, 1}, {5, 2}, {8, 2}}) length[a] = x;
  length[TMesh::arc_of(line.right[0])] = 2;
  const DeflatedTMesh split = deflate_two_gons(inflated, length);
  EXPECT_NO_THROW(validate_tmesh(split.tmesh));
  EXPECT_EQ(check_quantization(split.tmesh, split.arc_length), "");
  ASSERT_EQ(split.tmesh.nonzero_paths[1].size(), 3u);
  EXPECT_EQ(split.arc_length[TMesh::arc_of(split.tmesh.nonzero_paths[1][1])], 1);
  std::swap(t.nonzero_paths[0], t.nonzero_paths[1]);
  inc = validate_tmesh(t);
  EXPECT_EQ(relaxable_paths(t, inc, true), std::vector<int>{1});
}

TEST(HalfArc, InflationCutsTheMeshOpenAlongEachPath) {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  t.nonzero_paths = {{2 * 3, 2 * 4, 2 * 5}};  // y = 1 across the mesh
  const TMeshIncidence inc = validate_tmesh(t);
  ASSERT_EQ(relaxable_paths(t, inc, false), std::vector<int>{0});
  const InflatedTMesh inflated = inflate_two_gons(t, inc, {0});
  const TMesh& cut = inflated.tmesh;
  const TMeshIncidence cut_inc = validate_tmesh(cut);
  EXPECT_EQ(cut.num_arcs(), t.num_arcs() + 3);
  EXPECT_EQ(cut.num_vertices(), t.num_vertices() + 2);  // (1, 1) and (2, 1)
  ASSERT_EQ(inflated.two_gons.size(), 1u);
  const TwoGon& two_gon = inflated.two_gons[0];
  EXPECT_EQ(two_gon.left, (std::vector<int>{6, 8, 10}));
  for (size_t i = 0; i < 3; ++i) {
    const int copy = TMesh::arc_of(two_gon.right[i]);
    EXPECT_EQ(inflated.arc_origin[copy], 3 + static_cast<int>(i));
    EXPECT_EQ(inflated.twin[copy], 3 + static_cast<int>(i));
    // Both sides face the two-gon: border half-arcs of T'.
    EXPECT_TRUE(cut_inc.is_border(TMesh::opposite(two_gon.left[i])));
    EXPECT_TRUE(cut_inc.is_border(two_gon.right[i]));
  }
  // The lower row's patches 0–2 now lie on the copies.
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(cut_inc.half_arc_patch[TMesh::opposite(two_gon.right[i])], i);
  // The vertical arcs at x = 1 and 2 below the path now end at the copies.
  EXPECT_EQ(inflated.vertex_origin[cut.arc_ends[11][1]], t.arc_ends[11][1]);
  EXPECT_NE(cut.arc_ends[11][1], t.arc_ends[11][1]);
  EXPECT_EQ(cut.arc_ends[12][0], t.arc_ends[12][0]);
}

// Two paths overlapping along y = 1 — x = 0 to 2 and, walked back, x = 3 to 1 — are relaxed
// together: one two-gon along their union, the first measured on the left up to x = 2, the
// second on the right from x = 1; in T' the second runs back along the right copies.
TEST(HalfArc, OverlappingPathsShareOneTwoGon) {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  t.nonzero_paths = {{2 * 5 + 1, 2 * 4 + 1}, {2 * 3, 2 * 4}};
  const TMeshIncidence inc = validate_tmesh(t);
  ASSERT_EQ(relaxable_paths(t, inc, false), (std::vector<int>{0, 1}));
  EXPECT_THROW(inflate_two_gons(t, inc, {0}), std::invalid_argument);  // not without path 1
  const InflatedTMesh inflated = inflate_two_gons(t, inc, {0, 1});
  ASSERT_EQ(inflated.two_gons.size(), 1u);
  const TwoGon& two_gon = inflated.two_gons[0];
  EXPECT_EQ(two_gon.left, (std::vector<int>{6, 8, 10}));  // the union, canonically oriented
  EXPECT_EQ(two_gon.paths, (std::vector<int>{1, 0}));
  EXPECT_EQ(two_gon.left_end, 2);
  EXPECT_EQ(two_gon.right_start, 1);
  EXPECT_EQ(inflated.tmesh.nonzero_paths[0],
            (std::vector<int>{two_gon.right[2] ^ 1, two_gon.right[1] ^ 1}));
  EXPECT_EQ(inflated.tmesh.nonzero_paths[1], t.nonzero_paths[1]);
  // A third path along the same line leaves neither relaxed.
  t.nonzero_paths.push_back({2 * 4});
  EXPECT_EQ(relaxable_paths(t, validate_tmesh(t), true), std::vector<int>{});
}

// The random grid T-mesh of a trial: sizes and paths cycling with `trial`, and on three trials
// of four short targets, so that arcs collapse and the paths' min-one binds.
GridTMesh trial_tmesh(std::mt19937& rng, int trial) {
  GridTMesh g = random_grid_tmesh(rng, 2 + trial % 4, 2 + (trial / 4) % 3, 1 + trial % 6);
  if (trial % 4 != 0)
    for (double& x : g.tmesh.arc_target) x *= 0.25;
  return g;
}

// Two paths overlapping partially along an inner horizontal grid line (horizontal arcs are
// numbered row by row, random_grid_tmesh), the second walked either way; nothing without an
// inner line of three arcs or more.
void add_overlapping_pair(GridTMesh& g, std::mt19937& rng) {
  if (g.rows < 2 || g.columns < 3) return;
  const int j = 1 + static_cast<int>(rng() % (g.rows - 1));
  const int s = 1 + static_cast<int>(rng() % (g.columns - 2));  // the second starts at x = s
  const int e = s + 1 + static_cast<int>(rng() % (g.columns - 1 - s));  // the first ends at e
  std::vector<int> first, second;
  for (int i = 0; i < e; ++i) first.push_back(2 * (j * g.columns + i));
  for (int i = s; i < g.columns; ++i) second.push_back(2 * (j * g.columns + i));
  if (rng() % 2) {
    std::reverse(second.begin(), second.end());
    for (int& h : second) h ^= 1;
  }
  g.tmesh.nonzero_paths.push_back(first);
  g.tmesh.nonzero_paths.push_back(second);
}

QuantizeOptions trial_options(int trial) {
  QuantizeOptions o;
  o.cost = trial % 2 ? DeviationCost::Absolute : DeviationCost::Quadratic;
  o.side_weight = trial % 3 == 0 ? 0.0 : 1.0 + trial % 4;
  return o;
}

// Two-gons whose sides differ somewhere (a half-arc's length not its opposite's).
int drifting_two_gons(const HalfArcQuantization& h) {
  int drifting = 0;
  for (const TwoGon& two_gon : h.inflated.two_gons)
    for (int half : two_gon.left)
      if (h.half_arc_length[half] != h.half_arc_length[TMesh::opposite(half)]) {
        ++drifting;
        break;
      }
  return drifting;
}

// Random grid T-meshes: the half-arc optimum, exact or bounded, equals the CBC oracle of the
// half-arc model (with the same bounds for the paths that are not relaxed), passes the three
// validity conditions, and is never worse than Algorithm 2's quantization.
TEST(HalfArc, OptimumEqualsTheMilpOracleAndNeverLosesToGreedy) {
  std::mt19937 rng(17);
  int relaxed = 0, better = 0, tied = 0, pairs = 0;
  for (int trial = 0; trial < testing::scaled(160); ++trial) {
    GridTMesh g = trial_tmesh(rng, trial);
    if (trial % 3 == 1) add_overlapping_pair(g, rng);
    const TMesh& t = g.tmesh;
    const TMeshIncidence inc = validate_tmesh(t);
    const QuantizeOptions o = trial_options(trial);
    // Exact two-gons on half of the trials, bounded ones (reordering free, or at a cost) on the
    // others.
    const double reorder = trial % 2 ? -1.0 : 0.5 * (trial % 3);
    const HalfArcQuantization h = quantize_half_arcs(t, inc, o, reorder, trial % 4 == 0);
    ASSERT_EQ(h.quantization.status, SolveStatus::Optimal) << "trial " << trial;
    ASSERT_EQ(check_half_arc_quantization(t, h.inflated.two_gons, h.half_arc_length), "")
        << "trial " << trial;
    // Bounded two-gons do not drift at their pins (drift_pins).
    std::vector<std::vector<char>> pinned;
    for (const TwoGon& two_gon : h.inflated.two_gons)
      pinned.push_back(drift_pins(two_gon, h.keep_crossings));
    const double oracle =
        milp_optimum(t, o.cost, o.side_weight, &h.quantization.constraints, 12, -1,
                     &h.inflated.two_gons, &h.inflated.arc_origin, reorder, &pinned);
    ASSERT_TRUE(testing::relatively_close(h.quantization.objective, oracle))
        << "trial " << trial << ": " << h.quantization.objective << " vs CBC " << oracle;
    const TMeshQuantization greedy = quantize_tmesh(t, inc, o);
    ASSERT_LE(h.quantization.objective, greedy.objective + 1e-9) << "trial " << trial;
    // The exact model's tie-break: no better than greedy means no drift (HalfArcSetup).
    if (reorder < 0 && testing::relatively_close(h.quantization.objective, greedy.objective)) {
      ASSERT_EQ(drifting_two_gons(h), 0) << "trial " << trial;
      tied += !h.relaxed.empty();
    }
    relaxed += !h.relaxed.empty();
    for (const TwoGon& two_gon : h.inflated.two_gons) pairs += two_gon.paths.size() == 2;
    better += h.quantization.objective < greedy.objective - 1e-9;
  }
  std::printf(
      "%d of %d with relaxed paths (%d overlapping pairs), %d better than greedy, %d "
      "exact ones tied\n",
      relaxed, testing::scaled(160), pairs, better, tied);
  EXPECT_GT(relaxed, testing::scaled(160) / 3);
  EXPECT_GT(pairs, testing::scaled(160) / 16);
  EXPECT_GT(better, 0);
}

// Aligned two-gons (the half-arc repair): aligning a random part of the exact two-gons never
// lowers the optimum nor lets it exceed greedy's; aligned sides are equal copy by copy; and
// with every two-gon aligned the optimum is the oracle's with both sides pinned together at
// every vertex of every path (an arc quantization along them, with Algorithm 2's bounds).
TEST(HalfArc, AlignedTwoGonsHoldAnArcQuantizationAlongTheirPaths) {
  std::mt19937 rng(23);
  int aligned_trials = 0, raised = 0;
  // At least 40 trials, so that a scaled-down run still sees aligning raise an optimum.
  const int trials = std::max(40, testing::scaled(120));
  for (int trial = 0; trial < trials; ++trial) {
    GridTMesh g = trial_tmesh(rng, trial);
    if (trial % 2 == 1) add_overlapping_pair(g, rng);
    const TMesh& t = g.tmesh;
    const TMeshIncidence inc = validate_tmesh(t);
    const QuantizeOptions o = trial_options(trial);
    HalfArcSetup setup = prepare_half_arcs(t, inc);
    const int n = static_cast<int>(setup.inflated.two_gons.size());
    if (n == 0) continue;
    ++aligned_trials;
    const TMeshQuantization exact = quantize_inflated(setup, o);
    const TMeshQuantization greedy = quantize_tmesh(t, inc, o);
    ASSERT_EQ(exact.status, SolveStatus::Optimal) << "trial " << trial;
    std::vector<int> some;
    for (int k = 0; k < n; ++k)
      if (rng() % 2) some.push_back(k);
    const bool all = trial % 3 == 0;
    if (all || some.empty()) {
      some.clear();
      for (int k = 0; k < n; ++k) some.push_back(k);
    }
    ASSERT_EQ(align_two_gons(setup, t, inc, some), static_cast<int>(some.size()));
    ASSERT_EQ(align_two_gons(setup, t, inc, some), 0);  // already aligned
    const TMeshQuantization q = quantize_inflated(setup, o);
    ASSERT_EQ(q.status, SolveStatus::Optimal) << "trial " << trial;
    ASSERT_GE(q.objective, exact.objective - 1e-9) << "trial " << trial;
    ASSERT_LE(q.objective, greedy.objective + 1e-9) << "trial " << trial;
    raised += q.objective > exact.objective + 1e-9;
    const std::vector<int64_t> half = half_arc_lengths(t, setup.inflated, q.arc_length);
    ASSERT_EQ(check_half_arc_quantization(t, setup.inflated.two_gons, half), "")
        << "trial " << trial;
    for (int k : some) {
      const TwoGon& two_gon = setup.inflated.two_gons[k];
      for (size_t i = 0; i < two_gon.left.size(); ++i)
        ASSERT_EQ(q.arc_length[TMesh::arc_of(two_gon.left[i])],
                  q.arc_length[TMesh::arc_of(two_gon.right[i])])
            << "trial " << trial << ", two-gon " << k << ", arc " << i;
    }
    if (static_cast<int>(some.size()) != n) continue;
    std::vector<std::vector<char>> pinned;
    for (const TwoGon& two_gon : setup.inflated.two_gons)
      pinned.emplace_back(two_gon.left.size() + 1, 1);
    const double oracle =
        milp_optimum(t, o.cost, o.side_weight, &q.constraints, 12, -1, &setup.inflated.two_gons,
                     &setup.inflated.arc_origin, 0.0, &pinned);
    ASSERT_TRUE(testing::relatively_close(q.objective, oracle))
        << "trial " << trial << ": " << q.objective << " vs CBC " << oracle;
  }
  EXPECT_GT(aligned_trials, trials / 4);
  EXPECT_GT(raised, 0);  // aligning takes away solutions the exact model used
}

// T-meshes traced on random quad meshes, both graphs, plain and coarse: the inflated T-mesh
// validates, the quantization is valid, and never worse than Algorithm 2's.
TEST(HalfArc, TracedRandomMeshesNeverLoseToGreedy) {
  std::mt19937 rng(9);
  int relaxed = 0, tied = 0;
  for (uint64_t seed = 0; seed < uint64_t(testing::scaled(120)); ++seed) {
    TraceOptions trace;
    trace.density = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    if (seed % 2 == 0) trace.max_angle_deg = 10.0 * (1 + seed % 5);
    const TracedTMesh traced = trace_tmesh(test::random_quad_mesh(seed), trace, "random");
    const TMesh& t = traced.tmesh;
    const TMeshIncidence inc = validate_tmesh(t);
    QuantizeOptions o;
    o.coarse = seed % 4 == 0;
    const HalfArcQuantization h = quantize_half_arcs(t, inc, o);
    ASSERT_EQ(h.quantization.status, SolveStatus::Optimal) << "seed " << seed;
    ASSERT_EQ(check_half_arc_quantization(t, h.inflated.two_gons, h.half_arc_length), "")
        << "seed " << seed;
    const TMeshQuantization greedy = quantize_tmesh(t, inc, o);
    const double half_arc_value =
        o.coarse ? h.quantization.coarse_objective : h.quantization.objective;
    const double greedy_value = o.coarse ? greedy.coarse_objective : greedy.objective;
    ASSERT_LE(half_arc_value, greedy_value + 1e-9) << "seed " << seed;
    if (testing::relatively_close(half_arc_value, greedy_value)) {
      ASSERT_EQ(drifting_two_gons(h), 0) << "seed " << seed;  // the tie-break (HalfArcSetup)
      tied += !h.relaxed.empty();
    }
    relaxed += static_cast<int>(h.relaxed.size());
  }
  std::printf("%d paths relaxed, %d ties with greedy\n", relaxed, tied);
  EXPECT_GT(relaxed, 0);
  EXPECT_GT(tied, 0);
}

// The arc lengths of T' for a half-arc quantization of the input (half_arc_lengths' inverse).
std::vector<int64_t> inflated_lengths(const InflatedTMesh& inflated,
                                      const std::vector<int64_t>& half_arc_length) {
  std::vector<int64_t> x(inflated.arc_origin.size());
  for (size_t a = 0; a < x.size(); ++a) x[a] = half_arc_length[2 * inflated.arc_origin[a]];
  for (const TwoGon& g : inflated.two_gons)
    for (size_t i = 0; i < g.left.size(); ++i) {
      x[TMesh::arc_of(g.left[i])] = half_arc_length[g.left[i]];
      x[TMesh::arc_of(g.right[i])] = half_arc_length[TMesh::opposite(g.left[i])];
    }
  return x;
}

// Quads, vertices and the valence of every vertex, sorted: what two collapses of one
// quantization must share.
std::vector<int> mesh_signature(const QuadMesh& m) {
  std::vector<int> valence(m.num_vertices(), 0);
  for (const auto& q : m.quads)
    for (int v : q) ++valence[v];
  std::sort(valence.begin(), valence.end());
  valence.push_back(m.num_quads());
  valence.push_back(m.num_vertices());
  return valence;
}

// Per patch and side, the lengths of its arcs in order: the deflated T-mesh up to the
// numbering of its vertices and arcs (its patches keep the input's ids).
std::vector<std::vector<int64_t>> side_signature(const DeflatedTMesh& d) {
  std::vector<std::vector<int64_t>> out;
  for (const auto& sides : d.tmesh.patch_sides)
    for (const auto& side : sides) {
      out.emplace_back();
      for (int h : side) out.back().push_back(d.arc_length[TMesh::arc_of(h)]);
    }
  return out;
}

// The grid of JunctionsTradePlacesAcrossAPathWhereArcsCannot (below): its optimum moves one
// T-junction across a path.
TMesh traded_junction_grid() {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  for (int a = 0; a < 9; ++a) t.arc_target[a] = 1;
  for (int i = 0; i <= 3; ++i) t.arc_target[9 + 2 * i] = 0.6, t.arc_target[10 + 2 * i] = 0.2;
  t.nonzero_paths = {{2 * 10}, {2 * 13, 2 * 14}};
  return t;
}

// Random grid T-meshes with short targets, and first the grid whose optimum moves a T-junction
// across a path: the deflated T-mesh validates, carries a valid arc
// quantization, collapses into the same quad mesh as T' closed by its zips, and does not
// depend on the order of the paths (10 shuffles, the same half-arc lengths).
TEST(HalfArc, DeflationIsAValidArcQuantizationInAnyPathOrder) {
  std::mt19937 rng(23);
  int reordered = 0, deflated = 0, detoured = 0;
  for (int trial = -1; trial < testing::scaled(150); ++trial) {
    GridTMesh g{traded_junction_grid(), 3, 2};
    if (trial >= 0) g = random_grid_tmesh(rng, 2 + trial % 4, 2 + (trial / 4) % 3, 2 + trial % 6);
    if (trial % 2 == 1) add_overlapping_pair(g, rng);
    TMesh& t = g.tmesh;
    if (trial >= 0)
      for (double& x : t.arc_target) x *= trial % 2 ? 0.3 : 1.0;
    const TMeshIncidence inc = validate_tmesh(t);
    // Exact two-gons, and every third trial bounded ones (along crossed lines too).
    const HalfArcQuantization h = quantize_half_arcs(t, inc, {}, trial % 3 == 2 ? 0.5 : -1);
    ASSERT_EQ(h.quantization.status, SolveStatus::Optimal);
    if (h.relaxed.empty()) continue;
    ++deflated;
    const DeflatedTMesh d = deflate_two_gons(h.inflated, h.quantization.arc_length);
    ASSERT_NO_THROW(validate_tmesh(d.tmesh)) << "trial " << trial;
    ASSERT_EQ(check_quantization(d.tmesh, d.arc_length), "") << "trial " << trial;
    reordered += d.reordered_junctions;
    // Paths crossing a line detour in T' (bounded); the crossing holds, so deflated they do not.
    for (size_t m = 0; m < t.nonzero_paths.size(); ++m) {
      if (h.inflated.tmesh.nonzero_paths[m].size() == t.nonzero_paths[m].size()) continue;
      ++detoured;
      ASSERT_EQ(d.tmesh.nonzero_paths[m].size(), t.nonzero_paths[m].size()) << "trial " << trial;
    }
    std::vector<Zip> zips;
    for (const TwoGon& two_gon : h.inflated.two_gons) zips.push_back(two_gon_zip(two_gon));
    std::vector<int> zipped, plain;
    try {
      zipped =
          mesh_signature(collapse_and_tessellate(h.inflated.tmesh, h.incidence,
                                                 h.quantization.arc_length, nullptr, false, zips)
                             .mesh);
    } catch (const CollapseError&) {
      // Not every quantization collapses into a mesh (separation repair is requantize's);
      // then neither must the deflated T-mesh.
      EXPECT_THROW(collapse_and_tessellate(d.tmesh, validate_tmesh(d.tmesh), d.arc_length, nullptr),
                   CollapseError)
          << "trial " << trial;
      continue;
    }
    plain = mesh_signature(
        collapse_and_tessellate(d.tmesh, validate_tmesh(d.tmesh), d.arc_length, nullptr).mesh);
    ASSERT_EQ(zipped, plain) << "trial " << trial;
    const auto signature = side_signature(d);
    for (int shuffle = 0; shuffle < 10; ++shuffle) {
      TMesh s = t;
      std::shuffle(s.nonzero_paths.begin(), s.nonzero_paths.end(), rng);
      const TMeshIncidence s_inc = validate_tmesh(s);
      const InflatedTMesh inflated =
          inflate_two_gons(s, s_inc, relaxable_paths(s, s_inc, h.reorder_weight >= 0));
      const DeflatedTMesh sd =
          deflate_two_gons(inflated, inflated_lengths(inflated, h.half_arc_length));
      ASSERT_EQ(side_signature(sd), signature) << "trial " << trial << ", shuffle " << shuffle;
      ASSERT_EQ(sd.tmesh.num_vertices(), d.tmesh.num_vertices());
      ASSERT_EQ(sd.reordered_junctions, d.reordered_junctions);
    }
  }
  std::printf("%d deflated, %d junctions reordered, %d paths detour\n", deflated, reordered,
              detoured);
  EXPECT_GT(deflated, testing::scaled(150) / 4);
  EXPECT_GT(reordered, 0);  // the first grid's, at least
  EXPECT_GT(detoured, 0);
}

// In the spirit of the paper's Fig. 11: a 3 × 2 grid whose upper row is thin (0.2 against
// 0.6), a non-zero path up its left border there, and one up x = 2 across both rows. Arc
// quantization keeps both rows (the left path holds the upper row open everywhere, and the
// lower row cannot take the whole height alone), six quads. Half-arc quantization lets the
// line between the rows meet x = 2 at different heights on its two sides: west of it the lower
// row collapses, east of it the upper one, three quads — every path still non-zero.
TEST(HalfArc, JunctionsTradePlacesAcrossAPathWhereArcsCannot) {
  const TMesh t = traded_junction_grid();
  const TMeshIncidence inc = validate_tmesh(t);
  const TMeshQuantization greedy = quantize_tmesh(t, inc, {});
  EXPECT_EQ(greedy.zero_arcs, 0);
  EXPECT_EQ(collapse_and_tessellate(t, inc, greedy.arc_length, nullptr).mesh.num_quads(), 6);

  const HalfArcQuantization h = quantize_half_arcs(t, inc, {});
  ASSERT_EQ(h.relaxed, std::vector<int>{1});
  EXPECT_LT(h.quantization.objective, greedy.objective);
  // Along x = 2, going up: west (left) side 0 then 1, east side 1 then 0.
  EXPECT_EQ(h.half_arc_length[2 * 13], 0);
  EXPECT_EQ(h.half_arc_length[2 * 14], 1);
  EXPECT_EQ(h.half_arc_length[2 * 13 + 1], 1);
  EXPECT_EQ(h.half_arc_length[2 * 14 + 1], 0);
  const Zip zip = two_gon_zip(h.inflated.two_gons[0]);
  const CollapsedMesh zipped = collapse_and_tessellate(
      h.inflated.tmesh, h.incidence, h.quantization.arc_length, nullptr, false, {zip});
  EXPECT_EQ(zipped.mesh.num_quads(), 3);
  const DeflatedTMesh d = deflate_two_gons(h.inflated, h.quantization.arc_length);
  EXPECT_EQ(d.reordered_junctions, 1);  // the east end of the line between the rows
  EXPECT_EQ(check_quantization(d.tmesh, d.arc_length), "");
  EXPECT_EQ(collapse_and_tessellate(d.tmesh, validate_tmesh(d.tmesh), d.arc_length, nullptr)
                .mesh.num_quads(),
            3);
  // (2, 1) is a crossing: bounded two-gons that keep crossings leave it in place even when
  // drifting is free, and the line between the rows stays straight — greedy's optimum again.
  // Even with crossings free to drift, bounded ones stay there: they keep Algorithm 2's bound
  // for the path up x = 2 (the side of patch 1 along it), which holds the lower row open east
  // of it — the exactness that only the exact two-gon has.
  EXPECT_NEAR(quantize_half_arcs(t, inc, {}, 0.0).quantization.objective, greedy.objective, 1e-9);
  const HalfArcQuantization bounded = quantize_half_arcs(t, inc, {}, 0.0, true);
  EXPECT_EQ(bounded.inflated.two_gons[0].crossing, (std::vector<char>{0, 1, 0}));
  EXPECT_NEAR(bounded.quantization.objective, greedy.objective, 1e-9);
  EXPECT_EQ(bounded.half_arc_length[2 * 13], bounded.half_arc_length[2 * 13 + 1]);
}

TEST(HalfArc, CheckNamesTheBrokenCondition) {
  GridTMesh g = three_by_two();
  TMesh& t = g.tmesh;
  t.nonzero_paths = {{2 * 3, 2 * 4, 2 * 5}};
  const TMeshIncidence inc = validate_tmesh(t);
  const HalfArcQuantization h = quantize_half_arcs(t, inc, {});
  std::vector<int64_t> H = h.half_arc_length;
  const std::vector<TwoGon>& lines = h.inflated.two_gons;
  ASSERT_EQ(check_half_arc_quantization(t, lines, H), "");
  H[6] += 1;  // the path's left side grows at arc 3, and patch 3's bottom with it
  EXPECT_EQ(check_half_arc_quantization(t, lines, H).substr(0, 8), "patch 3:");
  H[13] += 1;  // patch 3's top (arc 6, on the border) too: the path's sides differ
  EXPECT_EQ(check_half_arc_quantization(t, lines, H),
            "the line of path 0: its sides have lengths " + std::to_string(H[6] + H[8] + H[10]) +
                " and " + std::to_string(H[7] + H[9] + H[11]));
  // Not relaxed, arc 3's half-arcs must be equal.
  EXPECT_EQ(check_half_arc_quantization(t, {}, H).substr(0, 6), "arc 3:");
  H[2 * 9 + 1] = -1;
  EXPECT_EQ(check_half_arc_quantization(t, lines, H), "half-arc 19: negative length -1");
}

}  // namespace
}  // namespace bimdf::tmesh
