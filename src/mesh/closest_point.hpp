// Closest points on a triangle mesh: a bounding-volume hierarchy over its triangles, queried by
// branch and bound. Used to measure distances to the input surface and to project onto it.
#pragma once

#include <array>
#include <vector>

#include "bimdf/mesh.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::detail {

// The point of triangle (a, b, c) closest to p (by Voronoi regions of its vertices and edges).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// The point of segment (a, b) closest to p (a for a segment of length 0).
Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

// The barycentric coordinates of p's projection onto the plane of triangle (a, b, c), each
// clamped to [0, 1] and renormalized (equal thirds for a degenerate triangle).
Vec3 barycentric_coordinates(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
 public:
  // Keeps a reference to `mesh`, which must outlive the tree. With `faces`, only those
  // triangles are searched.
  explicit TriangleTree(const TriangleMesh& mesh);
  TriangleTree(const TriangleMesh& mesh, std::vector<int> faces);

  struct Hit {
    int face = -1;
    Vec3 point{};
    double distance = 0;
  };
  // The closest point of the mesh to p (face −1 for an empty mesh).
  Hit closest(const Vec3& p) const;
  // Whether some triangle is within `radius` of p: the search starts with that bound, so it
  // visits far fewer nodes than closest() when the answer is near.
  bool within(const Vec3& p, double radius) const;
  // max(farthest, distance from p to the mesh), for taking the farthest of many points (a
  // Hausdorff distance): only a point beyond the running maximum needs its distance, and asking
  // whether one is within that bound is a much cheaper search than closest().
  double farther(const Vec3& p, double farthest) const;

 private:
  struct Node {
    Vec3 lo, hi;
    int first = 0, count = 0;  // leaf: faces order_[first, first + count)
    int left = -1, right = -1;
  };
  int build(int first, int count, std::vector<Vec3>& centroid);
  void search(int node, const Vec3& p, Hit& best) const;
  bool any_within(int node, const Vec3& p, double radius2) const;

  const TriangleMesh& mesh_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace bimdf::detail
