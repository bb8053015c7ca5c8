// Validation of quadrangular T-meshes (tmesh.hpp states the rules). Every later stage — the
// Bi-MDF model, Algorithm 2, collapse, tessellation — indexes the arrays without checking, so a
// T-mesh that passes here must be safe to walk: ids in range, sides chained into one simple loop
// per patch, every half-arc on at most one side, grids agreeing with the chains they are cut
// along. The checks run in a fixed order and stop at the first broken rule, so that a message
// never blames a consequence of an earlier mistake (a side is only walked once its ids are known
// to be in range).
#include "bimdf/tmesh/tmesh.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "bimdf/error.hpp"

namespace bimdf::tmesh {
namespace {

std::string str(int64_t x) { return std::to_string(x); }
std::string str(int x) { return std::to_string(x); }
std::string str(size_t x) { return std::to_string(x); }

// Shortest text that reads back as the same double ("nan", "inf", "-0.5").
std::string str(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string range(int n) { return "[0, " + str(n) + ")"; }

std::string plural(size_t n, const std::string& one, const std::string& many) {
  return str(static_cast<int64_t>(n)) + " " + (n == 1 ? one : many);
}

// Thrown inside the checker only, caught by find_tmesh_issue: it lets each rule be one `if`
// deep inside loops without threading a status through every helper.
struct IssueFound {
  TMeshIssue issue;
};

class Checker {
 public:
  explicit Checker(const TMesh& t) : t_(t) {}

  TMeshIncidence run() {
    check_sizes();
    check_vertices();
    for (int a = 0; a < t_.num_arcs(); ++a) check_arc(a);
    inc_.half_arc_patch.assign(t_.num_half_arcs(), -1);
    inc_.half_arc_side.assign(t_.num_half_arcs(), -1);
    for (int p = 0; p < t_.num_patches(); ++p) check_patch(p);
    for (int a = 0; a < t_.num_arcs(); ++a)
      if (inc_.half_arc_patch[2 * a] < 0 && inc_.half_arc_patch[2 * a + 1] < 0)
        fail("/arcs/" + str(a),
             "arc " + str(a) + " (vertices " + str(t_.arc_ends[a][0]) + " → " +
                 str(t_.arc_ends[a][1]) +
                 ") lies on no patch side (every arc borders one or two patches)");
    for (size_t i = 0; i < t_.nonzero_paths.size(); ++i) check_path(static_cast<int>(i));
    return std::move(inc_);
  }

 private:
  [[noreturn]] static void fail(std::string path, std::string message) {
    throw IssueFound{TMeshIssue{std::move(path), std::move(message)}};
  }

  bool has_mesh_vertices() const { return !t_.vertex_mesh_vertex.empty(); }
  bool has_chains() const { return !t_.arc_chain.empty(); }

  // Array sizes cannot disagree in the JSON form (each value sits in its element), only when a
  // T-mesh is built in memory; the paths name the JSON array that holds the elements.
  void check_sizes() const {
    const size_t n = t_.vertices.size(), m = t_.arc_ends.size(), np = t_.patch_sides.size();
    auto per = [](const char* name, size_t have, size_t want, const char* array, const char* one,
                  const char* many, bool optional) {
      if (have == want || (optional && have == 0)) return;
      fail(std::string("/") + array, std::string(name) + " has " +
                                         plural(have, "entry", "entries") + " for " +
                                         plural(want, one, many) + ", expected " +
                                         (optional ? "none or " : "") + "one per " + one);
    };
    per("arc_target", t_.arc_target.size(), m, "arcs", "arc", "arcs", false);
    per("arc_chain", t_.arc_chain.size(), m, "arcs", "arc", "arcs", true);
    per("arc_feature", t_.arc_feature.size(), m, "arcs", "arc", "arcs", true);
    per("vertex_mesh_vertex", t_.vertex_mesh_vertex.size(), n, "vertex_mesh_vertex", "vertex",
        "vertices", true);
    per("patch_grid", t_.patch_grid.size(), np, "patches", "patch", "patches", true);
  }

  void check_vertices() const {
    for (int v = 0; v < t_.num_vertices(); ++v) {
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(t_.vertices[v][c]))
          fail("/vertices/" + str(v) + "/" + str(c), "vertex " + str(v) + ": coordinate " + str(c) +
                                                         " is " + str(t_.vertices[v][c]) +
                                                         ", expected a finite number");
      if (has_mesh_vertices() && t_.vertex_mesh_vertex[v] < -1)
        fail("/vertex_mesh_vertex/" + str(v), "vertex " + str(v) + ": mesh vertex " +
                                                  str(t_.vertex_mesh_vertex[v]) +
                                                  ", expected an id ≥ 0 or -1 (none)");
    }
  }

  void check_arc(int a) const {
    const std::string path = "/arcs/" + str(a), name = "arc " + str(a) + ": ";
    const auto& ends = t_.arc_ends[a];
    for (int k = 0; k < 2; ++k)
      if (ends[k] < 0 || ends[k] >= t_.num_vertices())
        fail(path + "/ends/" + str(k), name + "end " + str(k) + " is vertex " + str(ends[k]) +
                                           ", out of range " + range(t_.num_vertices()));
    if (ends[0] == ends[1])
      fail(path + "/ends",
           name + "both ends are vertex " + str(ends[0]) + " (an arc joins two distinct vertices)");
    const double target = t_.arc_target[a];
    if (!std::isfinite(target))
      fail(path + "/target",
           name + "target " + str(target) + " is not finite, expected a length ≥ 0");
    if (target < 0)
      fail(path + "/target",
           name + "target " + str(target) + " is negative, expected a length ≥ 0");
    if (!t_.arc_feature.empty() && t_.arc_feature[a] > 1)
      fail(path + "/feature",
           name + "feature flag " + str(t_.arc_feature[a]) + ", expected 0 or 1");
    if (has_chains()) check_chain(a, path, name);
  }

  void check_chain(int a, const std::string& path, const std::string& name) const {
    const std::vector<int>& chain = t_.arc_chain[a];
    if (chain.size() < 2)
      fail(path + "/chain", name + "chain has " +
                                plural(chain.size(), "mesh vertex", "mesh vertices") +
                                ", expected at least 2 (tail to head)");
    for (size_t i = 0; i < chain.size(); ++i)
      if (chain[i] < 0)
        fail(path + "/chain/" + str(i), name + "chain entry " + str(i) + " is mesh vertex " +
                                            str(chain[i]) + ", expected an id ≥ 0");
    if (!has_mesh_vertices()) return;
    // The chain is the arc drawn on the mesh, so its ends are the arc's ends.
    for (int k = 0; k < 2; ++k) {
      const int v = t_.arc_ends[a][k];
      const size_t i = k == 0 ? 0 : chain.size() - 1;
      if (chain[i] != t_.vertex_mesh_vertex[v])
        fail(path + "/chain/" + str(i), name + "chain " + (k == 0 ? "starts" : "ends") +
                                            " at mesh vertex " + str(chain[i]) + ", but its " +
                                            (k == 0 ? "tail" : "head") + ", vertex " + str(v) +
                                            ", is mesh vertex " + str(t_.vertex_mesh_vertex[v]));
    }
  }

  // The mesh vertices half-arc h runs through, in its direction.
  std::vector<int> half_arc_chain(int h) const {
    std::vector<int> c = t_.arc_chain[TMesh::arc_of(h)];
    if (h & 1) std::reverse(c.begin(), c.end());
    return c;
  }

  void check_patch(int p) {
    const std::string path = "/patches/" + str(p) + "/sides/";
    const auto& sides = t_.patch_sides[p];
    auto where = [&](int k, size_t i) { return path + str(k) + "/" + str(i); };
    auto name = [&](int k) { return "patch " + str(p) + ", side " + str(k) + ": "; };
    for (int k = 0; k < 4; ++k) {
      if (sides[k].empty()) fail(path + str(k), name(k) + "empty, expected at least one half-arc");
      for (size_t i = 0; i < sides[k].size(); ++i)
        if (sides[k][i] < 0 || sides[k][i] >= t_.num_half_arcs())
          fail(where(k, i), name(k) + "half-arc " + str(sides[k][i]) + " is out of range " +
                                range(t_.num_half_arcs()));
    }
    // Chained: each half-arc starts where the previous one ends, side k+1 where side k ends.
    int prev = sides[3].back();
    for (int k = 0; k < 4; ++k)
      for (size_t i = 0; i < sides[k].size(); ++i) {
        const int h = sides[k][i];
        if (t_.half_arc_tail(h) != t_.half_arc_head(prev))
          fail(where(k, i), name(k) + "half-arc " + str(h) + " starts at vertex " +
                                str(t_.half_arc_tail(h)) + ", but " +
                                (i == 0 ? "side " + str((k + 3) % 4) : "the previous one") +
                                " ends at vertex " + str(t_.half_arc_head(prev)));
        prev = h;
      }
    // A simple loop: the sides meet only at the corners and never cross themselves.
    std::unordered_map<int, int> side_of_vertex;
    for (int k = 0; k < 4; ++k)
      for (size_t i = 0; i < sides[k].size(); ++i) {
        const int v = t_.half_arc_tail(sides[k][i]);
        if (const auto [it, fresh] = side_of_vertex.emplace(v, k); !fresh)
          fail(where(k, i), name(k) + "half-arc " + str(sides[k][i]) + " starts at vertex " +
                                str(v) + ", already on side " + str(it->second) +
                                " (a patch's boundary passes each vertex once)");
      }
    for (int k = 0; k < 4; ++k)
      for (size_t i = 0; i < sides[k].size(); ++i) {
        const int h = sides[k][i];
        if (inc_.half_arc_patch[h] >= 0)
          fail(where(k, i),
               name(k) + "half-arc " + str(h) + " already lies on patch " +
                   str(inc_.half_arc_patch[h]) + ", side " + str(inc_.half_arc_side[h]) +
                   " (a half-arc lies on at most one side: sides run counter-clockwise, "
                   "so the patch across arc " +
                   str(TMesh::arc_of(h)) + " walks half-arc " + str(TMesh::opposite(h)) + ")");
        inc_.half_arc_patch[h] = p;
        inc_.half_arc_side[h] = k;
      }
    if (has_chains()) {
      // Consecutive half-arcs meet at a T-mesh vertex, so their chains meet at one mesh vertex;
      // with vertex_mesh_vertex this already follows from check_chain.
      prev = sides[3].back();
      for (int k = 0; k < 4; ++k)
        for (size_t i = 0; i < sides[k].size(); ++i) {
          const int h = sides[k][i];
          const int start = half_arc_chain(h).front(), end = half_arc_chain(prev).back();
          if (start != end)
            fail(where(k, i),
                 name(k) + "half-arc " + str(h) + "'s chain starts at mesh vertex " + str(start) +
                     ", but the previous half-arc's chain ends at mesh vertex " + str(end));
          prev = h;
        }
    }
    if (!t_.patch_grid.empty()) check_grid(p);
  }

  void check_grid(int p) const {
    const PatchGrid& g = t_.patch_grid[p];
    const std::string path = "/patches/" + str(p) + "/grid";
    const std::string name = "patch " + str(p) + ": ";
    if (g.width < 1 || g.height < 1)
      fail(path + (g.width < 1 ? "/width" : "/height"),
           name + "grid is " + str(g.width) + "×" + str(g.height) +
               ", expected at least 1×1 (patch_grid holds a grid for every patch or for none)");
    const int64_t want = (int64_t{g.width} + 1) * (int64_t{g.height} + 1);
    if (static_cast<int64_t>(g.vertices.size()) != want)
      fail(path + "/vertices", name + "grid has " +
                                   plural(g.vertices.size(), "mesh vertex", "mesh vertices") +
                                   ", expected (" + str(g.width) + " + 1) × (" + str(g.height) +
                                   " + 1) = " + str(want));
    auto at = [&](int i, int j) { return "(" + str(i) + ", " + str(j) + ")"; };
    auto index_path = [&](int i, int j) {
      return path + "/vertices/" + str(int64_t{j} * (g.width + 1) + i);
    };
    for (int j = 0; j <= g.height; ++j)
      for (int i = 0; i <= g.width; ++i)
        if (g.at(i, j) < 0)
          fail(index_path(i, j), name + "grid vertex " + at(i, j) + " is mesh vertex " +
                                     str(g.at(i, j)) + ", expected an id ≥ 0");
    // The grid's border, walked like the sides: side k runs from corner k to corner k+1.
    const int W = g.width, H = g.height;
    const auto walk = [&](int k, int s) -> std::array<int, 2> {
      switch (k) {
        case 0:
          return {s, 0};
        case 1:
          return {W, s};
        case 2:
          return {W - s, H};
        default:
          return {0, H - s};
      }
    };
    const auto& sides = t_.patch_sides[p];
    if (has_mesh_vertices())
      for (int k = 0; k < 4; ++k) {
        const auto [i, j] = walk(k, 0);
        const int v = t_.half_arc_tail(sides[k].front());
        if (g.at(i, j) != t_.vertex_mesh_vertex[v])
          fail(index_path(i, j), name + "grid corner " + at(i, j) + " is mesh vertex " +
                                     str(g.at(i, j)) + ", but corner " + str(k) + ", vertex " +
                                     str(v) + ", is mesh vertex " + str(t_.vertex_mesh_vertex[v]));
      }
    if (!has_chains()) return;
    for (int k = 0; k < 4; ++k) {
      // Consecutive chains share their meeting vertex (checked in check_patch): count it once.
      std::vector<int> along;
      for (int h : sides[k]) {
        const std::vector<int> c = half_arc_chain(h);
        along.insert(along.end(), c.begin() + (along.empty() ? 0 : 1), c.end());
      }
      const int n = k % 2 == 0 ? W : H;
      const std::string side = "patch " + str(p) + ", side " + str(k) + ": ";
      if (static_cast<int64_t>(along.size()) != int64_t{n} + 1)
        fail(path, side + "its arcs' chains pass " +
                       plural(along.size(), "mesh vertex", "mesh vertices") +
                       ", but the grid's side has " + str(int64_t{n} + 1) + " (" +
                       (k % 2 == 0 ? "width " : "height ") + str(n) + ")");
      for (int s = 0; s <= n; ++s) {
        const auto [i, j] = walk(k, s);
        if (g.at(i, j) != along[s])
          fail(index_path(i, j), side + "mesh vertex " + str(s) + " along the side is " +
                                     str(along[s]) + " in its arcs' chains, but " +
                                     str(g.at(i, j)) + " in the grid at " + at(i, j));
      }
    }
  }

  void check_path(int q) const {
    const std::vector<int>& path = t_.nonzero_paths[q];
    const std::string where = "/nonzero_paths/" + str(q);
    const std::string name = "non-zero path " + str(q) + ": ";
    if (path.empty()) fail(where, name + "empty, expected at least one half-arc");
    for (size_t i = 0; i < path.size(); ++i) {
      const std::string at = where + "/" + str(i);
      const int h = path[i];
      if (h < 0 || h >= t_.num_half_arcs())
        fail(at, name + "half-arc " + str(h) + " is out of range " + range(t_.num_half_arcs()));
      if (i > 0 && t_.half_arc_tail(h) != t_.half_arc_head(path[i - 1]))
        fail(at, name + "half-arc " + str(h) + " starts at vertex " + str(t_.half_arc_tail(h)) +
                     ", but the previous one ends at vertex " + str(t_.half_arc_head(path[i - 1])));
    }
  }

  const TMesh& t_;
  TMeshIncidence inc_;
};

}  // namespace

std::optional<TMeshIssue> find_tmesh_issue(const TMesh& tmesh, TMeshIncidence* incidence) {
  try {
    TMeshIncidence inc = Checker(tmesh).run();
    if (incidence) *incidence = std::move(inc);
    return std::nullopt;
  } catch (IssueFound& found) {
    return std::move(found.issue);
  }
}

TMeshIncidence validate_tmesh(const TMesh& tmesh, const std::string& source) {
  TMeshIncidence incidence;
  if (auto issue = find_tmesh_issue(tmesh, &incidence))
    throw InputError(source, "", std::move(issue->message));
  return incidence;
}

std::vector<int> arcs_along(const std::vector<int>& half_arcs) {
  std::vector<int> arcs;
  arcs.reserve(half_arcs.size());
  for (int h : half_arcs) arcs.push_back(TMesh::arc_of(h));
  std::sort(arcs.begin(), arcs.end());
  arcs.erase(std::unique(arcs.begin(), arcs.end()), arcs.end());
  return arcs;
}

int64_t side_length(const TMesh& tmesh, int patch, int side,
                    const std::vector<int64_t>& arc_length) {
  // Callers pass a validated T-mesh and one length per arc; a mismatch is a bug in the caller,
  // not bad input, hence a logic error rather than InputError.
  if (patch < 0 || patch >= tmesh.num_patches() || side < 0 || side >= 4)
    throw std::out_of_range("side_length: no patch " + str(patch) + ", side " + str(side));
  if (static_cast<int>(arc_length.size()) != tmesh.num_arcs())
    throw std::invalid_argument("side_length: " + plural(arc_length.size(), "length", "lengths") +
                                " for " + plural(tmesh.arc_ends.size(), "arc", "arcs"));
  int64_t sum = 0;
  for (int h : tmesh.patch_sides[patch][side]) sum += arc_length[TMesh::arc_of(h)];
  return sum;
}

}  // namespace bimdf::tmesh
