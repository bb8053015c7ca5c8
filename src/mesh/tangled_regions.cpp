#include "mesh/tangled_regions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "mesh/quad_quality.hpp"
#include "mesh/surface_untangling.hpp"

namespace bimdf::detail {
namespace {

// Regions grow by this many rings of quads around a cluster; a larger one is tried where a
// smaller one did not untangle (its boundary may be too folded to lay flat).
constexpr std::array<int, 3> kRings = {2, 3, 5};

// Gauss–Seidel sweeps of the barycentric embedding: regions are a few quads across, so this
// converges far beyond what smoothing then changes.
constexpr int kTutteSweeps = 300;

enum class Placement { kTutte, kDescent, kTutteThenDescent, kBeforeSmoothing };
constexpr std::array<Placement, 4> kPlacements = {Placement::kTutte, Placement::kDescent,
                                                  Placement::kTutteThenDescent,
                                                  Placement::kBeforeSmoothing};

bool inverted(const TangledRegionInput& in, int f) {
  const auto [own, under] = in.quality(f);
  return std::min(own, under) < 0;
}

// A quad whose worst corner against its own normal is below this is all but flat.
constexpr double kFlat = 0.01;

// How tangled the quads `quads` are: how many are inverted against their own normal (what
// metrics.hpp reports), how many against either, the worst scaled Jacobian against either and
// against their own normal.
struct Tangle {
  // Degenerate quads (corners merged, see quad_quality.hpp) count as inverted against their
  // own normal: their scaled Jacobian reads 0, so a placement that squeezes a fold into a
  // point would otherwise count as having righted it.
  int inverted_own = 0;
  int inverted = 0;
  double worst = 1;
  double worst_own = 1;
  // Fewer inverted against their own normal; with as many, fewer against either or a better
  // worst quad — but not by flattening a quad against its own normal (below kFlat and below
  // the worst before): a quad righted against the surface's normal, which can point astray,
  // is not worth a degenerate one.
  bool better_than(const Tangle& other) const {
    if (inverted_own != other.inverted_own) return inverted_own < other.inverted_own;
    if (worst_own < std::min(other.worst_own, kFlat)) return false;
    return std::tuple{-inverted, worst} > std::tuple{-other.inverted, other.worst};
  }
};

Tangle tangle(const TangledRegionInput& in, const std::vector<int>& quads) {
  Tangle t;
  for (int f : quads) {
    const auto [own, under] = in.quality(f);
    t.inverted_own += own < 0 || degenerate(in.mesh, in.mesh.quads[f]);
    t.inverted += std::min(own, under) < 0;
    t.worst = std::min({t.worst, own, under});
    t.worst_own = std::min(t.worst_own, own);
  }
  return t;
}

// The quads within `rings` rings (sharing a vertex) of quad `seed`.
std::vector<int> quads_around(const TangledRegionInput& in, int seed, int rings,
                              std::vector<char>& mark) {
  std::vector<int> region{seed};
  mark[seed] = 1;
  size_t ring_start = 0;
  for (int r = 0; r < rings; ++r) {
    const size_t ring_end = region.size();
    for (size_t i = ring_start; i < ring_end; ++i)
      for (int v : in.mesh.quads[region[i]])
        for (int g : in.vertex_quads[v])
          if (!mark[g]) mark[g] = 1, region.push_back(g);
    ring_start = ring_end;
  }
  for (int f : region) mark[f] = 0;
  return region;
}

// Lays region `quads` flat and places its inner vertices `inner` by Tutte's embedding.
void place_inner_vertices(const TangledRegionInput& in, const std::vector<int>& quads,
                          const std::vector<int>& inner) {
  QuadMesh& mesh = in.mesh;
  Vec3 normal{0, 0, 0}, centre{0, 0, 0};
  std::vector<int> corners;
  for (int f : quads) {
    normal = along(normal, 1, newell_normal(mesh, mesh.quads[f]));
    corners.insert(corners.end(), mesh.quads[f].begin(), mesh.quads[f].end());
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (int v : corners) centre = along(centre, 1.0 / corners.size(), mesh.vertices[v]);
  if (!(norm(normal) > 0)) return;
  const auto [t1, t2] = plane_frame(normalized(normal));
  // Plane coordinates of every corner; the inner ones are then relaxed to their neighbours'
  // mean (all their neighbours are corners of the region: their quads are in it).
  std::vector<std::array<double, 2>> uv(corners.size());
  const auto index = [&](int v) {
    return std::lower_bound(corners.begin(), corners.end(), v) - corners.begin();
  };
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec3 d = sub(mesh.vertices[corners[i]], centre);
    uv[i] = {dot(d, t1), dot(d, t2)};
  }
  // The sweeps work on positions in `corners`: each inner vertex's own and its neighbours'.
  std::vector<int> inner_at;
  std::vector<std::vector<int>> inner_neighbours;
  for (int v : inner) {
    inner_at.push_back(static_cast<int>(index(v)));
    std::vector<int> around;
    for (int w : in.neighbours[v]) around.push_back(static_cast<int>(index(w)));
    inner_neighbours.push_back(std::move(around));
  }
  for (int sweep = 0; sweep < kTutteSweeps; ++sweep)
    for (size_t k = 0; k < inner.size(); ++k) {
      std::array<double, 2> mean{0, 0};
      for (int j : inner_neighbours[k])
        for (int d = 0; d < 2; ++d) mean[d] += uv[j][d] / inner_neighbours[k].size();
      uv[inner_at[k]] = mean;
    }
  for (size_t k = 0; k < inner.size(); ++k) {
    const std::array<double, 2>& p = uv[inner_at[k]];
    mesh.vertices[inner[k]] = in.project(inner[k], along(along(centre, p[0], t1), p[1], t2));
  }
}

// Moves the inner vertices `inner` of region `quads` all at once down the untangling energy of
// surface_untangling.hpp, measured against the surface's normal under each quad.
void descend_untangling(const TangledRegionInput& in, const std::vector<int>& quads,
                        const std::vector<int>& inner) {
  QuadMesh& mesh = in.mesh;
  QuadsOnSurface region;
  std::vector<int> corners;  // region point → mesh vertex
  std::unordered_map<int, int> point;
  double length = 0;
  for (int f : quads) {
    std::array<int, 4> at;
    for (int i = 0; i < 4; ++i) {
      const int v = mesh.quads[f][i];
      const auto [it, added] = point.emplace(v, static_cast<int>(corners.size()));
      if (added) corners.push_back(v), region.points.push_back(mesh.vertices[v]);
      at[i] = it->second;
      length += norm(sub(mesh.vertices[mesh.quads[f][(i + 1) % 4]], mesh.vertices[v]));
    }
    region.quads.push_back(at);
    const Vec3 n = in.surface_normal(f);
    region.normals.push_back(norm(n) > 0 ? n : normalized(newell_normal(mesh, mesh.quads[f])));
  }
  region.movable.assign(corners.size(), 0);
  for (int v : inner) region.movable[point.at(v)] = 1;
  region.project = [&](int k, const Vec3& p) { return in.project(corners[k], p); };
  untangle_quads_on_surface(region, length / (4.0 * quads.size()));
  for (int v : inner) mesh.vertices[v] = region.points[point.at(v)];
}

}  // namespace

TangledRegionReport reembed_tangled_regions(const TangledRegionInput& in,
                                            const std::vector<int>& vertices) {
  QuadMesh& mesh = in.mesh;
  TangledRegionReport report;
  using Freedom = TangledRegionInput::Freedom;
  std::vector<Freedom> freedom(mesh.num_vertices(), Freedom::kPinned);
  std::vector<char> quad_mark(mesh.num_quads(), 0);
  for (int v : vertices) freedom[v] = in.freedom(v);
  const auto count_inverted = [&] {
    int count = 0;
    for (int f = 0; f < mesh.num_quads(); ++f) count += inverted(in, f);
    return count;
  };
  report.inverted_before = count_inverted();
  for (int rings : kRings) {
    std::vector<char> handled(mesh.num_quads(), 0);
    for (int seed = 0; seed < mesh.num_quads(); ++seed) {
      if (handled[seed] || !inverted(in, seed)) continue;
      const std::vector<int> quads = quads_around(in, seed, rings, quad_mark);
      for (int f : quads) quad_mark[f] = 1;
      std::vector<int> inner;
      for (int f : quads) {
        if (inverted(in, f)) handled[f] = 1;
        for (int v : mesh.quads[f]) {
          if (freedom[v] == Freedom::kPinned ||
              std::find(inner.begin(), inner.end(), v) != inner.end())
            continue;
          const auto& around = in.vertex_quads[v];
          if (std::all_of(around.begin(), around.end(), [&](int g) { return quad_mark[g]; }))
            inner.push_back(v);
        }
      }
      for (int f : quads) quad_mark[f] = 0;
      if (inner.empty()) continue;
      std::vector<int> free_inner;
      for (int v : inner)
        if (freedom[v] == Freedom::kFree) free_inner.push_back(v);
      ++report.regions;
      const Tangle before = tangle(in, quads);
      std::vector<Vec3> saved;
      for (int v : inner) saved.push_back(mesh.vertices[v]);
      // Up to four placements, the best kept: Tutte's embedding; the untangling descent
      // started from the current positions and from Tutte's; the positions before smoothing.
      // Each is tried only while the best so far leaves quads inverted: once none is, the
      // others could only raise the worst quad.
      Tangle best = before;
      std::vector<Vec3> chosen;
      for (Placement placement : kPlacements) {
        if (best.inverted == 0) break;
        if (placement == Placement::kBeforeSmoothing) {
          if (!in.placed) break;
          for (int v : inner) mesh.vertices[v] = (*in.placed)[v];
        } else {
          // Without free vertices Tutte's embedding moves nothing: starting the descent from it
          // would repeat the descent from the current positions.
          if (placement == Placement::kTutteThenDescent && free_inner.empty()) continue;
          if (placement != Placement::kDescent) place_inner_vertices(in, quads, free_inner);
          if (placement != Placement::kTutte) descend_untangling(in, quads, inner);
          in.smooth(inner);
        }
        const Tangle now = tangle(in, quads);
        if (now.better_than(best)) {
          best = now;
          chosen.clear();
          for (int v : inner) chosen.push_back(mesh.vertices[v]);
        }
        for (size_t k = 0; k < inner.size(); ++k) mesh.vertices[inner[k]] = saved[k];
      }
      for (size_t k = 0; k < chosen.size(); ++k) mesh.vertices[inner[k]] = chosen[k];
      report.kept += !chosen.empty();
    }
  }
  report.inverted_after = count_inverted();
  return report;
}

}  // namespace bimdf::detail
