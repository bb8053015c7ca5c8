// Quadrangular T-meshes (paper §4.1.1): vertices, arcs, half-arcs and 4-sided patches whose sides
// are paths of half-arcs — the input of quad T-mesh quantization (§4.2, tmesh/quantize.hpp).
//
// Conventions, used by every part of src/tmesh:
//   * Arc a joins arc_ends[a] = (c, d), c ≠ d. Its half-arcs are h = 2a (c → d) and h = 2a + 1
//     (d → c); half_arc_tail / half_arc_head give their ends.
//   * A patch has four sides; side k is a non-empty path of half-arcs, walked with the patch on
//     the left (counter-clockwise seen from outside). The head of side k's last half-arc is the
//     tail of side k+1's first (the patch's corner k+1, mod 4). Sides k and k+2 are opposite.
//   * Every half-arc lies on at most one patch side; a half-arc on none is a *border* half-arc,
//     and its opposite half-arc must lie on a side (an arc belongs to one or two patches).
//   * arc_target[a] ≥ 0 is the real length the quantization should approach, in output quad
//     edges (the density factor already applied).
//   * Non-zero paths (M1, §4.1.2): sequences of half-arcs, each starting where the previous one
//     ends; a valid quantization gives at least one arc of each path a length ≥ 1.
//
// Geometry is optional. `vertices` holds positions (used for drawing a layout); when the T-mesh
// was made from a quad mesh, each arc also lists the mesh vertices it runs through
// (`arc_chain`, tail to head) and each patch the grid of mesh vertices it covers
// (`patch_grid`), which tessellation maps through.
//
// Storage is a plain struct of arrays indexed by vertex, arc and patch id.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace bimdf::tmesh {

// A patch's rectangle of mesh vertices: `width` quads along side 0 and 2, `height` along sides
// 1 and 3; vertex (i, j), 0 ≤ i ≤ width, 0 ≤ j ≤ height, is vertices[j * (width + 1) + i], with
// (0, 0) = corner 0 (tail of side 0), (width, 0) = corner 1, (width, height) = corner 2,
// (0, height) = corner 3. Empty (width = height = 0, no vertices) when the T-mesh has no mesh.
struct PatchGrid {
  int width = 0, height = 0;
  std::vector<int> vertices;
  bool empty() const { return vertices.empty(); }
  int at(int i, int j) const { return vertices[j * (width + 1) + i]; }
};

struct TMesh {
  std::vector<std::array<double, 3>> vertices;  // positions, one per T-mesh vertex
  // Per T-mesh vertex: the quad mesh vertex it is (−1 or empty when there is no mesh).
  std::vector<int> vertex_mesh_vertex;

  std::vector<std::array<int, 2>> arc_ends;  // (tail, head) of half-arc 2a
  std::vector<double> arc_target;            // real target length, ≥ 0
  std::vector<std::vector<int>> arc_chain;   // mesh vertices tail → head (empty: no mesh)
  std::vector<uint8_t> arc_feature;          // 1: on a feature curve (kept by smoothing)

  std::vector<std::array<std::vector<int>, 4>> patch_sides;  // half-arc ids per side
  std::vector<PatchGrid> patch_grid;                         // empty, or one per patch

  std::vector<std::vector<int>> nonzero_paths;  // M1: half-arc paths

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_arcs() const { return static_cast<int>(arc_ends.size()); }
  int num_half_arcs() const { return 2 * num_arcs(); }
  int num_patches() const { return static_cast<int>(patch_sides.size()); }

  static int arc_of(int half_arc) { return half_arc >> 1; }
  static int opposite(int half_arc) { return half_arc ^ 1; }
  int half_arc_tail(int h) const { return arc_ends[h >> 1][h & 1]; }
  int half_arc_head(int h) const { return arc_ends[h >> 1][1 - (h & 1)]; }
};

// What validation derives: for every half-arc, the patch and side it lies on (−1, −1 for a
// border half-arc).
struct TMeshIncidence {
  std::vector<int> half_arc_patch;
  std::vector<int> half_arc_side;
  bool is_border(int half_arc) const { return half_arc_patch[half_arc] < 0; }
};

// Checks every rule above (ids in range, distinct arc ends, finite non-negative targets, sides
// non-empty and chained corner to corner, a patch's sides vertex-distinct apart from corners,
// no half-arc on two sides, no arc without a patch, array sizes agree, non-zero paths chained,
// patch grids consistent with their sides' chains) and returns the incidence. Geometry, when
// present: finite positions; vertex_mesh_vertex entries ≥ 0 or −1; every arc has a chain of
// ≥ 2 mesh vertices (or none has) whose ends are its ends' mesh vertices; consecutive half-arcs'
// chains meet; every patch has a grid (or none has) of at least 1×1 quads and
// (width+1)·(height+1) vertices whose border — side 0 = row j = 0 from i = 0 to width, side 1 =
// column i = width from j = 0 to height, side 2 = row j = height from i = width down to 0,
// side 3 = column i = 0 from j = height down to 0 — is its sides' chains, and whose corners are
// its corners' mesh vertices. The first broken rule is reported. Throws
// InputError naming `source` and the patch, arc or path (e.g. "patch 4, side 2: half-arc 17
// starts at vertex 9, but the previous one ends at vertex 8").
TMeshIncidence validate_tmesh(const TMesh& tmesh, const std::string& source = "<t-mesh>");

// A rule validate_tmesh found broken. `path` locates the offending value in the JSON form
// (e.g. "/patches/4/sides/2/1", docs/formats.md) so that the JSON reader can point into the
// file; `message` names the element and what was expected, as validate_tmesh's InputError says.
struct TMeshIssue {
  std::string path;
  std::string message;
};

// validate_tmesh without throwing: the first broken rule, or nothing — and then `incidence`,
// when given, receives what validate_tmesh would return.
std::optional<TMeshIssue> find_tmesh_issue(const TMesh& tmesh, TMeshIncidence* incidence = nullptr);

// The arcs a sequence of half-arcs (a side, a non-zero path) runs along: sorted, each once.
std::vector<int> arcs_along(const std::vector<int>& half_arcs);

// The sum of the lengths of a patch side's arcs under `arc_length` (one value per arc).
int64_t side_length(const TMesh& tmesh, int patch, int side,
                    const std::vector<int64_t>& arc_length);

// JSON form (docs/formats.md §7, "T-mesh (JSON)"). write_tmesh_json writes every field as is
// (without validating; a round trip is exact); parse_tmesh_json / read_tmesh_json parse and
// validate, throwing InputError with the JSON path of the offending field (an unreadable file:
// InputError naming it).
void write_tmesh_json(std::ostream& out, const TMesh& tmesh);
TMesh parse_tmesh_json(const std::string& text, const std::string& source);
TMesh read_tmesh_json(const std::string& path);

}  // namespace bimdf::tmesh
