// Irregular patches of a relaxed quantization (irregular_patch.hpp): pattern, point mapping,
// Tutte placement and evaluation on the input grid.
#include "tmesh/irregular_patch.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>

namespace bimdf::tmesh::detail {

std::string irregular_sides_issue(const std::array<int64_t, 4>& sides) {
  std::string list = "sides ";
  int64_t perimeter = 0;
  for (int k = 0; k < 4; ++k) list += (k ? ", " : "") + std::to_string(sides[k]);
  for (int64_t x : sides) perimeter += x;
  for (int64_t x : sides)
    if (x < 1) return list + ": an irregular patch needs every side ≥ 1";
  if (perimeter % 2 != 0) return list + ": the perimeter " + std::to_string(perimeter) + " is odd";
  // Patterns are built in ints; collapse already caps the total number of points far lower.
  if (perimeter > (int64_t{1} << 28)) return list + ": the perimeter is too large";
  return "";
}

quant::QuadPattern irregular_pattern(const std::array<int64_t, 4>& sides) {
  if (const std::string issue = irregular_sides_issue(sides); !issue.empty())
    throw std::invalid_argument(issue);
  return quant::make_quad_pattern({static_cast<int>(sides[0]), static_cast<int>(sides[1]),
                                   static_cast<int>(sides[2]), static_cast<int>(sides[3])});
}

std::vector<int> pattern_points(const quant::QuadPattern& pattern,
                                const std::array<std::vector<int>, 4>& side_points,
                                int first_interior) {
  std::vector<int> points;
  points.reserve(pattern.num_vertices());
  // Boundary vertex X0 + … + X(k−1) + s is position s of side k (see the header); the
  // last position of side k is the first of side k + 1, so it is left to that side.
  for (int k = 0; k < 4; ++k) {
    if (static_cast<int>(side_points[k].size()) != pattern.sides[k] + 1)
      throw std::logic_error("irregular patch: side " + std::to_string(k) + " has " +
                             std::to_string(side_points[k].size()) + " points for length " +
                             std::to_string(pattern.sides[k]));
    for (int s = 0; s < pattern.sides[k]; ++s) points.push_back(side_points[k][s]);
  }
  for (int v = pattern.perimeter(); v < pattern.num_vertices(); ++v)
    points.push_back(first_interior + (v - pattern.perimeter()));
  return points;
}

std::vector<std::array<double, 3>> tutte_interior(
    const quant::QuadPattern& pattern, const std::vector<std::array<double, 3>>& boundary) {
  const int P = pattern.perimeter(), n = pattern.num_vertices() - P;
  std::vector<std::array<double, 3>> result(n, {0, 0, 0});
  if (n == 0) return result;
  // Each undirected edge once: a quad edge shared by two quads must not count twice.
  std::set<std::pair<int, int>> edges;
  for (const auto& q : pattern.quads)
    for (int a = 0; a < 4; ++a)
      edges.insert({std::min(q[a], q[(a + 1) % 4]), std::max(q[a], q[(a + 1) % 4])});
  // The Laplacian restricted to the interior: positive definite, as every interior vertex is
  // joined to the boundary through the disk, so a Cholesky factorization solves it.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  std::vector<double> degree(n, 0);
  for (const auto& [u, v] : edges)
    for (const auto& [a, b] : {std::pair{u, v}, std::pair{v, u}}) {
      if (a < P) continue;
      degree[a - P] += 1;
      if (b < P)
        for (int d = 0; d < 3; ++d) rhs(a - P, d) += boundary[b][d];
      else
        entries.emplace_back(a - P, b - P, -1.0);
    }
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, degree[i]);
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  if (solver.info() != Eigen::Success)
    throw std::logic_error(
        "irregular patch: the pattern's interior is not connected to its "
        "boundary");
  const Eigen::MatrixXd x = solver.solve(rhs);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) result[i][d] = x(i, d);
  return result;
}

std::array<double, 3> point_on_grid(const QuadMesh& mesh, const PatchGrid& g,
                                    std::array<double, 2> uv) {
  const double u = std::clamp(uv[0], 0.0, double(g.width));
  const double v = std::clamp(uv[1], 0.0, double(g.height));
  const int i0 = std::min(static_cast<int>(u), g.width - 1);
  const int j0 = std::min(static_cast<int>(v), g.height - 1);
  const double s = u - i0, t = v - j0;
  const auto& x = mesh.vertices;
  const auto& a = x[g.at(i0, j0)];
  const auto& b = x[g.at(i0 + 1, j0)];
  const auto& c = x[g.at(i0 + 1, j0 + 1)];
  const auto& d = x[g.at(i0, j0 + 1)];
  std::array<double, 3> r;
  for (int k = 0; k < 3; ++k)
    r[k] = (1 - t) * ((1 - s) * a[k] + s * b[k]) + t * ((1 - s) * d[k] + s * c[k]);
  return r;
}

std::vector<std::array<double, 3>> place_pattern_interior(
    const quant::QuadPattern& pattern, const std::vector<std::array<double, 3>>& boundary,
    const QuadMesh* mesh, const PatchGrid* grid) {
  std::vector<std::array<double, 3>> inside = tutte_interior(pattern, boundary);
  if (mesh && grid)
    for (auto& x : inside) x = point_on_grid(*mesh, *grid, {x[0], x[1]});
  return inside;
}

}  // namespace bimdf::tmesh::detail
