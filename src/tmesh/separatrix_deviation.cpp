// measure_separatrix_deviation (tmesh/separatrix_deviation.hpp). Places on the input surface
// are an input quad and a point of its unit square (corner k of quad f at kCorner[k]); a walk
// keeps the rigid map (quarter turns and a shift) from the quad it stands in to the quad where
// it began, composed across shared edges as it moves, so every place is read in one frame.
#include "bimdf/tmesh/separatrix_deviation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "bimdf/tmesh/requantize.hpp"
#include "tmesh/quad_mesh_topology.hpp"

namespace bimdf::tmesh {
namespace {

using Vec2 = std::array<double, 2>;
using detail::QuadMeshTopology;

constexpr std::array<Vec2, 4> kCorner{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
constexpr std::array<Vec2, 4> kDirection{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};  // side k's
constexpr int kMaxSearch = 1 << 16;  // quads one step may search before giving up

Vec2 turn(const Vec2& x, int quarters) {  // counter-clockwise
  switch (quarters & 3) {
    case 0:
      return x;
    case 1:
      return {-x[1], x[0]};
    case 2:
      return {-x[0], -x[1]};
    default:
      return {x[1], -x[0]};
  }
}

// x ↦ turn(x, quarters) + shift.
struct RigidMap {
  int quarters = 0;
  Vec2 shift{0, 0};
  Vec2 operator()(const Vec2& x) const {
    const Vec2 r = turn(x, quarters);
    return {r[0] + shift[0], r[1] + shift[1]};
  }
  RigidMap after(const RigidMap& first) const {  // this ∘ first
    return {(quarters + first.quarters) & 3, (*this)(first.shift)};
  }
  RigidMap inverse() const {
    const Vec2 s = turn(shift, -quarters);
    return {(-quarters) & 3, {-s[0], -s[1]}};
  }
};

struct Place {
  int quad = -1;
  Vec2 x{0, 0};
};

class DeviationWalker {
 public:
  DeviationWalker(const QuadMesh& input, const TMesh& tmesh) : tm_(tmesh), topo_(input, "<input>") {
    quad_patch_.assign(input.num_quads(), -1);
    cell_half_edge_.resize(tmesh.num_patches());
    for (int p = 0; p < tmesh.num_patches(); ++p) {
      if (p >= static_cast<int>(tmesh.patch_grid.size()) || tmesh.patch_grid[p].empty()) continue;
      const PatchGrid& g = tmesh.patch_grid[p];
      std::vector<int>& cells = cell_half_edge_[p];
      cells.assign(size_t(g.width) * g.height, -1);
      for (int j = 0; j < g.height; ++j)
        for (int i = 0; i < g.width; ++i) {
          const int a = g.at(i, j), b = g.at(i + 1, j);
          const int e = topo_.find_edge(a, b);
          if (e < 0) continue;
          for (int h : topo_.edge_half_edges(e))
            if (h >= 0 && topo_.tail(h) == a) {
              cells[size_t(j) * g.width + i] = h;
              quad_patch_[QuadMeshTopology::face(h)] = p;
            }
        }
    }
    singular_.assign(topo_.num_vertices(), 0);
    for (int m = 0; m < topo_.num_vertices(); ++m) singular_[m] = is_singular(m);
    seen_.assign(input.num_quads(), 0);
    from_.assign(input.num_quads(), -1);
  }

  // Grid coordinate uv of patch p as a place, and the quarter turns from the patch's grid
  // axes to that quad's square; quad −1 when p has no cell there.
  Place place_in_patch(int p, const Vec2& uv, int& quarters) const {
    if (uv == Vec2{-1, -1}) return {};  // an irregular patch's quad: no grid coordinates
    const PatchGrid& g = tm_.patch_grid[p];
    const int i = std::clamp(static_cast<int>(std::floor(uv[0])), 0, g.width - 1);
    const int j = std::clamp(static_cast<int>(std::floor(uv[1])), 0, g.height - 1);
    const int h = cell_half_edge_[p].empty() ? -1 : cell_half_edge_[p][size_t(j) * g.width + i];
    if (h < 0) return {};
    const int k = h & 3;
    quarters = k;
    const Vec2 a = turn({uv[0] - i, uv[1] - j}, k);
    return {QuadMeshTopology::face(h), {kCorner[k][0] + a[0], kCorner[k][1] + a[1]}};
  }

  // Input vertex m as a place (a corner of one of its quads).
  Place place_of_vertex(int m) const {
    for (int e : topo_.vertex_edges(m))
      for (int h : topo_.edge_half_edges(e))
        if (h >= 0 && topo_.tail(h) == m) return {QuadMeshTopology::face(h), kCorner[h & 3]};
    return {};
  }

  bool is_singular(int m) const {
    return m >= 0 && m < topo_.num_vertices() && topo_.is_used(m) && !topo_.is_regular(m);
  }

  // The map from quad a's square to quad b's along a shortest way through quads of the
  // `patches` (and a, b; nullptr: any quads); false when none is found within kMaxSearch quads.
  // Going round a singular vertex turns the frame (a doublet's valence-2 vertex by half a turn),
  // so which side a way passes one on changes the result — but not for a place at that vertex,
  // which stays where it is under the turn. With `pivot` ≥ 0 (the singular input vertex both
  // places stand at), `only_pivot` keeps the way to edges at the pivot, and `avoid_singular`
  // keeps it off edges at any other singular vertex.
  bool transport(int a, int b, const std::vector<int>* patches, int pivot, bool only_pivot,
                 bool avoid_singular, RigidMap& map) {
    map = {};
    if (a == b) return true;
    ++stamp_;
    std::vector<int> queue{a};
    seen_[a] = stamp_;
    const auto allowed = [&](int f) {
      return f == b || !patches ||
             std::find(patches->begin(), patches->end(), quad_patch_[f]) != patches->end();
    };
    for (size_t head = 0; head < queue.size() && queue.size() < kMaxSearch; ++head) {
      const int f = queue[head];
      for (int k = 0; k < 4; ++k) {
        const int o = topo_.opposite(4 * f + k);
        if (o < 0) continue;
        const int u = topo_.tail(4 * f + k), w = topo_.head(4 * f + k);
        const bool at_pivot = u == pivot || w == pivot;
        if (only_pivot && !at_pivot) continue;
        if (avoid_singular && !at_pivot && (singular_[u] || singular_[w])) continue;
        const int g = QuadMeshTopology::face(o);
        if (seen_[g] == stamp_ || !allowed(g)) continue;
        seen_[g] = stamp_, from_[g] = o;
        if (g == b) {
          for (int at = b; at != a;) {              // compose the crossings back to a
            const int h = from_[at];                // in `at`, opposite of a half-edge of prev
            const int crossed = topo_.opposite(h);  // in the previous quad
            const int k_prev = crossed & 3, k_here = h & 3;
            // crossed runs corner k_prev → k_prev+1 of prev; h runs back, k_here → k_here+1.
            const RigidMap step{(k_here + 2 - k_prev) & 3, {0, 0}};
            const Vec2 moved = step(kCorner[k_prev]);
            const Vec2& target = kCorner[(k_here + 1) & 3];
            const RigidMap cross{step.quarters, {target[0] - moved[0], target[1] - moved[1]}};
            map = map.after(cross);
            at = QuadMeshTopology::face(crossed);
          }
          return true;
        }
        queue.push_back(g);
      }
    }
    return false;
  }

 private:
  const TMesh& tm_;
  QuadMeshTopology topo_;
  std::vector<int> quad_patch_;
  std::vector<std::vector<int>>
      cell_half_edge_;  // per patch, per cell: its half-edge (i,j)→(i+1,j)
  std::vector<char> singular_;  // per input vertex
  std::vector<int> seen_, from_;
  int stamp_ = 0;
};

}  // namespace

SeparatrixDeviation measure_separatrix_deviation(const QuadMesh& input, const TMesh& tmesh,
                                                 const CollapsedMesh& collapsed, double bound_deg) {
  const QuadMesh& out = collapsed.mesh;
  SeparatrixDeviation result;
  result.bound_deg = bound_deg < 0 ? -1 : bound_deg;
  if (out.num_quads() == 0) return result;
  if (collapsed.origin.size() != size_t(out.num_vertices()) ||
      out.quad_patch.size() != size_t(out.num_quads()) ||
      (!collapsed.quad_grid_uv.empty() && collapsed.quad_grid_uv.size() != size_t(out.num_quads())))
    throw std::invalid_argument(
        "the collapsed mesh's origin, patches or grid coordinates do not "
        "match its quads");
  for (int p : out.quad_patch)
    if (p < 0 || p >= tmesh.num_patches())
      throw std::invalid_argument("a quad's patch " + std::to_string(p) +
                                  " is not a patch of the T-mesh");
  const QuadMeshTopology topo(out, "<requantized mesh>");
  DeviationWalker walker(input, tmesh);
  const auto singular = [&](int v) { return topo.is_used(v) && !topo.is_regular(v); };
  // The singular input vertex merged into output vertex v (−1: none).
  const auto singular_input_vertex = [&](int v) {
    for (int t : collapsed.origin[v].tmesh_vertices) {
      const int m =
          t < static_cast<int>(tmesh.vertex_mesh_vertex.size()) ? tmesh.vertex_mesh_vertex[t] : -1;
      if (walker.is_singular(m)) return m;
    }
    return -1;
  };
  std::vector<char> traced(topo.num_edges(), 0);
  const double bound = bound_deg < 0 ? -1 : bound_deg + 1e-9;
  for (int s = 0; s < topo.num_vertices(); ++s) {
    if (!singular(s)) continue;
    for (int e0 : topo.vertex_edges(s)) {
      if (traced[e0] || topo.is_border_edge(e0)) continue;
      // Walk state: the quad we stand in, the map from its square to the start's, where the
      // start is, and the output's axis there.
      bool ok = !collapsed.quad_grid_uv.empty();
      const int start_vertex = singular_input_vertex(s);
      Place start = start_vertex >= 0 ? walker.place_of_vertex(start_vertex) : Place{};
      Place here = start;
      RigidMap to_start;
      Vec2 axis{0, 0}, last{0, 0};
      bool have_start = start.quad >= 0;
      const auto move_to = [&](const Place& to, const std::vector<int>& patches, int pivot = -1) {
        if (!ok || to.quad < 0) return ok = false;
        if (here.quad < 0) {  // the first place: the frame starts here
          here = to, to_start = {}, start = to, last = to.x;
          return true;
        }
        RigidMap map;
        // The safest way first (see transport): round the pivot only, then away from other
        // singular vertices, then through the vertex's patches, then anywhere — two-gons cut
        // the T-mesh open (half-arc quantization), and places a zip joined may lie apart along
        // the line, past the patches of the vertex.
        const bool found =
            (pivot >= 0 &&
             walker.transport(here.quad, to.quad, nullptr, pivot, true, false, map)) ||
            walker.transport(here.quad, to.quad, &patches, pivot, false, true, map) ||
            walker.transport(here.quad, to.quad, &patches, pivot, false, false, map) ||
            walker.transport(here.quad, to.quad, nullptr, pivot, false, false, map);
        if (!found) return ok = false;
        to_start = to_start.after(map.inverse());
        here = to;
        last = to_start(to.x);
        return true;
      };
      if (have_start) last = start.x;
      int from = s, e = e0, to = -1;
      std::vector<int> line_patches;
      while (true) {
        traced[e] = 1;
        int h = topo.edge_half_edges(e)[0];
        if (topo.tail(h) != from) h = topo.edge_half_edges(e)[1];
        if (h < 0) {  // a border edge walked against its quad: not a separatrix inside
          ok = false;
          break;
        }
        to = topo.head(h);
        const int q = QuadMeshTopology::face(h), k = h & 3, p = out.quad_patch[q];
        int quarters = 0;
        const Place tail = walker.place_in_patch(p, collapsed.quad_grid_uv[q][k], quarters);
        std::vector<int> patches = collapsed.origin[from].patches;
        patches.push_back(p);
        line_patches.insert(line_patches.end(), patches.begin(), patches.end());
        if (!move_to(tail, patches, from == s ? start_vertex : -1)) break;
        // The output edge runs along patch axis k (0: +u, 1: +v, 2: −u, 3: −v).
        const Vec2 along = turn(turn(kDirection[k], quarters), to_start.quarters);
        if (axis == Vec2{0, 0}) axis = along;
        if (along != axis) ok = false;  // the frames disagree: not a straight line in them
        int ignored = 0;
        const Place head =
            walker.place_in_patch(p, collapsed.quad_grid_uv[q][(k + 1) & 3], ignored);
        if (!move_to(head, {p})) break;  // inside one patch: its own quads
        if (singular(to) || topo.is_border_vertex(to)) break;
        const int next = topo.straight_on(to, e);
        if (next < 0 || traced[next]) {  // a closed line: no end to measure to
          ok = false;
          break;
        }
        from = to, e = next;
      }
      if (ok) {
        const std::vector<int>& at_end = collapsed.origin[to].patches;
        line_patches.insert(line_patches.end(), at_end.begin(), at_end.end());
      }
      if (ok && singular(to)) {
        const int end_vertex = singular_input_vertex(to);
        if (end_vertex >= 0)
          move_to(walker.place_of_vertex(end_vertex), collapsed.origin[to].patches, end_vertex);
      }
      if (!ok) {
        ++result.unmeasured;
        continue;
      }
      const Vec2 d{last[0] - start.x[0], last[1] - start.x[1]};
      const double along = d[0] * axis[0] + d[1] * axis[1];
      const double across = axis[0] * d[1] - axis[1] * d[0];
      const double deg = std::atan2(std::abs(across), along) * 180 / std::numbers::pi;
      ++result.measured;
      std::sort(line_patches.begin(), line_patches.end());
      line_patches.erase(std::unique(line_patches.begin(), line_patches.end()), line_patches.end());
      result.separatrices.push_back({s, to, !singular(to), deg, std::move(line_patches)});
      if (!singular(to)) {
        result.max_to_border_deg = std::max(result.max_to_border_deg, deg);
        continue;
      }
      if (deg > result.max_deg || result.worst_from < 0)
        result.max_deg = deg, result.worst_from = s, result.worst_to = to;
      if (bound >= 0 && deg > bound) ++result.over_bound;
    }
  }
  return result;
}

SeparatrixDeviation measure_separatrix_deviation(const QuadMesh& input, const RequantizeResult& r,
                                                 double bound_deg) {
  return measure_separatrix_deviation(
      input, r.half_arc ? r.half_arc->inflated.tmesh : r.traced.tmesh, r.collapsed, bound_deg);
}

}  // namespace bimdf::tmesh
