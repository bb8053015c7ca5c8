// The smoothest cross field with feature, border and curvature alignment, and its vertex
// indices (cross_field.hpp; Knöppel et al. 2013 in its face-based form).
#include "bimdf/layout/cross_field.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

#include "layout/face_frames.hpp"
#include "layout/feature_flags.hpp"
#include "layout/surface_topology.hpp"

namespace bimdf::layout {

FaceFrames::FaceFrames(const TriangleMesh& mesh) {
  const int F = mesh.num_faces();
  e1.resize(F), e2.resize(F), normal.resize(F), area.resize(F), centroid.resize(F);
  for (int f = 0; f < F; ++f) {
    const auto& t = mesh.faces[f];
    const detail::Vec3 n = detail::triangle_normal(mesh, f);
    area[f] = 0.5 * detail::norm(n);
    normal[f] = detail::normalized(n);
    e1[f] = detail::normalized(detail::sub(mesh.vertices[t[1]], mesh.vertices[t[0]]));
    e2[f] = detail::cross(normal[f], e1[f]);
    for (int k = 0; k < 3; ++k)
      centroid[f][k] =
          (mesh.vertices[t[0]][k] + mesh.vertices[t[1]][k] + mesh.vertices[t[2]][k]) / 3;
  }
}

namespace {

using Complex = std::complex<double>;
using detail::Vec3;

Vec3 edge_vector(const SurfaceTopology& top, int h) {
  return detail::sub(top.mesh().vertices[top.to(h)], top.mesh().vertices[top.from(h)]);
}

// The transport angle across the edge of half-edge h, from h's face to its opposite's: a
// direction of angle a in the first face's frame has angle a + transport in the second's.
double transport(const SurfaceTopology& top, const FaceFrames& frames, int h) {
  const Vec3 d = edge_vector(top, h);
  return frames.angle(top.opposite(h) / 3, d) - frames.angle(h / 3, d);
}

// The weight of the dual edge across h's edge: edge length over the distance between the two
// faces' centroids (the discrete Dirichlet energy of piecewise-constant functions).
double dual_weight(const SurfaceTopology& top, const FaceFrames& frames, int h) {
  const int f = h / 3, k = top.opposite(h) / 3;
  return detail::norm(edge_vector(top, h)) /
         std::max(detail::norm(detail::sub(frames.centroid[f], frames.centroid[k])), 1e-300);
}

// Per face: the cross (as e^{4iθ}) its feature and border edges ask for, or 0 for a face with
// none. Edges of one face that disagree as crosses (e.g. 45° apart) are averaged by length;
// where they nearly cancel, the longest edge decides.
std::vector<Complex> feature_crosses(const SurfaceTopology& top, const FaceFrames& frames,
                                     const std::vector<bool>& on_curve) {
  const int F = top.mesh().num_faces();
  std::vector<Complex> fixed(F, 0.0);
  for (int f = 0; f < F; ++f) {
    Complex sum = 0;
    double total = 0, longest = 0;
    Complex longest_cross = 0;
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i;
      if (!on_curve[top.edge(h)]) continue;
      const Vec3 d = edge_vector(top, h);
      const double len = detail::norm(d);
      const Complex c = std::polar(1.0, 4 * frames.angle(f, d));
      sum += len * c;
      total += len;
      if (len > longest) longest = len, longest_cross = c;
    }
    if (total == 0) continue;
    fixed[f] = std::abs(sum) > 0.25 * total ? sum / std::abs(sum) : longest_cross;
  }
  return fixed;
}

// Per face: the principal-curvature cross q_f (as e^{4iθ}) and the curvature difference
// |κ1 − κ2| there, from the edge-based shape operator (Cohen-Steiner & Morvan 2003): each edge
// adds its signed dihedral angle × length × d̂d̂ᵀ to its two vertices; a face takes the mean of
// its vertices' operators, then the operators diffuse for `diffusion_time` (a squared length).
void curvature_crosses(const SurfaceTopology& top, const FaceFrames& frames, double diffusion_time,
                       std::vector<Complex>& cross, std::vector<double>& difference) {
  const TriangleMesh& m = top.mesh();
  const int V = m.num_vertices(), F = m.num_faces();
  using Tensor = std::array<double, 6>;  // xx, xy, xz, yy, yz, zz
  std::vector<Tensor> vertex_tensor(V, Tensor{});
  std::vector<double> vertex_area(V, 0);
  for (int f = 0; f < F; ++f)
    for (int v : m.faces[f]) vertex_area[v] += frames.area[f] / 3;
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e), g = top.opposite(h);
    if (g < 0) continue;
    const Vec3 d = edge_vector(top, h);
    const double len = detail::norm(d);
    const Vec3 u = {d[0] / len, d[1] / len, d[2] / len};
    const Vec3& a = frames.normal[h / 3];
    const Vec3& b = frames.normal[g / 3];
    const double beta = std::atan2(detail::dot(detail::cross(a, b), u), detail::dot(a, b));
    const double s = 0.5 * beta * len;
    const Tensor t = {s * u[0] * u[0], s * u[0] * u[1], s * u[0] * u[2],
                      s * u[1] * u[1], s * u[1] * u[2], s * u[2] * u[2]};
    for (int v : {top.from(h), top.to(h)})
      for (int k = 0; k < 6; ++k) vertex_tensor[v][k] += t[k];
  }
  std::vector<Tensor> face_tensor(F, Tensor{});
  for (int f = 0; f < F; ++f)
    for (int v : m.faces[f])
      for (int k = 0; k < 6; ++k)
        face_tensor[f][k] += vertex_tensor[v][k] / (3 * std::max(vertex_area[v], 1e-300));
  // Implicit diffusion (B + t L) T = B T0 over the faces' dual graph: the operator at the
  // scale where the field should follow it, not at the mesh's noise.
  if (diffusion_time > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int f = 0; f < F; ++f) entries.emplace_back(f, f, frames.area[f]);
    for (int e = 0; e < top.num_edges(); ++e) {
      const int h = top.edge_half_edge(e), g = top.opposite(h);
      if (g < 0) continue;
      const int f = h / 3, k = g / 3;
      const double w = diffusion_time * dual_weight(top, frames, h);
      entries.emplace_back(f, f, w);
      entries.emplace_back(k, k, w);
      entries.emplace_back(f, k, -w);
      entries.emplace_back(k, f, -w);
    }
    Eigen::SparseMatrix<double> matrix(F, F);
    matrix.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    Eigen::MatrixXd rhs(F, 6);
    for (int f = 0; f < F; ++f)
      for (int k = 0; k < 6; ++k) rhs(f, k) = frames.area[f] * face_tensor[f][k];
    const Eigen::MatrixXd smoothed = solver.solve(rhs);
    for (int f = 0; f < F; ++f)
      for (int k = 0; k < 6; ++k) face_tensor[f][k] = smoothed(f, k);
  }
  cross.assign(F, 0.0);
  difference.assign(F, 0);
  for (int f = 0; f < F; ++f) {
    const Tensor& t = face_tensor[f];
    const auto apply = [&](const Vec3& x) -> Vec3 {
      return {t[0] * x[0] + t[1] * x[1] + t[2] * x[2], t[1] * x[0] + t[3] * x[1] + t[4] * x[2],
              t[2] * x[0] + t[4] * x[1] + t[5] * x[2]};
    };
    const Vec3 s1 = apply(frames.e1[f]), s2 = apply(frames.e2[f]);
    const double a = detail::dot(frames.e1[f], s1), b = detail::dot(frames.e1[f], s2),
                 c = detail::dot(frames.e2[f], s2);
    // The principal direction's angle φ = atan2(2b, a − c) / 2, so the cross e^{4iφ} is the
    // square of the unit (a − c, 2b).
    const double diff = std::hypot(a - c, 2 * b);
    difference[f] = diff;
    if (diff > 0) {
      const Complex z(a - c, 2 * b);
      cross[f] = (z / diff) * (z / diff);
    }
  }
}

}  // namespace

CrossField compute_cross_field(const TriangleMesh& mesh, const Features& features,
                               const CrossFieldOptions& options) {
  const SurfaceTopology top(mesh);
  const FaceFrames frames(mesh);
  const int F = mesh.num_faces();
  CrossField field;
  field.direction.resize(F);
  field.fixed.assign(F, false);
  field.curvature_weight.assign(F, 0);
  if (F == 0) return field;

  const double edge_length = top.mean_edge_length();
  const double length = options.alignment_length * edge_length;
  const double eps = 1 / (length * length);

  const std::vector<Complex> fixed =
      feature_crosses(top, frames, feature_edge_flags(top, features));
  std::vector<Complex> target(F, 0.0);
  if (options.align_to_curvature) {
    std::vector<double> difference;
    const double scale = options.curvature_scale * edge_length;
    curvature_crosses(top, frames, scale * scale, target, difference);
    for (int f = 0; f < F; ++f) field.curvature_weight[f] = std::min(1.0, difference[f] * length);
  }

  // Pieces with nothing to align to get the smoothest field instead.
  const int C = top.num_components();
  std::vector<double> pull(C, 0), piece_area(C, 0);
  for (int f = 0; f < F; ++f) {
    const int c = top.face_component()[f];
    piece_area[c] += frames.area[f];
    pull[c] += fixed[f] != 0.0 ? frames.area[f] : frames.area[f] * field.curvature_weight[f];
  }
  std::vector<bool> smoothest(C);
  for (int c = 0; c < C; ++c) {
    smoothest[c] = !(pull[c] > 1e-9 * piece_area[c]);
    field.smoothest_components += smoothest[c];
  }

  // Unknowns: the real and imaginary parts of every free face's u.
  std::vector<int> unknown(F, -1);
  int n = 0;
  for (int f = 0; f < F; ++f)
    if (fixed[f] == 0.0) unknown[f] = n++;
  std::vector<Complex> u(F, 0.0);
  for (int f = 0; f < F; ++f) u[f] = fixed[f];
  if (n > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
    // Adds coefficient a (complex) at (row face i, column face j) of the Hermitian form.
    const auto add = [&](int i, int j, Complex a) {
      const int r = 2 * unknown[i], c = 2 * unknown[j];
      entries.emplace_back(r, c, a.real());
      entries.emplace_back(r, c + 1, -a.imag());
      entries.emplace_back(r + 1, c, a.imag());
      entries.emplace_back(r + 1, c + 1, a.real());
    };
    for (int e = 0; e < top.num_edges(); ++e) {
      const int h = top.edge_half_edge(e), g = top.opposite(h);
      if (g < 0) continue;
      const int f = h / 3, k = g / 3;
      const double w = dual_weight(top, frames, h);
      const Complex r = std::polar(1.0, 4 * transport(top, frames, h));  // u_k ≈ r u_f
      // w |u_k − r u_f|²: diagonal w, off-diagonal −w r at (k, f) and −w r̄ at (f, k).
      if (unknown[f] >= 0) add(f, f, w);
      if (unknown[k] >= 0) add(k, k, w);
      if (unknown[f] >= 0 && unknown[k] >= 0) {
        add(k, f, -w * r);
        add(f, k, -w * std::conj(r));
      } else if (unknown[k] >= 0) {
        const Complex b = w * r * fixed[f];
        rhs[2 * unknown[k]] += b.real(), rhs[2 * unknown[k] + 1] += b.imag();
      } else if (unknown[f] >= 0) {
        const Complex b = w * std::conj(r) * fixed[k];
        rhs[2 * unknown[f]] += b.real(), rhs[2 * unknown[f] + 1] += b.imag();
      }
    }
    // Alignment to curvature, or for pieces without any a small shift so that the matrix is
    // definite (inverse iteration below then finds their smoothest field).
    for (int f = 0; f < F; ++f) {
      if (unknown[f] < 0) continue;
      const bool free_piece = smoothest[top.face_component()[f]];
      const double d = free_piece ? 1e-3 * eps * frames.area[f]
                                  : eps * frames.area[f] * field.curvature_weight[f];
      if (d > 0) add(f, f, d);
      if (!free_piece) {
        const Complex b = d * target[f];
        rhs[2 * unknown[f]] += b.real(), rhs[2 * unknown[f] + 1] += b.imag();
      }
    }
    Eigen::SparseMatrix<double> matrix(2 * n, 2 * n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    Eigen::VectorXd x = solver.solve(rhs);
    if (field.smoothest_components > 0) {
      // Inverse iteration on the free pieces only (the matrix is block diagonal by piece),
      // from a fixed start so the result is deterministic.
      Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n);
      for (int f = 0; f < F; ++f)
        if (unknown[f] >= 0 && smoothest[top.face_component()[f]]) {
          y[2 * unknown[f]] = std::cos(0.7 * f);
          y[2 * unknown[f] + 1] = std::sin(0.7 * f);
        }
      for (int it = 0; it < 50; ++it) {
        Eigen::VectorXd b = y;
        for (int f = 0; f < F; ++f)
          if (unknown[f] >= 0) b.segment<2>(2 * unknown[f]) *= frames.area[f];
        y = solver.solve(b);
        y /= std::max(y.norm(), 1e-300);
      }
      x += y;
    }
    // Unit-length rounds: the linear solve lets |u| shrink, so its zeros crowd where the
    // constraints wind (a disc bounded by a feature circle gets one zero of order four at its
    // centre, split by rounding into four singularities a few triangles apart: polar wedges).
    // Pulling u towards its own normalised value, round after round, makes them repel like
    // the vortices of a Ginzburg–Landau energy.
    const double lambda = options.unit_pull * edge_length;
    if (options.unit_rounds > 0 && options.unit_pull > 0) {
      const double l2 = 1 / (lambda * lambda);
      for (int f = 0; f < F; ++f)
        if (unknown[f] >= 0)
          for (int k = 0; k < 2; ++k)
            entries.emplace_back(2 * unknown[f] + k, 2 * unknown[f] + k, l2 * frames.area[f]);
      Eigen::SparseMatrix<double> pulled(2 * n, 2 * n);
      pulled.setFromTriplets(entries.begin(), entries.end());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> unit_solver(pulled);
      for (int round = 0; round < options.unit_rounds; ++round) {
        Eigen::VectorXd b = rhs;
        for (int f = 0; f < F; ++f) {
          if (unknown[f] < 0) continue;
          const Complex z(x[2 * unknown[f]], x[2 * unknown[f] + 1]);
          if (std::abs(z) <= 0) continue;
          const Complex unit = z / std::abs(z);
          b[2 * unknown[f]] += l2 * frames.area[f] * unit.real();
          b[2 * unknown[f] + 1] += l2 * frames.area[f] * unit.imag();
        }
        x = unit_solver.solve(b);
      }
    }
    for (int f = 0; f < F; ++f)
      if (unknown[f] >= 0) u[f] = Complex(x[2 * unknown[f]], x[2 * unknown[f] + 1]);
  }
  for (int f = 0; f < F; ++f) {
    field.fixed[f] = fixed[f] != 0.0;
    // A face whose u vanished (exactly cancelling neighbours) keeps angle 0.
    const double theta = std::abs(u[f]) > 0 ? std::arg(u[f]) / 4 : 0;
    field.direction[f] = frames.direction(f, theta);
  }
  return field;
}

FieldIndices field_indices(const TriangleMesh& mesh, const CrossField& field,
                           const std::vector<int>& matching_offset) {
  const SurfaceTopology top(mesh);
  const FaceFrames frames(mesh);
  const int F = mesh.num_faces(), V = mesh.num_vertices();
  std::vector<double> theta(F);
  for (int f = 0; f < F; ++f) theta[f] = frames.angle(f, field.direction[f]);
  // δ once per edge (from edge_half_edge's face to the other), so that the two vertices of an
  // edge see exactly opposite jumps and the indices sum exactly.
  std::vector<double> jump(top.num_edges());
  for (int e = 0; e < top.num_edges(); ++e) {
    const int h = top.edge_half_edge(e), g = top.opposite(h);
    jump[e] = g >= 0 ? cross_difference(theta[g / 3] - theta[h / 3] - transport(top, frames, h))
                     : cross_difference(theta[h / 3] - frames.angle(h / 3, edge_vector(top, h)));
    if (!matching_offset.empty()) jump[e] += matching_offset[e] * M_PI / 2;
  }
  FieldIndices out;
  out.quarter_index.assign(V, 0);
  for (int v = 0; v < V; ++v) {
    const std::vector<int> ring = top.outgoing(v);
    if (ring.empty()) continue;
    double turn = 0, angles = 0;
    for (size_t j = 0; j < ring.size(); ++j) {
      const int h = ring[j];
      angles += top.corner_angle(h);
      const int p = SurfaceTopology::prev(h), e = top.edge(p);
      if (top.opposite(p) >= 0) {
        turn += top.edge_half_edge(e) == p ? jump[e] : -jump[e];
      } else {
        turn -= jump[e];  // the border edge the fan ends at runs into v
      }
    }
    const bool border = top.on_border(v);
    if (border) turn += jump[top.edge(ring[0])];  // the border edge the fan starts at
    const double total = turn + (border ? M_PI : 2 * M_PI) - angles;
    const double quarters = total / (M_PI / 2);
    const int k = static_cast<int>(std::lround(quarters));
    out.max_rounding = std::max(out.max_rounding, std::fabs(quarters - k) * M_PI / 2);
    out.quarter_index[v] = k;
    out.quarter_index_sum += k;
    if (k != 0) out.singularities.push_back({v, k, border});
  }
  return out;
}

std::string to_rosy(const CrossField& field) {
  std::ostringstream s;
  s.precision(17);
  s << field.direction.size() << "\n4\n";
  for (const auto& d : field.direction) s << d[0] << ' ' << d[1] << ' ' << d[2] << '\n';
  return s.str();
}

}  // namespace bimdf::layout
