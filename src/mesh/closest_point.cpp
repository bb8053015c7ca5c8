#include "mesh/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "mesh/vec3.hpp"

namespace bimdf::detail {
namespace {

// Squared distance from p to the box [lo, hi].
double box_distance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double d = std::max({lo[i] - p[i], 0.0, p[i] - hi[i]});
    d2 += d * d;
  }
  return d2;
}

constexpr int kLeafSize = 8;

}  // namespace

Vec3 barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Cramer's rule on the 2×2 normal equations of p − a = u (b − a) + v (c − a).
  const Vec3 e1 = sub(b, a), e2 = sub(c, a), r = sub(p, a);
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  const double r1 = dot(r, e1), r2 = dot(r, e2);
  Vec3 w{0, (d22 * r1 - d12 * r2) / det, (d11 * r2 - d12 * r1) / det};
  w[0] = 1 - w[1] - w[2];
  double total = 0;
  for (double& x : w) total += x = std::clamp(x, 0.0, 1.0);
  for (double& x : w) x /= total;
  return w;
}

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = sub(b, a);
  const double length2 = dot(ab, ab);
  return length2 > 0 ? along(a, std::clamp(dot(sub(p, a), ab) / length2, 0.0, 1.0), ab) : a;
}

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return along(a, d1 / (d1 - d3), ab);
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return along(a, d2 / (d2 - d6), ac);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return along(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
  const double denominator = va + vb + vc;
  if (denominator <= 0) return a;  // degenerate triangle: its vertices were checked above
  const double v = vb / denominator, w = vc / denominator;
  return {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w};
}

namespace {

std::vector<int> all_faces(const TriangleMesh& mesh) {
  std::vector<int> faces(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) faces[f] = f;
  return faces;
}

}  // namespace

TriangleTree::TriangleTree(const TriangleMesh& mesh) : TriangleTree(mesh, all_faces(mesh)) {}

TriangleTree::TriangleTree(const TriangleMesh& mesh, std::vector<int> faces)
    : mesh_(mesh), order_(std::move(faces)) {
  std::vector<Vec3> centroid(mesh.num_faces());
  for (int f : order_)
    for (int i = 0; i < 3; ++i) {
      centroid[f][i] = 0;
      for (int v : mesh.faces[f]) centroid[f][i] += mesh.vertices[v][i] / 3;
    }
  if (!order_.empty()) build(0, static_cast<int>(order_.size()), centroid);
}

int TriangleTree::build(int first, int count, std::vector<Vec3>& centroid) {
  Node node;
  node.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
  node.hi = {-node.lo[0], -node.lo[1], -node.lo[2]};
  for (int i = first; i < first + count; ++i)
    for (int v : mesh_.faces[order_[i]])
      for (int d = 0; d < 3; ++d) {
        node.lo[d] = std::min(node.lo[d], mesh_.vertices[v][d]);
        node.hi[d] = std::max(node.hi[d], mesh_.vertices[v][d]);
      }
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (node.hi[d] - node.lo[d] > node.hi[axis] - node.lo[axis]) axis = d;
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count,
                   [&](int a, int b) { return centroid[a][axis] < centroid[b][axis]; });
  const int left = build(first, half, centroid);
  const int right = build(first + half, count - half, centroid);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void TriangleTree::search(int index, const Vec3& p, Hit& best) const {
  const Node& node = nodes_[index];
  if (node.left < 0) {
    for (int i = node.first; i < node.first + node.count; ++i) {
      const auto& f = mesh_.faces[order_[i]];
      const Vec3 q = closest_point_on_triangle(p, mesh_.vertices[f[0]], mesh_.vertices[f[1]],
                                               mesh_.vertices[f[2]]);
      const Vec3 d = sub(q, p);
      const double d2 = dot(d, d);
      if (d2 < best.distance) best = {order_[i], q, d2};
    }
    return;
  }
  const double dl = box_distance2(p, nodes_[node.left].lo, nodes_[node.left].hi);
  const double dr = box_distance2(p, nodes_[node.right].lo, nodes_[node.right].hi);
  const int near = dl <= dr ? node.left : node.right, far = dl <= dr ? node.right : node.left;
  if (std::min(dl, dr) < best.distance) search(near, p, best);
  if (std::max(dl, dr) < best.distance) search(far, p, best);
}

TriangleTree::Hit TriangleTree::closest(const Vec3& p) const {
  Hit best;
  best.distance = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best;
  search(0, p, best);
  best.distance = std::sqrt(best.distance);
  return best;
}

bool TriangleTree::any_within(int index, const Vec3& p, double radius2) const {
  const Node& node = nodes_[index];
  if (node.left < 0) {
    for (int i = node.first; i < node.first + node.count; ++i) {
      const auto& f = mesh_.faces[order_[i]];
      const Vec3 d = sub(closest_point_on_triangle(p, mesh_.vertices[f[0]], mesh_.vertices[f[1]],
                                                   mesh_.vertices[f[2]]),
                         p);
      if (dot(d, d) <= radius2) return true;
    }
    return false;
  }
  const double dl = box_distance2(p, nodes_[node.left].lo, nodes_[node.left].hi);
  const double dr = box_distance2(p, nodes_[node.right].lo, nodes_[node.right].hi);
  const int near = dl <= dr ? node.left : node.right, far = dl <= dr ? node.right : node.left;
  return (std::min(dl, dr) <= radius2 && any_within(near, p, radius2)) ||
         (std::max(dl, dr) <= radius2 && any_within(far, p, radius2));
}

bool TriangleTree::within(const Vec3& p, double radius) const {
  return !nodes_.empty() && any_within(0, p, radius * radius);
}

double TriangleTree::farther(const Vec3& p, double farthest) const {
  return within(p, farthest) ? farthest : std::max(farthest, closest(p).distance);
}

}  // namespace bimdf::detail
