// Seamless parametrization by per-edge images (seamless.hpp).
#include "layout/seamless.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bimdf::layout {
namespace {

using detail::Vec3;
using Mat2 = std::array<std::array<double, 2>, 2>;  // [row][column]

// A quarter-turn rotation k times counter-clockwise.
Mat2 quarter_turns(int k) {
  switch (((k % 4) + 4) % 4) {
    case 0:
      return {{{1, 0}, {0, 1}}};
    case 1:
      return {{{0, -1}, {1, 0}}};
    case 2:
      return {{{-1, 0}, {0, -1}}};
    default:
      return {{{0, 1}, {-1, 0}}};
  }
}

// How the image of half-edge h, seen in its face's cross frame, is made of its edge's two
// unknowns (x[2e], x[2e + 1]): image = coefficient · (x[2e], x[2e + 1]).
struct HalfEdgeImage {
  int edge = -1;
  Mat2 coefficient{};
};

}  // namespace

SeamlessMap seamless_parametrization(const SurfaceTopology& top, const FaceFrames& frames,
                                     const CrossField& field, const std::vector<bool>& curve_edge,
                                     const SeamlessOptions& options) {
  const TriangleMesh& m = top.mesh();
  const int F = m.num_faces(), E = top.num_edges();
  // The cross frame (a, b) of every face: the field's direction and a quarter turn from it.
  std::vector<Vec3> a(F), b(F);
  for (int f = 0; f < F; ++f) {
    a[f] = detail::normalized(field.direction[f]);
    b[f] = detail::cross(frames.normal[f], a[f]);
  }
  const auto vector_of = [&](int h) {
    return detail::sub(m.vertices[top.to(h)], m.vertices[top.from(h)]);
  };
  const auto coords = [&](int f, const Vec3& x) {
    return std::array<double, 2>{detail::dot(a[f], x), detail::dot(b[f], x)};
  };

  // Unknowns: two per edge. On a curve edge, which component lies across the curve (the
  // field there is aligned to it, so the edge's image in its frame is close to an axis).
  const int n = 2 * E;
  std::vector<int> across(E, -1);
  for (int e = 0; e < E; ++e) {
    if (!curve_edge[e]) continue;
    const int h = top.edge_half_edge(e);
    const auto c = coords(h / 3, vector_of(h));
    across[e] = std::fabs(c[0]) < std::fabs(c[1]) ? 0 : 1;
  }
  std::vector<HalfEdgeImage> image(3 * F);
  for (int h = 0; h < 3 * F; ++h) {
    const int e = top.edge(h), home = top.edge_half_edge(e);
    image[h].edge = e;
    if (h == home) {
      image[h].coefficient = quarter_turns(0);
      continue;
    }
    // The matching: the quarter turns that carry the home face's view of the edge to this
    // face's view; the opposite half-edge's image is minus that.
    const Vec3 x = vector_of(home);
    const auto ch = coords(home / 3, x), cf = coords(h / 3, x);
    int best = 0;
    double best_d = 1e300;
    for (int k = 0; k < 4; ++k) {
      const Mat2 r = quarter_turns(k);
      const double dx = r[0][0] * ch[0] + r[0][1] * ch[1] - cf[0];
      const double dy = r[1][0] * ch[0] + r[1][1] * ch[1] - cf[1];
      if (dx * dx + dy * dy < best_d) best_d = dx * dx + dy * dy, best = k;
    }
    if (!options.matching_offset.empty()) best += options.matching_offset[e];
    Mat2 r = quarter_turns(best);
    for (auto& row : r)
      for (double& v : row) v = -v;
    image[h].coefficient = r;
  }

  // Least squares: rows of (fit of the map to the cross frame, closure of the triangle). The
  // fit's weight per face grows, round by round, where the map came out folded or far from
  // the frame (MIQ's "local stiffening"): that pushes distortion away from the few faces
  // around close singularities, where least squares concentrates it, into their neighbours.
  std::vector<Mat2> inverse_m(F);
  std::vector<double> longest(F, 0);
  for (int f = 0; f < F; ++f) {
    const auto e0 = coords(f, vector_of(3 * f)), e1 = coords(f, vector_of(3 * f + 1));
    const double det = e0[0] * e1[1] - e1[0] * e0[1];
    if (!(std::fabs(det) > 0)) throw std::invalid_argument("seamless: a degenerate face");
    inverse_m[f] = {{{e1[1] / det, -e1[0] / det}, {-e0[1] / det, e0[0] / det}}};
    for (int i = 0; i < 3; ++i)
      longest[f] = std::max(longest[f], detail::norm(vector_of(3 * f + i)));
  }
  const auto image_of = [&](const Eigen::VectorXd& x, int h) {
    const HalfEdgeImage& im = image[h];
    std::array<double, 2> v{0, 0};
    for (int c = 0; c < 2; ++c) {
      v[0] += im.coefficient[0][c] * x[2 * im.edge + c];
      v[1] += im.coefficient[1][c] * x[2 * im.edge + c];
    }
    return v;
  };
  // J = [q0 q1] · M⁻¹ in face f's cross frame: J[r][j] = q0_r N[0][j] + q1_r N[1][j].
  const auto jacobian = [&](const Eigen::VectorXd& x, int f) {
    const auto q0 = image_of(x, 3 * f), q1 = image_of(x, 3 * f + 1);
    Mat2 J;
    for (int r = 0; r < 2; ++r)
      for (int j = 0; j < 2; ++j) J[r][j] = q0[r] * inverse_m[f][0][j] + q1[r] * inverse_m[f][1][j];
    return J;
  };
  std::vector<double> stiffness(F, 1);
  Eigen::VectorXd x;
  for (int round = 0; round <= options.stiffening_rounds; ++round) {
    std::vector<Eigen::Triplet<double>> rows;
    std::vector<double> rhs;
    const auto add_term = [&](int row, int h, int component, double weight) {
      const HalfEdgeImage& im = image[h];
      for (int c = 0; c < 2; ++c) {
        const double w = weight * im.coefficient[component][c];
        if (w != 0) rows.emplace_back(row, 2 * im.edge + c, w);
      }
    };
    for (int f = 0; f < F; ++f) {
      const double s = std::sqrt(frames.area[f] * stiffness[f]);
      for (int r = 0; r < 2; ++r)
        for (int j = 0; j < 2; ++j) {
          const int row = static_cast<int>(rhs.size());
          add_term(row, 3 * f, r, s * inverse_m[f][0][j]);
          add_term(row, 3 * f + 1, r, s * inverse_m[f][1][j]);
          rhs.push_back(r == j ? s : 0);
        }
      const double closure = 1e3 * s / longest[f];
      for (int r = 0; r < 2; ++r) {
        const int row = static_cast<int>(rhs.size());
        for (int i = 0; i < 3; ++i) add_term(row, 3 * f + i, r, closure);
        rhs.push_back(0);
      }
    }
    // Curves: the image's component across the curve towards zero, weighted against the fit
    // (a hard zero folds the map where noisy curves zigzag across the field).
    for (int e = 0; e < E; ++e) {
      if (across[e] < 0) continue;
      const int h = top.edge_half_edge(e), f = h / 3;
      const double w = options.curve_weight * std::sqrt(frames.area[f] * stiffness[f]) /
                       detail::norm(vector_of(h));
      rows.emplace_back(static_cast<int>(rhs.size()), 2 * e + across[e], w);
      rhs.push_back(0);
    }
    Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(rhs.size()), n);
    A.setFromTriplets(rows.begin(), rows.end());
    const Eigen::VectorXd bvec = Eigen::Map<const Eigen::VectorXd>(rhs.data(), rhs.size());
    const Eigen::SparseMatrix<double> normal = (A.transpose() * A).pruned();
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("seamless parametrization: the normal equations did not factor");
    x = solver.solve(A.transpose() * bvec);
    bool stiffened = false;
    for (int f = 0; f < F; ++f) {
      const Mat2 J = jacobian(x, f);
      const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      // How far J is from a rotation-free similarity: its singular values' spread, and folds.
      const double frob =
          std::sqrt(J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1]);
      const double conformal = det > 0 ? frob * frob / (2 * det) : 1e3;  // 1: no shear
      if (conformal > options.stiffen_above) {
        stiffness[f] *= std::min(conformal, 10.0);
        stiffened = true;
      }
    }
    if (!stiffened) break;
  }

  SeamlessMap out;
  out.iso_direction.resize(F);
  out.gradient.resize(F);
  double area_sum = 0, distortion = 0;
  for (int f = 0; f < F; ++f) {
    const auto q0 = image_of(x, 3 * f), q1 = image_of(x, 3 * f + 1), q2 = image_of(x, 3 * f + 2);
    out.max_closure = std::max(
        out.max_closure, std::hypot(q0[0] + q1[0] + q2[0], q0[1] + q1[1] + q2[1]) / longest[f]);
    const Mat2 J = jacobian(x, f);
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    distortion += frames.area[f] * std::sqrt((J[0][0] - 1) * (J[0][0] - 1) + J[0][1] * J[0][1] +
                                             J[1][0] * J[1][0] + (J[1][1] - 1) * (J[1][1] - 1));
    area_sum += frames.area[f];
    if (!(det > 0)) ++out.folded_faces;
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 3; ++k) out.gradient[f][r][k] = J[r][0] * a[f][k] + J[r][1] * b[f][k];
    if (!(std::fabs(det) > 1e-12)) {
      out.iso_direction[f] = {a[f], b[f]};
      continue;
    }
    // Columns of J⁻¹, in cross-frame coordinates, then in 3D.
    const std::array<double, 2> du = {J[1][1] / det, -J[1][0] / det};
    const std::array<double, 2> dv = {-J[0][1] / det, J[0][0] / det};
    const auto to3 = [&](const std::array<double, 2>& c) {
      return Vec3{c[0] * a[f][0] + c[1] * b[f][0], c[0] * a[f][1] + c[1] * b[f][1],
                  c[0] * a[f][2] + c[1] * b[f][2]};
    };
    out.iso_direction[f] = {to3(du), to3(dv)};
  }
  out.mean_distortion = area_sum > 0 ? distortion / area_sum : 0;
  return out;
}

}  // namespace bimdf::layout
