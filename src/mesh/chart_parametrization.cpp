#include "mesh/chart_parametrization.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "bimdf/quant/quantize.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::quant::detail {
namespace {

using bimdf::detail::cross;
using bimdf::detail::dot;
using bimdf::detail::norm;
using bimdf::detail::sub;
using bimdf::detail::Vec3;

// tan(θ/2) of the angle θ between u and v, stable for all angles: sin θ / (1 + cos θ).
double tan_half_angle(const Vec3& u, const Vec3& v) {
  const double denominator = norm(u) * norm(v) + dot(u, v);
  return denominator > 0 ? norm(cross(u, v)) / denominator : 1e6;
}

}  // namespace

ChartParametrization parametrize_chart(const Layout& layout, int c,
                                       const std::vector<int64_t>& lengths,
                                       const std::vector<std::array<double, 2>>& corner,
                                       FlatteningWeights weights) {
  const Chart& chart = layout.charts[c];
  const TriangleMesh& mesh = layout.mesh;
  const int k = chart.valence();
  ChartParametrization param;
  std::unordered_map<int, int> local;
  const auto local_of = [&](int v) {
    auto [it, inserted] = local.emplace(v, static_cast<int>(param.mesh_vertex.size()));
    if (inserted) param.mesh_vertex.push_back(v);
    return it->second;
  };
  // Boundary first, in walking order, pinned to the pattern's polygon.
  const std::vector<int64_t> sides = side_lengths(layout, c, lengths);
  std::vector<std::array<double, 2>> pinned;
  for (int j = 0; j < k; ++j) {
    const Side& side = chart.sides[j];
    const int64_t side_length = sides[j];
    const auto &p = corner[j], &q = corner[(j + 1) % k];
    int64_t offset = 0;
    for (size_t i = 0; i < side.subsides.size(); ++i) {
      const Subside& sub = layout.subsides[side.subsides[i]];
      std::vector<int> chain = sub.vertices;
      if (side.reversed[i]) std::reverse(chain.begin(), chain.end());
      std::vector<double> arc(chain.size(), 0);
      for (size_t m = 1; m < chain.size(); ++m)
        arc[m] = arc[m - 1] +
                 norm(bimdf::detail::sub(mesh.vertices[chain[m]], mesh.vertices[chain[m - 1]]));
      const int64_t x = lengths[side.subsides[i]];
      for (size_t m = 0; m + 1 < chain.size(); ++m) {
        const double fraction =
            arc.back() > 0 ? arc[m] / arc.back() : double(m) / (chain.size() - 1);
        const double t = (offset + fraction * x) / double(side_length);
        if (local.count(chain[m]))
          throw std::runtime_error("chart " + std::to_string(c) + ": boundary passes vertex " +
                                   std::to_string(chain[m]) + " twice");
        local_of(chain[m]);
        pinned.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
      offset += x;
    }
  }
  const int nb = static_cast<int>(pinned.size());
  for (int f : chart.faces) {
    const auto& t = mesh.faces[f];
    param.triangles.push_back({local_of(t[0]), local_of(t[1]), local_of(t[2])});
  }
  const int n = static_cast<int>(param.mesh_vertex.size());
  param.uv.assign(n, {0, 0});
  std::copy(pinned.begin(), pinned.end(), param.uv.begin());
  const int ni = n - nb;
  if (ni == 0) return param;

  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  std::vector<double> diagonal(ni, 0);
  for (const auto& t : param.triangles) {
    for (int a = 0; a < 3; ++a) {
      const int i = t[a];
      if (i < nb) continue;
      const Vec3& xi = mesh.vertices[param.mesh_vertex[i]];
      const int j = t[(a + 1) % 3], l = t[(a + 2) % 3];
      const Vec3 u = sub(mesh.vertices[param.mesh_vertex[j]], xi);
      const Vec3 v = sub(mesh.vertices[param.mesh_vertex[l]], xi);
      const double half = tan_half_angle(u, v);
      constexpr double kTiny = 1e-300;
      for (auto [other, d] : {std::pair{j, norm(u)}, std::pair{l, norm(v)}}) {
        // Uniform: each interior edge is seen from its two triangles, so weight ½ each.
        const double w = weights == FlatteningWeights::Uniform ? 0.5 : half / std::max(d, kTiny);
        diagonal[i - nb] += w;
        if (other < nb) {
          rhs(i - nb, 0) += w * param.uv[other][0];
          rhs(i - nb, 1) += w * param.uv[other][1];
        } else {
          entries.emplace_back(i - nb, other - nb, -w);
        }
      }
    }
  }
  for (int i = 0; i < ni; ++i) entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> system(ni, ni);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("chart " + std::to_string(c) + ": parametrization failed");
  const Eigen::MatrixXd solution = solver.solve(rhs);
  for (int i = 0; i < ni; ++i) param.uv[nb + i] = {solution(i, 0), solution(i, 1)};
  return param;
}

namespace {

std::array<double, 3> barycentric(const std::array<double, 2>& p, const std::array<double, 2>& a,
                                  const std::array<double, 2>& b, const std::array<double, 2>& c) {
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  if (std::abs(det) < 1e-300) return {-1, -1, -1};
  const double l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (p[1] - a[1])) / det;
  const double l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])) / det;
  return {1 - l1 - l2, l1, l2};
}

}  // namespace

UvLocator::UvLocator(const ChartParametrization& param) : param_(param) {
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
  x0_ = y0_ = std::numeric_limits<double>::infinity();
  for (const auto& p : param.uv) {
    x0_ = std::min(x0_, p[0]), y0_ = std::min(y0_, p[1]);
    x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
  }
  const double area = std::max((x1 - x0_) * (y1 - y0_), 1e-12);
  cell_ = std::sqrt(area / std::max<size_t>(1, param.triangles.size())) * 1.5;
  nx_ = std::max(1, static_cast<int>((x1 - x0_) / cell_) + 1);
  ny_ = std::max(1, static_cast<int>((y1 - y0_) / cell_) + 1);
  cells_.assign(static_cast<size_t>(nx_) * ny_, {});
  for (int t = 0; t < static_cast<int>(param.triangles.size()); ++t) {
    double tx0 = x1, ty0 = y1, tx1 = x0_, ty1 = y0_;
    for (int v : param.triangles[t]) {
      tx0 = std::min(tx0, param.uv[v][0]), ty0 = std::min(ty0, param.uv[v][1]);
      tx1 = std::max(tx1, param.uv[v][0]), ty1 = std::max(ty1, param.uv[v][1]);
    }
    const int cx0 = std::clamp(static_cast<int>((tx0 - x0_) / cell_), 0, nx_ - 1);
    const int cx1 = std::clamp(static_cast<int>((tx1 - x0_) / cell_), 0, nx_ - 1);
    const int cy0 = std::clamp(static_cast<int>((ty0 - y0_) / cell_), 0, ny_ - 1);
    const int cy1 = std::clamp(static_cast<int>((ty1 - y0_) / cell_), 0, ny_ - 1);
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx) cells_[static_cast<size_t>(cy) * nx_ + cx].push_back(t);
  }
}

SurfacePoint UvLocator::locate(const std::array<double, 2>& p) const {
  const auto at = [&](int t) {
    const auto& tri = param_.triangles[t];
    return barycentric(p, param_.uv[tri[0]], param_.uv[tri[1]], param_.uv[tri[2]]);
  };
  SurfacePoint best;
  double best_margin = -std::numeric_limits<double>::infinity();
  const auto consider = [&](int t) {
    const std::array<double, 3> b = at(t);
    const double margin = std::min({b[0], b[1], b[2]});
    if (margin > best_margin) best_margin = margin, best = {t, b};
  };
  const int cx = std::clamp(static_cast<int>((p[0] - x0_) / cell_), 0, nx_ - 1);
  const int cy = std::clamp(static_cast<int>((p[1] - y0_) / cell_), 0, ny_ - 1);
  for (int t : cells_[static_cast<size_t>(cy) * nx_ + cx]) consider(t);
  if (best_margin < -1e-9)
    for (int t = 0; t < static_cast<int>(param_.triangles.size()); ++t) consider(t);
  // Clamp what rounding left outside and renormalize.
  double sum = 0;
  for (double& b : best.barycentric) sum += (b = std::max(b, 0.0));
  for (double& b : best.barycentric) b = sum > 0 ? b / sum : 1.0 / 3;
  return best;
}

}  // namespace bimdf::quant::detail
