// Half-arc quantization of a quad T-mesh (paper §4.3, Fig. 11–12, Appendix A): the two sides of
// a non-zero path are quantized separately, so that T-junctions on opposite sides of it may
// trade places, and the path's own length — not a greedy choice of arcs and sides — carries its
// min-one constraint.
//
// Model (Fig. 12a). Each *relaxed* path is inflated into a virtual two-gon: the T-mesh is cut
// open along it (inflate_two_gons), every arc of the path becomes two arcs — the left copy,
// on the patches to the path's left, and the right copy — and every interior vertex of the path
// two vertices. The cut-open T-mesh T' is an ordinary quad T-mesh whose arc lengths are the
// half-arc lengths of the input. Its Bi-MDF model is the arc model (quantize.hpp) of T', where the
// cut half-arcs, instead of being border, join the two nodes of their two-gon, tied by an edge of
// lower bound 1 whose flow is the path's length: Σ left copies = Σ right copies ≥ 1, exactly
// the three validity conditions of §4.3 (opposite half-arcs off every path equal, opposite
// sides of every patch equal, both sides of every path equal) and the path's min-one.
//
// Which paths are relaxed (relaxable_paths). The two-gon realises a path's length as one edge,
// so the deflated T-mesh must place the path's ends where the model measures them; that holds
// for a path that (a) runs along two or more arcs, none on the border or a feature curve (whose
// two sides the smoothing keeps apart, and across whose sharp edge T-junctions should not
// trade places: relaxed, they left degenerate quads on 10 of 17 shared layouts at 35°, see
// docs/benchmarks.md), (b) is straight at each interior vertex (180° on either side: no patch
// corner, or two, on each side), (c) shares no arc with another path — except that two paths
// overlapping partially along one line (each reaching past the other's end, sharing arcs with
// each other only) are relaxed together, as one two-gon along their union — and (d) crosses no
// other relaxed line. §4.3 stacks the second path's two-gon on the first one's: each path's
// length is then its own two-gon's, which is the sum of one real side — the outer one. So in
// the merged two-gon (Appendix A, step 1) the path from the line's tail is measured on the left
// (the left copies up to its end) and the other on the right (the right copies from its start),
// each by one network edge: the left copies flow along a chain of nodes into a hub at the first
// path's end, so that each chain edge carries a prefix sum of the left side, the hub's edge to
// the right side's hub carries the line's length, and the right copies leave along a chain from
// a hub at the second path's start (suffix sums).
// Rule (d) is not a limit of the construction but of what a valid half-arc quantization can
// deflate into: where two relaxed lines cross, each may split the crossing along itself — the
// horizontal line's sides meet the vertical one at heights y_left, y_right, the vertical line's
// meet the horizontal one at x_above, x_below — and both splits together are realisable only
// as a pinwheel around a small patch, whose turning sense ties the signs of the two drifts: of
// the four sign combinations two would need a patch corner of 270°. That coupling is not
// convex, so no network models it; nor even one fixed turning sense: bounding a drift's sign
// (or pinning it to 0) needs an edge carrying the drift at that vertex beside the edge carrying
// the line's length, and the two split the line's half-arcs in crossing ways (left vs right;
// before vs after the vertex), which the edges of one flow network cannot do while each still
// carries exactly its sum. So of crossing paths one is relaxed (a maximal set of lines
// crossing none of each other, chosen by the lines' arcs: fewest crossings first), and the
// other keeps Algorithm 2's bounds — for bounded two-gons, which then hold still where a path
// crosses them (drift_pins): of the multi-arc paths of the 23 shared layouts traced at 35°, 73%
// are relaxed, against 53% when neither of two crossing paths is. An exact two-gon cannot hold
// still at one vertex (that needs the drift edge above), and drifting where a non-zero path
// crosses it — splitting the crossing of two separatrices — its quads fold (blade at 10°: 5th
// percentile of the scaled Jacobian 0.97 → 0.32, minutes of repairs); so exact two-gons go
// only along lines no other path crosses (relaxable_paths' `crossed` false). In T' a path crossing
// a line reaches the crossing on one side of the cut and leaves it on the other: it detours
// around the line's nearer end (along one side and back along the other), which keeps it a
// chain; deflated, the detour shrinks to the run between the crossing's two places. Three or
// more paths overlapping are not relaxed. Paths of one arc are exact without a two-gon (the
// arc's own lower bound). Every other path keeps the bounds of Algorithm 2
// (greedy_min_one_constraints on the whole T-mesh) that cover it, so that any quantization
// satisfying Algorithm 2's bounds stays feasible: the half-arc optimum is never worse than the
// greedy one. Identical paths (the same arcs, e.g. walked both ways) count once.
//
// Deflation (deflate_two_gons, Appendix A): every two-gon closes again — along each relaxed
// path, the left copy's vertices and the right copy's vertices are merged in the order of their
// positions (ties: left first), each run between two consecutive positions becoming one arc of
// their difference in length. The result is an arc-quantized T-mesh with the same patches, in
// which the T-junctions of the path's right side have moved to their quantized places and
// crossings of the path have split into two T-junctions. It depends only on the lengths, not on
// the order of the paths. Re-embedding is done in the patches' own parameter domains: every
// patch keeps its rectangle of the input grid, and collapse_and_tessellate (collapse.hpp) closes
// the two-gons of T' point by point (its `zips`) when it tessellates; the deflated T-mesh
// carries the topology and the arc quantization, not the geometry.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/quantize.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh {

// A non-zero path cut open (inflate_two_gons): the half-arcs of T' along its two sides, both
// walked from the path's tail to its head, position by position the same line. `left` lie on
// the patches left of the path (the input's half-arc ids), `right` are the border half-arcs of
// the right copies (the patches to the right lie on their opposites).
struct TwoGon {
  // The relaxed paths it holds (indices into the input's nonzero_paths): one, along the whole
  // line, or two overlapping ones (see above): paths[0] from the line's tail to its vertex
  // `left_end`, measured on the left, and paths[1] from vertex `right_start` (< left_end) to the
  // line's head, measured on the right. Alone, −1 both.
  std::vector<int> paths;
  int left_end = -1, right_start = -1;
  std::vector<int> left, right;
  // Per vertex of the path (0..n, the ends included as 0): 1 where arcs leave it on both sides
  // — a crossing, which a bounded two-gon can keep in place (HalfArcSetup::keep_crossings).
  std::vector<char> crossing;
  // Per vertex of the path: 1 where a non-zero path that is not relaxed crosses it (rule (d)).
  std::vector<char> path_crossing;
};

// The two-gon's zip for collapse_and_tessellate (collapse.hpp): its two sides of border
// half-arcs, each walked with the two-gon on its left — the right copies' from the path's tail
// to its head, then the left copies' back.
Zip two_gon_zip(const TwoGon& two_gon);

struct InflatedTMesh {
  // T': the input cut open along every relaxed path. Arcs and vertices of the input keep their
  // ids (a path's arcs become its left copies, its interior vertices their left copies); the
  // right copies follow. Its nonzero_paths: the relaxed paths along their left copies, the
  // others as in the input (re-routed through the right copies where they start or end there,
  // and around a line's end where they cross it).
  TMesh tmesh;
  std::vector<TwoGon> two_gons;
  std::vector<int> arc_origin;     // per T' arc: the input arc it copies
  std::vector<int> vertex_origin;  // per T' vertex: the input vertex it copies
  // Per T' arc: the other copy of the same input arc, or −1 for an arc that was not cut.
  std::vector<int> twin;
};

// The paths to relax (rules above), as sorted indices into tmesh.nonzero_paths; of identical
// paths only the first; both of an overlapping pair; of crossing ones, those rule (d) chooses —
// with `crossed`, else none that any other path crosses (for exact two-gons, see above).
// Deterministic, and independent of the order of the paths.
std::vector<int> relaxable_paths(const TMesh& tmesh, const TMeshIncidence& incidence, bool crossed);

// Cuts the T-mesh open along `paths` (from relaxable_paths; throws std::invalid_argument for a
// path that breaks rules (a)–(c), one of an overlapping pair without the other, or two paths
// whose lines cross): one two-gon per
// path alone, in the order given, or per pair, at its first path. Patch grids and arc chains
// carry over (a right copy has its arc's chain), so T' validates like the input.
InflatedTMesh inflate_two_gons(const TMesh& tmesh, const TMeshIncidence& incidence,
                               const std::vector<int>& paths);

// The bounds of Algorithm 2 that the half-arc model keeps (see above), in T''s ids: those of
// greedy_min_one_constraints(tmesh) covering a path of two or more arcs that is not relaxed
// or whose two-gon has no edges carrying its paths' lengths (`bounded`, per two-gon of
// `inflated`: a bounded or aligned one; empty: none), plus a min-one bound on the arc of every
// one-arc path. An arc bound on a cut arc — both of whose copies ≥ 1 would undo the cut —
// becomes bounds on the sides holding its two copies where it covers a path that is not relaxed
// (it implies that path through those sides), and a bound on the copy on the side a relaxed
// path is measured on where it covers one (its left copy, the arc's own id, for a path alone,
// whose two sides are equal).
MinOneConstraints half_arc_bounds(const TMesh& tmesh, const TMeshIncidence& incidence,
                                  const InflatedTMesh& inflated,
                                  const std::vector<char>& bounded = {});

// Per input half-arc, its length under a quantization of T' (`arc_length`, one per T' arc):
// an uncut arc gives both of its half-arcs its length, a cut arc each half-arc its copy's.
std::vector<int64_t> half_arc_lengths(const TMesh& tmesh, const InflatedTMesh& inflated,
                                      const std::vector<int64_t>& arc_length);

// Checks a half-arc quantization of the input (one length per half-arc; a border half-arc's is
// ignored), independently of any model: every length ≥ 0; the opposite half-arcs of every arc
// off the two-gons' lines equal; opposite sides of every patch equal (summed over the half-arcs
// on them); along every line both sides equal; every relaxed path ≥ 1 on the side it is measured
// on (a path alone: either); every other path ≥ 1 (its arcs' lengths summed, their half-arcs
// being equal; a path with the same arcs as a relaxed one is that path). Returns "" when valid,
// else the first violation ("the line of path 3: its sides have lengths 4 and 5").
std::string check_half_arc_quantization(const TMesh& tmesh, const std::vector<TwoGon>& two_gons,
                                        const std::vector<int64_t>& half_arc_length);

// The half-arc model of a T-mesh, before any solve: every relaxable path made a two-gon, T'
// with its incidence, and the bounds kept for the other paths (half_arc_bounds, T' ids).
//
// `reorder_weight` < 0: exact two-gons (Fig. 12a). ≥ 0: bounded ones (Fig. 12b): every unit by
// which the two sides of a path drift apart at one of its vertices costs this much (0: free,
// large: an arc quantization), and every path keeps Algorithm 2's bounds instead of its
// two-gon's min-one — T-junctions trade places only where that pays for itself. It does not
// drift (drift_pins) at the inner ends of an overlapping pair (so both paths' sides sum
// equally, and Algorithm 2's bounds on either side hold them), nor where another non-zero path
// crosses it (rule (d)): that splits the crossing of two separatrices, and measured on the
// shared layouts it left inverted or degenerate quads on 10 of 92 coarse runs (blade 10°: p5
// of the scaled Jacobian 0.97 → 0.32) for a few percent more base-complex reduction. With
// keep_crossings, a bounded two-gon does not drift at any crossing (a path vertex with arcs on
// both sides): splitting one into two T-junctions breaks a straight line of the layout in two.
// Measured (docs/benchmarks.md), that keeps every coarse base complex near greedy's, where
// drifting crossings shrink most of them by 20–25%.
//
// `aligned` (per two-gon, all 0 at first): two-gons held to an arc quantization along their
// path — sides equal half-arc by half-arc, the path kept by Algorithm 2's bounds again — where
// the re-embedding could not follow the drift (align_two_gons).
//
// Exact two-gons have no term for drift, and where equally good solutions abound (coarse
// layouts) the solver's may drift for nothing. So an exact solve is followed by a bounded one
// with every path under Algorithm 2's bounds (`greedy_bounds`) and each unit of drift costing
// kDriftTieBreak: when that is as good (both objectives within 1e-9, relative, drift cost left
// out), its solution — an optimum of the exact model too, as its feasible set lies inside the
// exact one's, with the least drift among those — is returned. Whenever the exact optimum is
// no better than greedy's, the result therefore has no drift at all (greedy's own solution is
// a candidate).
struct HalfArcSetup {
  std::vector<int> relaxed;  // the input's paths made two-gons (relaxable_paths)
  InflatedTMesh inflated;
  TMeshIncidence incidence;  // of inflated.tmesh
  MinOneConstraints bounds;
  MinOneConstraints greedy_bounds;  // half_arc_bounds with every two-gon bounded
  double reorder_weight = -1;
  bool keep_crossings = false;
  std::vector<char> aligned;
};
HalfArcSetup prepare_half_arcs(const TMesh& tmesh, const TMeshIncidence& incidence,
                               double reorder_weight = -1, bool keep_crossings = false);

// The vertices (0..n along the two-gon's line) where a bounded or tie-breaking two-gon does not
// drift (see above): those a non-zero path crosses, an overlapping pair's inner ends, and with
// keep_crossings every crossing.
std::vector<char> drift_pins(const TwoGon& two_gon, bool keep_crossings);

// The drift cost of the exact model's tie-break (HalfArcSetup): small enough that drift never
// outweighs an objective's difference in practice (coarse objectives move in steps of ¼ at
// least; 10⁵ units of drift cost 0.1), while the solver still sees it.
inline constexpr double kDriftTieBreak = 1e-6;

// Aligns the two-gons `two_gons` (indices into setup.inflated.two_gons) and recomputes
// setup.bounds (half_arc_bounds; `tmesh` and `incidence` are the input setup was prepared
// from). Returns how many were not aligned before. Aligning every two-gon gives a model whose
// feasible set contains the greedy one's (the arc model with Algorithm 2's bounds): more
// aligned two-gons never lower the optimum, and all of them keep it ≤ greedy's.
int align_two_gons(HalfArcSetup& setup, const TMesh& tmesh, const TMeshIncidence& incidence,
                   const std::vector<int>& two_gons);

// Sets which two-gons are aligned (one flag per two-gon; all 0: none, as prepared) and
// setup.bounds to match: Algorithm 2's bounds for every path when bounded, else for the paths
// of aligned two-gons (half_arc_bounds). `tmesh`, `incidence`: as for align_two_gons.
void set_aligned(HalfArcSetup& setup, const TMesh& tmesh, const TMeshIncidence& incidence,
                 std::vector<char> aligned);

// T''s incidence with every half-arc facing a two-gon counted on the patch across it (the side
// its twin's other half-arc lies on): what the separation repairs and smoothing must see, for
// which a cut is no border. (Collapse and the model need the real one.)
TMeshIncidence glued_incidence(const HalfArcSetup& setup);

// Solves the arc model of T' with the two-gons and `setup.bounds` plus
// options.extra_constraints (T' ids) exactly (coarse stages as quantize_tmesh) and checks the
// result on T' (check_quantization, and every two-gon's sides equal): a failure throws
// std::logic_error (a bug). status Infeasible: no valid half-arc quantization with these bounds
// exists. options.relaxed throws std::invalid_argument.
TMeshQuantization quantize_inflated(const HalfArcSetup& setup, const QuantizeOptions& options);

// A half-arc quantization: the setup, the quantization of T' (arc lengths per T' arc, bounds in
// T' ids, model size and times as quantize_tmesh's) and the same as one length per input
// half-arc.
struct HalfArcQuantization : HalfArcSetup {
  TMeshQuantization quantization;
  std::vector<int64_t> half_arc_length;
};

// prepare_half_arcs, then quantize_inflated, then check_half_arc_quantization on the input
// (std::logic_error if it fails).
HalfArcQuantization quantize_half_arcs(const TMesh& tmesh, const TMeshIncidence& incidence,
                                       const QuantizeOptions& options, double reorder_weight = -1,
                                       bool keep_crossings = false);

// The deflated T-mesh (see above) and its arc quantization: vertices and arcs of the input's
// positions where a position is shared (no chains or grids), the same patches, every
// non-zero path along its arcs.
struct DeflatedTMesh {
  TMesh tmesh;
  std::vector<int64_t> arc_length;
  int reordered_junctions = 0;  // T-junctions of a right side that now sit elsewhere among
                                // the left side's vertices than in the input
};
DeflatedTMesh deflate_two_gons(const InflatedTMesh& inflated,
                               const std::vector<int64_t>& arc_length);

}  // namespace bimdf::tmesh
