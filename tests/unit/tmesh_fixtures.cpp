#include "tmesh_fixtures.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace bimdf::test {
namespace {

using Vec = std::array<double, 3>;

Vec add(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec scale(const Vec& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// A tiny deterministic generator (splitmix64): the same numbers on every platform, unlike the
// standard distributions.
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<uint64_t>(n)); }
  int between(int lo, int hi) { return lo + below(hi - lo + 1); }

 private:
  uint64_t state_;
};

std::pair<int, int> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// A planar grid of cells with some cells removed, split or merged (see random_quad_mesh).
PolyMesh random_planar_polygons(Random& rng, std::string& summary) {
  const int W = rng.between(2, 5), H = rng.between(2, 5);
  auto vid = [&](int x, int y) { return y * (W + 1) + x; };
  std::vector<int> state(W * H, 0);  // 0 quad, 1 removed, 2 taken by a merge
  auto cell = [&](int x, int y) -> int& { return state[y * W + x]; };
  int removed = 0, splits = 0, merges = 0;
  if (rng.below(2)) {
    const int corner = rng.below(4);
    cell(corner & 1 ? W - 1 : 0, corner & 2 ? H - 1 : 0) = 1;
    removed = 1;
  }
  // Merges never touch each other (blocked cells), so that no vertex loses two edges and
  // every interior vertex keeps at least three.
  std::vector<uint8_t> blocked(W * H, 0);
  auto block_around = [&](int x0, int y0, int x1, int y1) {
    for (int y = std::max(0, y0 - 1); y <= std::min(H - 1, y1 + 1); ++y)
      for (int x = std::max(0, x0 - 1); x <= std::min(W - 1, x1 + 1); ++x) blocked[y * W + x] = 1;
  };
  PolyMesh poly;
  for (int y = 0; y <= H; ++y)
    for (int x = 0; x <= W; ++x) poly.vertices.push_back({double(x), double(y), 0});
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      if (cell(x, y) != 0) continue;
      const int a = vid(x, y), b = vid(x + 1, y), c = vid(x + 1, y + 1), d = vid(x, y + 1);
      const int r = rng.below(100);
      const bool free_here = !blocked[y * W + x];
      if (r < 20) {
        if (rng.below(2)) {
          poly.faces.push_back({a, b, c});
          poly.faces.push_back({a, c, d});
        } else {
          poly.faces.push_back({a, b, d});
          poly.faces.push_back({b, c, d});
        }
        ++splits;
      } else if (r < 35 && free_here && x + 1 < W && cell(x + 1, y) == 0 &&
                 !blocked[y * W + x + 1]) {
        poly.faces.push_back({a, b, vid(x + 2, y), vid(x + 2, y + 1), c, d});
        cell(x + 1, y) = 2;
        block_around(x, y, x + 1, y);
        ++merges;
      } else if (r < 50 && free_here && y + 1 < H && cell(x, y + 1) == 0 &&
                 !blocked[(y + 1) * W + x]) {
        poly.faces.push_back({a, b, c, vid(x + 1, y + 2), vid(x, y + 2), d});
        cell(x, y + 1) = 2;
        block_around(x, y, x, y + 1);
        ++merges;
      } else {
        poly.faces.push_back({a, b, c, d});
      }
    }
  }
  summary = "planar " + std::to_string(W) + "x" + std::to_string(H) + " cells, " +
            std::to_string(removed) + " removed, " + std::to_string(splits) + " split, " +
            std::to_string(merges) + " merged";
  return poly;
}

// An n-gonal prism of `rings` stacked rings of side quads, with or without its caps.
PolyMesh prism(int n, int rings, bool bottom_cap, bool top_cap) {
  PolyMesh poly;
  for (int level = 0; level <= rings; ++level)
    for (int i = 0; i < n; ++i) {
      const double t = 2 * std::numbers::pi * i / n;
      poly.vertices.push_back({std::cos(t), std::sin(t), 1.5 * level / rings});
    }
  for (int level = 0; level < rings; ++level)
    for (int i = 0; i < n; ++i) {
      const int a = level * n + i, b = level * n + (i + 1) % n;
      poly.faces.push_back({a, b, b + n, a + n});
    }
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(rings * n + i);
  }
  if (bottom_cap) poly.faces.push_back(bottom);
  if (top_cap) poly.faces.push_back(top);
  return poly;
}

}  // namespace

PolyMesh to_poly(const QuadMesh& mesh) {
  PolyMesh poly;
  poly.vertices = mesh.vertices;
  for (const auto& q : mesh.quads) poly.faces.push_back({q[0], q[1], q[2], q[3]});
  return poly;
}

QuadMesh grid_mesh(int w, int h) {
  QuadMesh m;
  for (int y = 0; y <= h; ++y)
    for (int x = 0; x <= w; ++x) m.vertices.push_back({double(x), double(y), 0});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int v = y * (w + 1) + x;
      m.quads.push_back({v, v + 1, v + w + 2, v + w + 1});
    }
  return m;
}

QuadMesh torus_mesh(int w, int h, int shift) {
  if (w < 3 || h < 3) throw std::invalid_argument("torus_mesh needs w, h >= 3");
  QuadMesh m;
  const double R = 3, r = 1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = 2 * std::numbers::pi * (x + double(shift) * y / h) / w;
      const double v = 2 * std::numbers::pi * y / h;
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto vid = [&](int x, int y) {
    if (y == h) {
      y = 0;
      x += shift;
    }
    return y * w + ((x % w) + w) % w;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      m.quads.push_back({vid(x, y), vid(x + 1, y), vid(x + 1, y + 1), vid(x, y + 1)});
  return m;
}

QuadMesh cube_mesh() {
  QuadMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  // Counter-clockwise seen from outside (vertex bit 0 = x, 1 = y, 2 = z).
  m.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

QuadMesh catmull_clark(const PolyMesh& mesh) {
  const int V = static_cast<int>(mesh.vertices.size());
  const int F = static_cast<int>(mesh.faces.size());
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (int f = 0; f < F; ++f) {
    const auto& face = mesh.faces[f];
    for (size_t i = 0; i < face.size(); ++i)
      edge_faces[key(face[i], face[(i + 1) % face.size()])].push_back(f);
  }
  QuadMesh out;
  out.vertices.resize(V);
  std::vector<Vec> face_point(F);
  for (int f = 0; f < F; ++f) {
    Vec s{0, 0, 0};
    for (int v : mesh.faces[f]) s = add(s, mesh.vertices[v]);
    face_point[f] = scale(s, 1.0 / mesh.faces[f].size());
  }
  std::map<std::pair<int, int>, int> edge_point;
  std::vector<Vec> face_sum(V, {0, 0, 0}), mid_sum(V, {0, 0, 0}), border_sum(V, {0, 0, 0});
  std::vector<int> faces_at(V, 0), edges_at(V, 0), border_at(V, 0);
  for (const auto& [e, faces] : edge_faces) {
    const Vec& a = mesh.vertices[e.first];
    const Vec& b = mesh.vertices[e.second];
    const Vec mid = scale(add(a, b), 0.5);
    Vec p = mid;
    if (faces.size() == 2)
      p = scale(add(add(a, b), add(face_point[faces[0]], face_point[faces[1]])), 0.25);
    edge_point[e] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(p);
    for (int v : {e.first, e.second}) {
      mid_sum[v] = add(mid_sum[v], mid);
      ++edges_at[v];
      if (faces.size() == 1) {
        border_sum[v] = add(border_sum[v], mesh.vertices[v == e.first ? e.second : e.first]);
        ++border_at[v];
      }
    }
  }
  for (int f = 0; f < F; ++f)
    for (int v : mesh.faces[f]) {
      face_sum[v] = add(face_sum[v], face_point[f]);
      ++faces_at[v];
    }
  for (int v = 0; v < V; ++v) {
    const Vec& p = mesh.vertices[v];
    if (edges_at[v] == 0) {
      out.vertices[v] = p;  // unused vertex: kept, still unused
    } else if (border_at[v] == 0) {
      const double n = edges_at[v];
      out.vertices[v] =
          add(add(scale(face_sum[v], 1.0 / (n * n)), scale(mid_sum[v], 2.0 / (n * n))),
              scale(p, (n - 3) / n));
    } else if (faces_at[v] == 1) {
      out.vertices[v] = p;  // a corner of a single face stays put
    } else {
      out.vertices[v] = add(scale(p, 0.75), scale(border_sum[v], 0.125));
    }
  }
  const int first_face_point = static_cast<int>(out.vertices.size());
  for (int f = 0; f < F; ++f) out.vertices.push_back(face_point[f]);
  for (int f = 0; f < F; ++f) {
    const auto& face = mesh.faces[f];
    const size_t n = face.size();
    for (size_t i = 0; i < n; ++i) {
      const int v = face[i], next = face[(i + 1) % n], prev = face[(i + n - 1) % n];
      out.quads.push_back(
          {v, edge_point.at(key(v, next)), first_face_point + f, edge_point.at(key(prev, v))});
    }
  }
  return out;
}

QuadMesh catmull_clark(const QuadMesh& mesh) { return catmull_clark(to_poly(mesh)); }

QuadMesh subdivided_cube(int levels) {
  QuadMesh m = cube_mesh();
  for (int i = 0; i < levels; ++i) m = catmull_clark(m);
  return m;
}

QuadMesh linear_subdivision(const QuadMesh& mesh, int k) {
  if (k < 1) throw std::invalid_argument("linear_subdivision needs k >= 1");
  QuadMesh out;
  out.vertices = mesh.vertices;
  // Edge (a, b), a < b: its k − 1 inner points from a to b.
  std::map<std::pair<int, int>, std::vector<int>> edge_points;
  auto lerp = [](const Vec& a, const Vec& b, double t) {
    return add(scale(a, 1 - t), scale(b, t));
  };
  auto edge_point = [&](int a, int b, int i) {  // i-th of k − 1 points walking from a to b
    auto [it, fresh] = edge_points.try_emplace(key(a, b));
    if (fresh) {
      const int lo = std::min(a, b), hi = std::max(a, b);
      for (int t = 1; t < k; ++t) {
        it->second.push_back(static_cast<int>(out.vertices.size()));
        out.vertices.push_back(lerp(mesh.vertices[lo], mesh.vertices[hi], double(t) / k));
      }
    }
    return a < b ? it->second[i - 1] : it->second[k - 1 - i];
  };
  for (const auto& q : mesh.quads) {
    // Local grid (i, j), 0..k: (0,0) = q[0], (k,0) = q[1], (k,k) = q[2], (0,k) = q[3].
    std::vector<int> g((k + 1) * (k + 1));
    auto at = [&](int i, int j) -> int& { return g[j * (k + 1) + i]; };
    at(0, 0) = q[0], at(k, 0) = q[1], at(k, k) = q[2], at(0, k) = q[3];
    for (int t = 1; t < k; ++t) {
      at(t, 0) = edge_point(q[0], q[1], t);
      at(k, t) = edge_point(q[1], q[2], t);
      at(t, k) = edge_point(q[3], q[2], t);
      at(0, t) = edge_point(q[0], q[3], t);
    }
    for (int j = 1; j < k; ++j)
      for (int i = 1; i < k; ++i) {
        const double s = double(i) / k, t = double(j) / k;
        at(i, j) = static_cast<int>(out.vertices.size());
        out.vertices.push_back(lerp(lerp(mesh.vertices[q[0]], mesh.vertices[q[1]], s),
                                    lerp(mesh.vertices[q[3]], mesh.vertices[q[2]], s), t));
      }
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i)
        out.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  }
  return out;
}

QuadMesh random_quad_mesh(uint64_t seed, std::string* description, bool with_tubes) {
  Random rng(seed * 0x2545f4914f6cdd1dULL + 17);
  std::string summary;
  PolyMesh coarse;
  int steps = 1, max_k = 3;
  if (rng.below(4) == 3) {
    const int n = rng.between(3, 6);
    // Prisms keep their first draws, so that older seeds still give the same closed prism.
    switch (rng.below(4)) {
      case 0:
        coarse = prism(n, 1, true, true);
        summary = std::to_string(n) + "-gonal prism";
        break;
      case 1:
        coarse = prism(n, 1, true, true);
        summary = std::to_string(n) + "-gonal prism, smoothed";
        steps = 2, max_k = 2;
        break;
      case 2: {
        if (!with_tubes) {
          coarse = prism(n, 1, true, true);
          summary = std::to_string(n) + "-gonal prism, smoothed";
          steps = 2, max_k = 2;
          break;
        }
        const int rings = rng.between(1, 3);
        coarse = prism(n, rings, false, false);
        summary = std::to_string(n) + "-gonal open tube of " + std::to_string(rings) + " rings";
        break;
      }
      default:
        coarse = prism(n, 2, true, false);
        summary = std::to_string(n) + "-gonal cup, smoothed";
        steps = 2, max_k = 2;
    }
  } else {
    coarse = random_planar_polygons(rng, summary);
  }
  QuadMesh mesh = catmull_clark(coarse);
  if (steps == 2) mesh = catmull_clark(mesh);
  const int r = rng.below(5);
  const int k = std::min(max_k, r < 2 ? 1 : r < 4 ? 2 : 3);
  mesh = linear_subdivision(mesh, k);
  if (description)
    *description = "seed " + std::to_string(seed) + ": " + summary + ", Catmull-Clark, " +
                   (steps == 2 ? "twice, " : "") + std::to_string(k) + "x" + std::to_string(k) +
                   " subdivision, " + std::to_string(mesh.num_quads()) + " quads";
  return mesh;
}

namespace {
bool thin_strip_cell(int x, int y) {
  if (x < 0 || x >= 10 || y < 0 || y >= 8) return false;
  if (x < 3 && y < 3) return false;
  if (x >= 7 && y >= 4) return false;
  return true;
}
bool thin_strip_used(int x, int y) {
  return thin_strip_cell(x - 1, y - 1) || thin_strip_cell(x, y - 1) || thin_strip_cell(x - 1, y) ||
         thin_strip_cell(x, y);
}
}  // namespace

int thin_strip_vertex(int x, int y) {
  if (!thin_strip_used(x, y)) return -1;
  int id = 0;
  for (int yy = 0; yy <= 8; ++yy)
    for (int xx = 0; xx <= 10; ++xx) {
      if (xx == x && yy == y) return id;
      if (thin_strip_used(xx, yy)) ++id;
    }
  return -1;
}

QuadMesh thin_strip_mesh() {
  QuadMesh m;
  for (int y = 0; y <= 8; ++y)
    for (int x = 0; x <= 10; ++x)
      if (thin_strip_used(x, y)) m.vertices.push_back({double(x), double(y), 0});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 10; ++x)
      if (thin_strip_cell(x, y))
        m.quads.push_back({thin_strip_vertex(x, y), thin_strip_vertex(x + 1, y),
                           thin_strip_vertex(x + 1, y + 1), thin_strip_vertex(x, y + 1)});
  return m;
}

QuadMesh folded_grid(int w, int h, int fold_x, double angle_deg) {
  QuadMesh m = grid_mesh(w, h);
  const double t = angle_deg * std::numbers::pi / 180;
  for (auto& p : m.vertices)
    if (p[0] > fold_x) {
      const double d = p[0] - fold_x;
      p = {fold_x + d * std::cos(t), p[1], d * std::sin(t)};
    }
  return m;
}

}  // namespace bimdf::test
