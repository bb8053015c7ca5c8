#include "mesh/surface_untangling.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace bimdf::detail {
namespace {

using Vector = std::vector<double>;

// L-BFGS keeps this many correction pairs; a minimization stops after this many steps.
constexpr int kMemory = 8;
constexpr int kDescentSteps = 200;
// A step moves no point farther than this (in target edge lengths): the energy is not convex,
// and a long step from a tangled start can leap into another fold.
constexpr double kMaxMove = 0.5;

double chi(double det, double eps) { return 0.5 * (det + std::sqrt(eps * eps + det * det)); }

double inner(const Vector& u, const Vector& v) {
  double s = 0;
  for (size_t i = 0; i < u.size(); ++i) s += u[i] * v[i];
  return s;
}

// The energy of the region as a function of its movable points' coordinates x (three per
// point, in target edge lengths), with its gradient, and the projection of x onto the surface.
class CornerEnergy {
 public:
  CornerEnergy(const QuadsOnSurface& region, double edge_length)
      : region_(region), length_(edge_length), slot_(region.points.size(), -1) {
    for (size_t p = 0; p < region.points.size(); ++p)
      if (region.movable[p]) slot_[p] = num_movable_++;
    for (const Vec3& n : region.normals) {
      frames_.push_back(plane_frame(n));
      frames_.push_back(plane_frame(n));
    }
  }

  // The quads' own frames (about their Newell normals) at x.
  void refresh_own_frames(const Vector& x) {
    for (size_t f = 0; f < region_.quads.size(); ++f) {
      Vec3 n{0, 0, 0};
      for (int i = 0; i < 4; ++i)
        n = along(n, 1,
                  cross(position(x, region_.quads[f][i], 1),
                        position(x, region_.quads[f][(i + 1) % 4], 1)));
      if (norm(n) > 0) frames_[2 * f + 1] = plane_frame(normalized(n));
    }
  }

  int dimension() const { return 3 * num_movable_; }

  Vector start() const {
    Vector x(dimension());
    for (size_t p = 0; p < slot_.size(); ++p)
      if (slot_[p] >= 0)
        for (int d = 0; d < 3; ++d) x[3 * slot_[p] + d] = region_.points[p][d] / length_;
    return x;
  }

  void store(const Vector& x, QuadsOnSurface& region) const {
    for (size_t p = 0; p < slot_.size(); ++p)
      if (slot_[p] >= 0) region.points[p] = position(x, static_cast<int>(p), length_);
  }

  void project(Vector& x) const {
    if (!region_.project) return;
    for (size_t p = 0; p < slot_.size(); ++p)
      if (slot_[p] >= 0) {
        const Vec3 q = region_.project(static_cast<int>(p), position(x, p, length_));
        for (int d = 0; d < 3; ++d) x[3 * slot_[p] + d] = q[d] / length_;
      }
  }

  // The smallest determinant among the corners that a movable point changes.
  double min_det(const Vector& x) const {
    double lowest = std::numeric_limits<double>::infinity();
    for_each_corner(x, [&](int p, int next, int prev, const Frame&, double a0, double a1, double b0,
                           double b1) {
      if (slot_[p] >= 0 || slot_[next] >= 0 || slot_[prev] >= 0)
        lowest = std::min(lowest, a0 * b1 - a1 * b0);
    });
    return lowest;
  }

  double operator()(const Vector& x, double eps, Vector* grad) const {
    if (grad) grad->assign(x.size(), 0.0);
    double total = 0;
    for_each_corner(x, [&](int p, int next, int prev, const Frame& frame, double a0, double a1,
                           double b0, double b1) {
      const double det = a0 * b1 - a1 * b0;
      const double root = std::sqrt(eps * eps + det * det), c = 0.5 * (det + root);
      const double numerator = 0.5 * (a0 * a0 + a1 * a1 + b0 * b0 + b1 * b1 + det * det + 1);
      total += numerator / c;
      if (!grad) return;
      // f = N/χ: ∂f/∂|J|² = 1/(2χ) and ∂f/∂D = D/χ − N·χ'/χ², with χ' = (1 + D/root)/2.
      const double d_trace = 0.5 / c;
      const double d_det = det / c - numerator * 0.5 * (1 + det / root) / (c * c);
      const double ga0 = 2 * d_trace * a0 + d_det * b1, ga1 = 2 * d_trace * a1 - d_det * b0;
      const double gb0 = 2 * d_trace * b0 - d_det * a1, gb1 = 2 * d_trace * b1 + d_det * a0;
      add(*grad, next, frame, ga0, ga1);
      add(*grad, prev, frame, gb0, gb1);
      add(*grad, p, frame, -ga0 - gb0, -ga1 - gb1);
    });
    return total;
  }

 private:
  using Frame = std::array<Vec3, 2>;

  Vec3 position(const Vector& x, size_t p, double scale) const {
    if (slot_[p] < 0) return along({0, 0, 0}, scale / length_, region_.points[p]);
    const double* at = &x[3 * slot_[p]];
    return {at[0] * scale, at[1] * scale, at[2] * scale};
  }

  // Adds the gradient (g0, g1), in the frame's plane, to point p's coordinates.
  void add(Vector& grad, int p, const Frame& frame, double g0, double g1) const {
    if (slot_[p] < 0) return;
    for (int d = 0; d < 3; ++d) grad[3 * slot_[p] + d] += g0 * frame[0][d] + g1 * frame[1][d];
  }

  // Calls visit(p, next, prev, frame, a, b) for every corner p of every quad, with a and b its
  // edges to the next and the previous corner in the quad's frame (a × b > 0 when the corner
  // turns counter-clockwise about the quad's normal).
  template <class Visit>
  void for_each_corner(const Vector& x, Visit&& visit) const {
    for (size_t f = 0; f < region_.quads.size(); ++f) {
      const auto& quad = region_.quads[f];
      for (int which = 0; which < 2; ++which) {
        const Frame& frame = frames_[2 * f + which];
        double u[4][2];
        for (int i = 0; i < 4; ++i) {
          const Vec3 at = position(x, quad[i], 1);
          u[i][0] = dot(at, frame[0]);
          u[i][1] = dot(at, frame[1]);
        }
        for (int i = 0; i < 4; ++i) {
          const int next = (i + 1) % 4, prev = (i + 3) % 4;
          visit(quad[i], quad[next], quad[prev], frame, u[next][0] - u[i][0], u[next][1] - u[i][1],
                u[prev][0] - u[i][0], u[prev][1] - u[i][1]);
        }
      }
    }
  }

  const QuadsOnSurface& region_;
  double length_;
  std::vector<int> slot_;
  std::vector<Frame> frames_;
  int num_movable_ = 0;
};

// −H·grad by the two-loop recursion over the correction pairs (s, y), newest first.
Vector lbfgs_direction(const std::deque<std::pair<Vector, Vector>>& history, const Vector& grad) {
  Vector direction = grad;
  std::vector<double> alpha(history.size());
  for (size_t k = 0; k < history.size(); ++k) {
    const auto& [s, y] = history[k];
    alpha[k] = inner(s, direction) / inner(s, y);
    for (size_t i = 0; i < direction.size(); ++i) direction[i] -= alpha[k] * y[i];
  }
  if (!history.empty()) {
    const auto& [s, y] = history.front();
    const double gamma = inner(s, y) / inner(y, y);
    for (double& d : direction) d *= gamma;
  }
  for (size_t k = history.size(); k-- > 0;) {
    const auto& [s, y] = history[k];
    const double beta = inner(y, direction) / inner(s, y);
    for (size_t i = 0; i < direction.size(); ++i) direction[i] += s[i] * (alpha[k] - beta);
  }
  for (double& d : direction) d = -d;
  return direction;
}

// Minimizes the energy at fixed ε from x (on the surface); returns the energy reached.
double minimize(const CornerEnergy& energy, double eps, Vector& x) {
  Vector grad, next_grad, next_x(x.size());
  double value = energy(x, eps, &grad);
  std::deque<std::pair<Vector, Vector>> history;
  for (int step = 0; step < kDescentSteps; ++step) {
    Vector direction = lbfgs_direction(history, grad);
    double slope = inner(direction, grad);
    if (!(slope < 0)) {  // not a descent direction: start again from the gradient
      history.clear();
      for (size_t i = 0; i < x.size(); ++i) direction[i] = -grad[i];
      slope = -inner(grad, grad);
      if (!(slope < 0)) break;
    }
    double longest = 0;
    for (size_t i = 0; i + 2 < x.size(); i += 3)
      longest = std::max(longest, std::hypot(direction[i], direction[i + 1], direction[i + 2]));
    double t = std::min(1.0, kMaxMove / longest), next_value = 0;
    for (;; t *= 0.5) {
      if (t * longest < 1e-9) return value;
      for (size_t i = 0; i < x.size(); ++i) next_x[i] = x[i] + t * direction[i];
      energy.project(next_x);
      next_value = energy(next_x, eps, nullptr);
      if (next_value <= value + 1e-4 * t * slope) break;
    }
    energy(next_x, eps, &next_grad);
    Vector s(x.size()), y(x.size());
    for (size_t i = 0; i < x.size(); ++i) s[i] = next_x[i] - x[i], y[i] = next_grad[i] - grad[i];
    if (inner(s, y) > 1e-12 * inner(s, s)) {
      history.emplace_front(std::move(s), std::move(y));
      if (history.size() > kMemory) history.pop_back();
    }
    const bool settled = value - next_value < 1e-9 * std::max(1.0, value);
    x.swap(next_x);
    grad.swap(next_grad);
    value = next_value;
    if (settled) break;
  }
  return value;
}

}  // namespace

SurfaceUntangling untangle_quads_on_surface(QuadsOnSurface& quads, double edge_length,
                                            int max_rounds) {
  SurfaceUntangling result;
  CornerEnergy energy(quads, edge_length);
  Vector x = energy.start();
  double min_det = energy.min_det(x);
  result.min_det_before = result.min_det_after = min_det;
  if (energy.dimension() == 0 || !std::isfinite(min_det) || !(edge_length > 0)) return result;
  // Regularized enough at first that the inverted corners' energy is moderate.
  double eps = min_det > 0 ? 1e-3 : 2 * std::sqrt(-min_det + 1e-6) + 0.1;
  while (result.rounds < max_rounds) {
    ++result.rounds;
    energy.refresh_own_frames(x);
    const double before = energy(x, eps, nullptr);
    const double after = minimize(energy, eps, x);
    min_det = energy.min_det(x);
    const double decrease = 1 - after / before;
    if (min_det > 0 && decrease < 1e-3) break;
    const double sigma = std::max(decrease, 0.1);
    const double mu = (1 - sigma) * chi(min_det, eps);
    eps = min_det < mu ? 2 * std::sqrt(mu * (mu - min_det)) : eps / 10;
  }
  energy.store(x, quads);
  result.min_det_after = min_det;
  return result;
}

}  // namespace bimdf::detail
