// A patch layout made from a bare triangle mesh (issue 51): cross field, motorcycle graph of
// its separatrices, the mesh cut along them, patches and their corners — the same layout type
// (quant::Layout) that `bimdf remesh` reads from QuadWild's files, so the rest of the pipeline
// (quantization, tessellation, smoothing) is unchanged.
//
// Choice of method (docs/standalone_remesher.md): QuadWild traces many candidate paths and
// selects a subset into 3–6-sided patches with the singularities inside; we trace each
// separatrix once, as a motorcycle graph, which leaves quad patches with T-junctions and the
// singularities at patch corners. No selection is needed, every singularity of the field is one
// of the mesh's (no pattern adds any), and the quantizer's subsides already handle T-junctions.
// The separatrices are iso-lines of a seamless parametrization fitted to the field
// (layout/seamless.hpp), not the field's streamlines: streamlines of a field with curl drift
// past each other and leave 3-, 5- and 6-sided patches, each a singularity the field lacks.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bimdf/layout/cross_field.hpp"
#include "bimdf/layout/features.hpp"
#include "bimdf/quant/layout.hpp"

namespace bimdf::layout {

struct LayoutOptions {
  CrossFieldOptions field;
  // Trace the iso-lines of a seamless parametrization fitted to the field (layout/seamless.hpp)
  // rather than the field's own streamlines, which drift apart where the field has curl.
  bool trace_parametrization = true;
  // ... unless the parametrization folds more than this fraction of the faces (near dense
  // clusters of singularities and sharp features least squares folds the map): then the
  // field's streamlines are traced instead, with `streamline_snap` and
  // `streamline_shallow_angle_deg` in place of snap and shallow_angle_deg. A few folds cost
  // less than streamlines do: on bull, camel and mannequin-devil (0.4–0.9% folded) the map
  // gave 1, 1 and 17 inverted quads where streamlines gave 16, 0 and 39, and raised the SJ
  // mean / p5 from 0.876/0.460, 0.889/0.351, 0.831/0.200 to 0.902/0.598, 0.954/0.803,
  // 0.890/0.376 (docs/standalone_remesher.md); no shared model folds more than 0.9%.
  double max_folded_fraction = 0.02;
  double streamline_snap = 0.1;
  double streamline_shallow_angle_deg = 30;
  // Trace crossings within this fraction of an edge from a vertex pass through the vertex.
  // Snapping moves a trace off its iso-line, so it is kept tiny when tracing the
  // parametrization (0.1 suited the field's streamlines, which drift anyway).
  double snap = 1e-4;
  // Traces longer than this many bounding-box diagonals are given up (and removed).
  double max_trace_length = 4;
  // Rounds of seeding patches that are not disks (each round traces everything again).
  int max_seed_rounds = 3;
  // Then rounds of cutting what is still not a disk across, along mesh edges from one of its
  // boundary loops to another (patches.hpp, cut_across_non_disks).
  int max_cut_across = 4;
  // Separatrices ending on a line at less than this angle (degrees) are not traced (see
  // tracing.hpp, Trace::end_angle), over up to max_ban_rounds tracings. 0: all are traced —
  // the default, since iso-lines of one family do not meet (30 suited the streamlines).
  double shallow_angle_deg = 0;
  // Separatrices ending on a feature curve or the border at less than this angle (degrees)
  // are not traced, whichever way is traced: curves are not iso-lines, and such a trace has
  // run alongside the curve, leaving a long sliver with a cusp between them (dino: one
  // six-sided sliver held 310 of the 711 quads below the 5th percentile). Measured on the 23
  // shared models: 10°, 20°, 35°, 45°, 60° (docs/standalone_remesher.md).
  double curve_shallow_angle_deg = 45;
  int max_ban_rounds = 6;
  // A singularity off a curve whose consecutive separatrices reach that curve within this many
  // average edge lengths sits practically on it: of each such run only the shortest is traced
  // (the others would cut off small three-sided patches, each needing a singularity of its own
  // in its pattern), over the same ban rounds. 0: all are traced.
  double short_to_curve_edges = 3;
  // Where tracing the parametrization leaves a patch that cannot be a chart (or a layout the
  // caller rejects), try again along the parametrization despite its folds, then along the
  // field's streamlines.
  bool try_other_ways = true;
  // Separatrices that pass this close to another singularity (in average edge lengths), head
  // on against one of its separatrices, are steered into it and the pair traced as one line
  // (tracing.hpp, TraceOptions::approach_radius). With a check (generate_layout), the layout
  // is made once per radius and the one the check rates least bad is kept; without one, the
  // first radius alone is used. Tracing reacts to small changes everywhere at once: radius
  // 1.25 rid helmet of a strip between a singularity's separatrices and a trace passing it at
  // 1.1 edges (SJ p5 0.637 → 0.819) but left bull an inverted quad, which radius 1 does not.
  // Two radii cost two layouts and remeshes (docs/standalone_remesher.md).
  std::vector<double> pairing_radii = {1, 1.25};
  // With a check, one more layout per radius here, traced with fewer lines, and kept where the
  // check rates it less bad than the others: no separatrix that runs alongside a curve, closer
  // than `beside_curve_edges` average edge lengths over more than `beside_curve_length_edges`
  // (trace_selection.hpp: ban_along_curves), and no patch corner where the map reads one but
  // the surface is flat, the sector's share of the field's turns above `flat_sector_quarters`
  // (patches.hpp: CornerHints::flat_share). Both cut slivers off CAD parts (couplingdown: a
  // separatrix 2 edges from the rim split off a band that a bolt hole squeezed, 405 of the
  // mesh's 529 worst quads; corners beside the small holes on straight borders); on organic
  // models they cost quality (cactus SJ p5 0.927 → 0.679 with them alone), so they are a
  // candidate, not the rule. Empty: none. Measured on the 23 shared models
  // (docs/standalone_remesher.md).
  std::vector<double> spare_pairing_radii = {1};
  double beside_curve_edges = 4;
  double beside_curve_length_edges = 10;
  double flat_sector_quarters = 1.9;
  // Pairs of opposite field singularities (valence 3 and 5) closer than this many average edge
  // lengths, neither on a feature curve or the border, are cancelled in the parametrization
  // (layout/singularity_pairs.hpp): below a quad's size a pair only adds two singular vertices
  // and the slivers between their separatrices. Measured on the 23 shared models at 1.5
  // (docs/standalone_remesher.md): camel 255 → 206 singular vertices, ChineseDragon-10kv
  // 860 → 671, bull 1891 → 1638, no model's SJ mean or p5 below QuadWild's. 0: none.
  double cancel_pair_radius = 1.5;
};

// One progress report (LayoutOptions' caller decides what to show): a stage has just ended.
struct LayoutProgress {
  double elapsed_s = 0;
  std::string stage;   // "field", "traced", "cut", "patches"
  std::string detail;  // what the stage found, in words and figures
};

struct GeneratedLayout {
  quant::Layout layout;    // on the cut mesh; average_edge_length is the input mesh's
  FieldIndices indices;    // the field's singularities, on the input mesh
  // Close pairs of them the parametrization left out (LayoutOptions::cancel_pair_radius; 0
  // where the field's streamlines were traced): the layout's singularities are the others.
  int cancelled_pairs = 0;
  int trace_starts = 0;    // vertices separatrices start from
  int traces = 0;          // kept
  int removed_traces = 0;  // unfinished, or ending on one that was removed
  int adjusted_patches = 0;  // patches given 3 or 6 corners where they had fewer or more
  int seeds = 0;             // regular vertices traced from to cut patches that were not disks
  int cuts_across = 0;       // paths along mesh edges that cut what seeds could not
  int banned_traces = 0;     // separatrices not traced: shallow ends, short runs to a curve
  int folded_faces = 0;      // of the parametrization (trace_parametrization)
  bool traced_parametrization = false;  // false: the field's streamlines were traced
  int attempts = 1;  // tracings tried (LayoutOptions::try_other_ways), the last one kept
  double pairing_radius = 1;  // the one of LayoutOptions::pairing_radii this layout was made with
  bool spare = false;         // traced with fewer lines (LayoutOptions::spare_pairing_radii)
  int candidates = 1;         // layouts the check took, of which this one rated least bad
  int checked = -1;           // which call of the check (from 0) rated this layout; −1: none
  // The field and the parametrization are computed once per generate_layout call and shared
  // by every pairing radius and retry (they do not depend on either): their times are that
  // one computation's, whichever layout is kept.
  double time_field_s = 0, time_parametrization_s = 0, time_trace_s = 0, time_cut_s = 0,
         time_patches_s = 0;
};

// A caller's verdict on a layout generate_layout made (e.g. from the quad mesh quantized from
// it: quant::remesh_layout, quant::layout_badness).
struct LayoutVerdict {
  std::string wrong;   // what is wrong with it, in words, or "" to take it
  double badness = 0;  // of the layouts taken (one per pairing radius), the least bad is kept
};
using LayoutCheck = std::function<LayoutVerdict(const quant::Layout&)>;

// Builds the layout of `mesh` (prepare_surface's output) with `features` (detect_features or
// features_from_edges on it), trying the other ways of tracing where the first leaves a patch
// that cannot be a chart or `check` rejects its layout (LayoutOptions::try_other_ways;
// progress then reports a "retry" stage). With a check, does so once per pairing radius
// (LayoutOptions::pairing_radii, then spare_pairing_radii traced with fewer lines; progress
// reports a "pairing" stage before each after the first) and returns the layout taken with the
// least badness, the first of equals; the caller finds what its check computed for it by
// GeneratedLayout::checked. Throws std::runtime_error when a patch still cannot be a chart (not a
// disk, or fewer than 3 boundary vertices), naming it, or when `check` rejects the last way's
// layout too, with its reason — for the first radius, if no radius gives a layout.
GeneratedLayout generate_layout(const TriangleMesh& mesh, const Features& features,
                                const LayoutOptions& options,
                                const std::function<void(const LayoutProgress&)>& progress = {},
                                const LayoutCheck& check = {});

// A layout as QuadWild's step-2 files (quadwild_modeling.md §1.1), as text: `NAME.obj`,
// `.patch`, `.corners`, `.feature` (face,edge pairs of the feature edges), `.c_feature`.
struct QuadwildFiles {
  std::string obj, patch, corners, feature, c_feature;
};
QuadwildFiles to_quadwild_files(const quant::Layout& layout);

}  // namespace bimdf::layout
