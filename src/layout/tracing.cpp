// Lockstep motorcycle tracing of a per-face cross field (tracing.hpp).
#include "layout/tracing.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "layout/feature_flags.hpp"

namespace bimdf::layout {
namespace {

using detail::Vec3;
constexpr double kQuarter = M_PI / 2;
constexpr double kMaxSteer = M_PI / 6;  // Tracer::steer
// A seed's trace pairs with another seed only if it passes that seed at most this far to the
// side per length it has gone (within about 37° ahead; Tracer::observe).
constexpr double kSeedsSideways = 0.75;

// The angle between two lines (not directions): 0 to π/2.
double line_angle(const Vec3& a, const Vec3& b) {
  const double n = detail::norm(a) * detail::norm(b);
  return n > 0 ? std::acos(std::min(1.0, std::fabs(detail::dot(a, b)) / n)) : M_PI / 2;
}

double wrap_2pi(double a) {
  a = std::fmod(a, 2 * M_PI);
  return a < 0 ? a + 2 * M_PI : a;
}

// A point in face f's plane in the face's frame, origin at its first vertex.
struct P2 {
  double x = 0, y = 0;
};
double cross2(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
P2 minus(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }

// A drawn piece of a trace, remembered by every face it lies in (two for a piece along an edge).
struct Segment {
  int trace = -1;
  SurfacePoint a, b;
  Vec3 pa, pb;
};

// One direction a trace can leave a vertex in: into face `ring` (its index in the vertex's
// ring) at `angle` in that face's frame, or along the edge of `edge_half_edge` (≥ 0, pointing
// away from the vertex). `ring_angle` places it around the vertex (0 at the ring's first edge).
struct Leave {
  double ring_angle = 0;
  double quarters = 0;  // its place around the vertex in the parameter plane (ring_quarters)
  int face = -1;
  double angle = 0;
  int edge_half_edge = -1;
};

class Tracer {
 public:
  Tracer(const SurfaceTopology& top, const FaceFrames& frames, const FaceWays& ways,
         const std::vector<int>& quarter_index, const std::vector<bool>& curve_edge,
         const TraceOptions& options)
      : top_(top),
        frames_(frames),
        quarter_index_(quarter_index),
        curve_(curve_edge),
        options_(options),
        m_(top.mesh()),
        ways_(ways) {
    const int F = m_.num_faces(), V = m_.num_vertices();
    faces_.resize(F);
    owner_.assign(V, -1);
    is_seed_.assign(V, false);
    for (int v : options.seeds)
      if (v >= 0 && v < V) is_seed_[v] = true;
    curve_vertex_ = vertices_of_edges(top, curve_);
    Vec3 lo = m_.vertices[0], hi = m_.vertices[0];
    for (const Vec3& p : m_.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    max_length_ = options.max_length * detail::norm(detail::sub(hi, lo));
    approach_radius_ = options.approach_radius * top.mean_edge_length();
  }

  MotorcycleGraph run();

 private:
  struct Walker {
    int trace = -1;
    double length = 0;
    // Moving inside `face` along `angle` (its frame) from the trace's last point, or (face −1)
    // standing at a vertex, having come from direction `back` (a ring angle there).
    int face = -1;
    double angle = 0;
    double back = 0;
    int target = -1;      // a singularity it is paired with: it ends there when it gets close
    int partner_way = -1;  // the target's separatrix it stands for (not traced from there)
    double steered = 0;    // its last piece's turn off its way (steer), radians
    bool operator<(const Walker& o) const {
      return length != o.length ? length > o.length : trace > o.trace;  // min-heap
    }
  };

  P2 to_2d(int f, const Vec3& x) const {
    const Vec3 d = detail::sub(x, m_.vertices[m_.faces[f][0]]);
    return {detail::dot(d, frames_.e1[f]), detail::dot(d, frames_.e2[f])};
  }
  double face_scale(int f) const {
    const auto& t = m_.faces[f];
    double l = 0;
    for (int k = 0; k < 3; ++k)
      l = std::max(l, detail::norm(detail::sub(m_.vertices[t[(k + 1) % 3]], m_.vertices[t[k]])));
    return l;
  }
  std::vector<Leave> leaves(int v) const;
  // The angle from a to b (tangents of face f) in the parameter plane whose iso-lines are f's
  // ways; the plain angle where the ways are too skewed to be a basis.
  double parameter_angle(int f, const Vec3& a, const Vec3& b) const;
  // Around v, where each of its ring's edges is (and, last, the end of the ring), in quarter
  // turns of the parameter plane from the first edge, scaled so that the whole ring spans the
  // field's turn there: 4 − index quarters inside, 2 − index on the border. `scale`: quarters
  // per radian of parameter angle.
  std::vector<double> ring_quarters(int v, double* scale = nullptr) const;
  double ring_total(int v) const;
  double ring_angle_of(int v, int face, const Vec3& d) const;
  double ring_angle_of_edge(int v, int other) const;
  void start_directions(int v, std::vector<Leave>& out) const;
  bool advance(Walker& w);
  bool move_in_face(Walker& w, const SurfacePoint& from, const Vec3& from_pos);
  bool move_along_edge(Walker& w, int h);
  // Draws the piece from → q inside face f: stops at the first drawn trace it meets before
  // `reach` (a fraction of the piece), else records the piece and arrives at q.
  bool draw(Walker& w, int f, const SurfacePoint& from, const Vec3& from_pos, const SurfacePoint& q,
            double reach);
  bool arrive(Walker& w, const SurfacePoint& q, const Vec3& qpos, int face, const Vec3& dir,
              bool along_edge, int along_half_edge);
  // The first hit of segment p→q (in face f) with a drawn segment: its parameter along p→q
  // and the point, or s < 0 for none.
  double first_hit(int f, int trace, const Vec3& p, const Vec3& q, SurfacePoint& point,
                   int& other) const;
  SurfacePoint locate(int f, const Vec3& x) const;
  void record(int f, const Segment& s) {
    if (!free_) faces_[f].push_back(s);
  }
  void finish(int trace, Trace::End end, int other) {
    traces_[trace].end = end;
    traces_[trace].end_trace = other;
  }

  const SurfaceTopology& top_;
  const FaceFrames& frames_;
  const std::vector<int>& quarter_index_;
  const std::vector<bool>& curve_;
  const TraceOptions& options_;
  const TriangleMesh& m_;
  const FaceWays& ways_;
  std::vector<std::vector<Segment>> faces_;
  std::vector<int> owner_;  // per vertex: a trace through it, −1
  std::vector<bool> curve_vertex_;
  std::vector<bool> start_vertex_;
  std::vector<bool> is_seed_;
  std::vector<Trace> traces_;
  double max_length_ = 0;
  // Pairing (pair_separatrices): while `free_`, traces ignore one another and stop at the
  // first singularity they pass head on, which they note in `approach_`.
  bool free_ = false;
  double approach_radius_ = 0;
  mutable Vec3 hit_direction_{};                  // of the drawn piece first_hit last met
  std::vector<std::vector<Vec3>> leave_vectors_;  // per vertex, its separatrices' directions
  struct Approach {
    int vertex = -1, leave = -1;
    double length = 0;
  } approach_;
  bool observe(const Walker& w, int f, const Vec3& p, const Vec3& q);
  // A paired walker may step onto its target: at once for another singularity, and only once
  // it has gone some way for its own start (a seed's loop around a tube, which leaves through
  // the faces it will come back through).
  bool may_close(const Walker& w) const {
    return w.target >= 0 &&
           (w.target != traces_[w.trace].start_vertex || w.length > 4 * approach_radius_);
  }
  // Near its target a paired walker leaves its way and heads for a point on the target's
  // separatrix it stands for, ahead of the target by a fraction of the distance left, so that
  // it arrives along that separatrix: the sideways offset (up to the approach radius) is taken
  // up by a gentle bend over a few edges instead of one step at a steep angle, which would
  // leave the target's sectors on either side a sliver and a nearly straight angle (a corner
  // too many). The steered angle in face f, or NaN to keep the way.
  double steer(const Walker& w, int f, const Vec3& pos) const;
  Vec3 leave_vector(int v, const Leave& l) const;
  void pair_separatrices(const std::vector<std::vector<Leave>>& starts,
                         std::vector<std::vector<int>>& target,
                         std::vector<std::vector<bool>>& skip,
                         std::vector<std::vector<int>>& partner);
};

double Tracer::ring_total(int v) const {
  double total = 0;
  for (int h : top_.outgoing(v)) total += top_.corner_angle(h);
  return total;
}

double Tracer::parameter_angle(int f, const Vec3& a, const Vec3& b) const {
  const P2 w0{std::cos(ways_[f][0]), std::sin(ways_[f][0])};
  const P2 w1{std::cos(ways_[f][1]), std::sin(ways_[f][1])};
  const double det = cross2(w0, w1);
  const P2 a2{detail::dot(a, frames_.e1[f]), detail::dot(a, frames_.e2[f])};
  const P2 b2{detail::dot(b, frames_.e1[f]), detail::dot(b, frames_.e2[f])};
  if (det < 0.1) return std::atan2(cross2(a2, b2), a2.x * b2.x + a2.y * b2.y);
  const P2 pa{cross2(a2, w1) / det, cross2(w0, a2) / det};
  const P2 pb{cross2(b2, w1) / det, cross2(w0, b2) / det};
  return std::atan2(cross2(pa, pb), pa.x * pb.x + pa.y * pb.y);
}

std::vector<double> Tracer::ring_quarters(int v, double* scale) const {
  const std::vector<int> ring = top_.outgoing(v);
  std::vector<double> at(ring.size() + 1, 0);
  for (size_t j = 0; j < ring.size(); ++j) {
    const int h = ring[j], f = h / 3;
    const Vec3 a = detail::sub(m_.vertices[top_.to(h)], m_.vertices[v]);
    const Vec3 b = detail::sub(m_.vertices[top_.from(SurfaceTopology::prev(h))], m_.vertices[v]);
    at[j + 1] = at[j] + std::max(0.0, parameter_angle(f, a, b));
  }
  const int turn = (top_.on_border(v) ? 2 : 4) - quarter_index_[v];
  const double s = turn > 0 && at.back() > 0 ? turn / at.back() : 1 / kQuarter;
  for (double& x : at) x *= s;
  if (scale) *scale = s;
  return at;
}

// Every field direction that leaves v into one of its faces or along one of its edges, by ring
// angle; near-duplicates (one direction seen from two faces of an edge) merged.
std::vector<Leave> Tracer::leaves(int v) const {
  std::vector<Leave> out;
  const std::vector<int> ring = top_.outgoing(v);
  double scale = 0;
  const std::vector<double> at = ring_quarters(v, &scale);
  double start = 0;
  const double tolerance = 0.02;  // radians: a direction this close to an edge runs along it
  for (size_t j = 0; j < ring.size(); ++j) {
    const int h = ring[j], f = h / 3, p = SurfaceTopology::prev(h);
    const Vec3 a = detail::sub(m_.vertices[top_.to(h)], m_.vertices[v]);
    const double corner = top_.corner_angle(h);
    const double edge_angle = frames_.angle(f, a);
    for (int k = 0; k < 4; ++k) {
      const double phi = ways_[f][k];
      double beta = wrap_2pi(phi - edge_angle);
      if (beta > M_PI + corner / 2) beta -= 2 * M_PI;  // just before the wedge: negative
      if (beta < -tolerance || beta > corner + tolerance) continue;
      Leave l;
      l.ring_angle = start + std::clamp(beta, 0.0, corner);
      if (beta <= tolerance) {
        l.edge_half_edge = h;
        l.quarters = at[j];
      } else if (beta >= corner - tolerance) {
        l.edge_half_edge = top_.opposite(p) >= 0 ? top_.opposite(p) : -2 - p;
        l.quarters = at[j + 1];
      } else {
        l.face = f;
        l.angle = phi;
        const double x = parameter_angle(f, a, frames_.direction(f, phi));
        l.quarters = at[j] + std::clamp(x * scale, 0.0, at[j + 1] - at[j]);
      }
      out.push_back(l);
    }
    start += corner;
  }
  std::sort(out.begin(), out.end(),
            [](const Leave& x, const Leave& y) { return x.ring_angle < y.ring_angle; });
  // Merge directions closer than a fifth of a quarter turn (around the ring, cyclically at an
  // interior vertex), preferring one along an edge.
  const double total = start;
  const bool closed = !top_.on_border(v);
  std::vector<Leave> merged;
  for (const Leave& l : out) {
    if (!merged.empty() && l.ring_angle - merged.back().ring_angle < 0.2 * kQuarter) {
      if (merged.back().edge_half_edge == -1 && l.edge_half_edge != -1) merged.back() = l;
      continue;
    }
    merged.push_back(l);
  }
  if (closed && merged.size() > 1 &&
      merged.front().ring_angle + total - merged.back().ring_angle < 0.2 * kQuarter) {
    if (merged.front().edge_half_edge == -1) merged.front() = merged.back();
    merged.pop_back();
  }
  return merged;
}

// The ring angle at v of tangent direction d seen in face `face` (one of v's faces).
double Tracer::ring_angle_of(int v, int face, const Vec3& d) const {
  double start = 0;
  for (int h : top_.outgoing(v)) {
    const Vec3 a = detail::sub(m_.vertices[top_.to(h)], m_.vertices[v]);
    const double corner = top_.corner_angle(h);
    if (h / 3 == face) {
      double beta = wrap_2pi(frames_.angle(face, d) - frames_.angle(face, a));
      if (beta > M_PI + corner / 2) beta -= 2 * M_PI;
      return start + std::clamp(beta, 0.0, corner);
    }
    start += corner;
  }
  return 0;
}

// The ring angle at v of the edge towards vertex `other`.
double Tracer::ring_angle_of_edge(int v, int other) const {
  double start = 0;
  for (int h : top_.outgoing(v)) {
    if (top_.to(h) == other) return start;
    start += top_.corner_angle(h);
  }
  return start;  // the last edge of a border fan
}

SurfacePoint Tracer::locate(int f, const Vec3& x) const {
  // Barycentric coordinates in the face's plane.
  const auto& t = m_.faces[f];
  const P2 a = to_2d(f, m_.vertices[t[0]]), b = to_2d(f, m_.vertices[t[1]]),
           c = to_2d(f, m_.vertices[t[2]]), p = to_2d(f, x);
  const double area = cross2(minus(b, a), minus(c, a));
  std::array<double, 3> w = {cross2(minus(b, p), minus(c, p)) / area,
                             cross2(minus(c, p), minus(a, p)) / area, 0};
  w[2] = 1 - w[0] - w[1];
  const double tiny = 1e-9;
  int zero = 0;
  for (double& x : w)
    if (x < tiny) x = 0, ++zero;
  if (zero >= 2)
    for (int k = 0; k < 3; ++k)
      if (w[k] > 0) return SurfacePoint::at_vertex(t[k]);
  if (zero == 1)
    for (int k = 0; k < 3; ++k)
      if (w[k] == 0) {
        // On the edge opposite corner k: from t[k+1] to t[k+2], half-edge 3f + (k+1)%3.
        const int h = 3 * f + (k + 1) % 3;
        const double s = w[(k + 2) % 3] / (w[(k + 1) % 3] + w[(k + 2) % 3]);
        const int e = top_.edge(h);
        return SurfacePoint::on_edge(e, top_.edge_half_edge(e) == h ? s : 1 - s);
      }
  const double sum = w[0] + w[1] + w[2];
  return SurfacePoint::in_face(f, {w[0] / sum, w[1] / sum, w[2] / sum});
}

double Tracer::first_hit(int f, int trace, const Vec3& p, const Vec3& q, SurfacePoint& point,
                         int& other) const {
  if (free_) return -1;
  const double scale = face_scale(f), eps = 1e-9;
  const P2 a = to_2d(f, p), b = to_2d(f, q), d = minus(b, a);
  const double len = std::hypot(d.x, d.y);
  if (len <= eps * scale) return -1;
  double best = 2;
  for (const Segment& s : faces_[f]) {
    const P2 c = to_2d(f, s.pa), e = to_2d(f, s.pb), g = minus(e, c);
    const double denom = cross2(d, g);
    const double glen = std::hypot(g.x, g.y);
    double hit = -1;
    if (std::fabs(denom) <= 1e-9 * len * glen) {
      // Parallel: a hit only if collinear and overlapping ahead.
      if (std::fabs(cross2(minus(c, a), d)) > eps * scale * len) continue;
      const double sc = ((c.x - a.x) * d.x + (c.y - a.y) * d.y) / (len * len);
      const double se = ((e.x - a.x) * d.x + (e.y - a.y) * d.y) / (len * len);
      const double lo = std::min(sc, se), hi = std::max(sc, se);
      if (hi < eps / len * scale || lo > 1) continue;
      hit = std::max(lo, 0.0);
      if (hit <= eps && s.trace == trace) continue;  // its own previous piece
    } else {
      const P2 ac = minus(c, a);
      const double s_new = cross2(ac, g) / denom, u = cross2(ac, d) / denom;
      if (u < -1e-9 || u > 1 + 1e-9 || s_new > 1 + 1e-9) continue;
      if (s_new * len <= eps * scale) continue;  // at the start: where it came from
      hit = s_new;
    }
    if (hit < best) {
      best = hit;
      other = s.trace;
      hit_direction_ = detail::sub(s.pb, s.pa);
    }
  }
  if (best > 1 + 1e-9) return -1;
  best = std::min(best, 1.0);
  point = locate(f, detail::along(p, best, detail::sub(q, p)));
  return best;
}

// The trace has reached q: stop at features, singular or occupied vertices, else continue
// (across the edge into the next face, or choosing a way on at the vertex).
bool Tracer::arrive(Walker& w, const SurfacePoint& q, const Vec3& qpos, int face, const Vec3& dir,
                    bool along_edge, int along_half_edge) {
  Trace& t = traces_[w.trace];
  w.length += detail::norm(detail::sub(qpos, position(top_, t.points.back())));
  t.points.push_back(q);
  t.length = w.length;
  if (q.kind == SurfacePoint::Kind::Vertex) {
    const int v = q.id;
    if (free_) {
      if (start_vertex_[v] && v != t.start_vertex) return false;  // observe() noted it
    } else if (owner_[v] >= 0) {
      finish(w.trace, start_vertex_[v] ? Trace::End::Singularity : Trace::End::Trace, owner_[v]);
      return false;
    }
    if (!free_) owner_[v] = w.trace;
    if (curve_vertex_[v]) {
      for (int h : top_.outgoing(v))
        for (int k : {h, SurfaceTopology::prev(h)})
          if (curve_[top_.edge(k)])
            t.end_angle = std::min(
                t.end_angle,
                line_angle(dir, detail::sub(m_.vertices[top_.to(k)], m_.vertices[top_.from(k)])));
      finish(w.trace, Trace::End::Curve, -1);
      return false;
    }
    w.face = -1;
    w.back = along_edge ? ring_angle_of_edge(v, top_.from(along_half_edge))
                        : ring_angle_of(v, face, {-dir[0], -dir[1], -dir[2]});
    return w.length < max_length_;
  }
  // On an edge: cross it, unless it is a curve.
  if (curve_[q.id]) {
    const int e = top_.edge_half_edge(q.id);
    t.end_angle = line_angle(dir, detail::sub(m_.vertices[top_.to(e)], m_.vertices[top_.from(e)]));
    finish(w.trace, Trace::End::Curve, -1);
    return false;
  }
  const int h0 = top_.edge_half_edge(q.id);
  const int h = h0 / 3 == face ? h0 : top_.opposite(h0);
  const int g = top_.opposite(h);
  const Vec3 edge = detail::sub(m_.vertices[top_.to(h)], m_.vertices[top_.from(h)]);
  // The way it was on (not the steered direction it drew), carried into the next face.
  const double transported = frames_.angle(face, dir) - w.steered +
                             (frames_.angle(g / 3, edge) - frames_.angle(face, edge));
  // The field direction of the next face closest to the transported one that points into it
  // (to the left of the edge as the next face walks it).
  const double into =
      frames_.angle(g / 3, detail::sub(m_.vertices[top_.to(g)], m_.vertices[top_.from(g)]));
  double best = 1e9, chosen = 0;
  for (int k = 0; k < 4; ++k) {
    const double phi = ways_[g / 3][k];
    if (std::sin(phi - into) <= 1e-6) continue;
    const double turn = std::fabs(std::remainder(phi - transported, 2 * M_PI));
    if (turn < best) best = turn, chosen = phi;
  }
  // A steered piece may cross an edge that its way runs along or away from: then no way of its
  // family leads on, and it goes straight on for a face rather than turn a quarter.
  const double straight = transported + w.steered;
  if (best > M_PI / 4 && w.steered != 0 && std::sin(straight - into) > 1e-6)
    chosen = straight;
  else if (best > 1e8) {
    finish(w.trace, Trace::End::Unfinished, -1);
    return false;
  }
  w.face = g / 3;
  w.angle = chosen;
  return w.length < max_length_;
}

bool Tracer::move_in_face(Walker& w, const SurfacePoint& from, const Vec3& from_pos) {
  const int f = w.face;
  if (may_close(w) && !(from.kind == SurfacePoint::Kind::Vertex && from.id == w.target)) {
    const auto& t = m_.faces[f];
    if (t[0] == w.target || t[1] == w.target || t[2] == w.target) {
      // Paired: the last step goes straight to the singularity (whose own separatrices
      // start where this one ends: hits there do not count).
      return draw(w, f, from, from_pos, SurfacePoint::at_vertex(w.target), 1 - 1e-9);
    }
  }
  const P2 p = to_2d(f, from_pos);
  const double scale = face_scale(f);
  double best_s = 1e300, best_t = 0;
  int best_h = -1;
  // The exit: the first edge the ray at `angle` meets beyond its start.
  const auto exit_along = [&](double angle) {
    const P2 d = {std::cos(angle), std::sin(angle)};
    best_s = 1e300, best_h = -1;
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i;
      const P2 a = to_2d(f, m_.vertices[top_.from(h)]), b = to_2d(f, m_.vertices[top_.to(h)]);
      const P2 g = minus(b, a);
      const double denom = cross2(d, g);
      if (std::fabs(denom) < 1e-12 * scale) continue;
      const P2 ap = minus(a, p);
      const double s = cross2(ap, g) / denom, t = cross2(ap, d) / denom;
      if (s <= 1e-9 * scale || t < -1e-9 || t > 1 + 1e-9) continue;
      if (s < best_s) best_s = s, best_t = std::clamp(t, 0.0, 1.0), best_h = h;
    }
  };
  const double steered = steer(w, f, from_pos);
  w.steered = 0;
  if (!std::isnan(steered)) {
    exit_along(steered);
    if (best_h >= 0) w.steered = std::remainder(steered - w.angle, 2 * M_PI);
  }
  if (best_h < 0) exit_along(w.angle);
  if (best_h < 0) {  // numerically stuck (a ray leaving through a corner): give up here
    finish(w.trace, Trace::End::Unfinished, -1);
    return false;
  }
  SurfacePoint q;
  // Snap to a vertex near the crossing, but not to a singularity this trace is not paired
  // with: arriving at one off its separatrices' directions would split one of its sectors in
  // two corners; passing close by, the trace meets a separatrix there instead.
  const auto snaps_to = [&](int v) { return !start_vertex_[v] || v == w.target; };
  if (best_t < options_.snap && snaps_to(top_.from(best_h))) {
    q = SurfacePoint::at_vertex(top_.from(best_h));
  } else if (best_t > 1 - options_.snap && snaps_to(top_.to(best_h))) {
    q = SurfacePoint::at_vertex(top_.to(best_h));
  } else {
    const int e = top_.edge(best_h);
    const double t = std::clamp(best_t, 1e-6, 1 - 1e-6);
    q = SurfacePoint::on_edge(e, top_.edge_half_edge(e) == best_h ? t : 1 - t);
  }
  if (from.kind == SurfacePoint::Kind::Vertex && q.kind == SurfacePoint::Kind::Vertex &&
      q.id == from.id) {
    finish(w.trace, Trace::End::Unfinished, -1);
    return false;
  }
  return draw(w, f, from, from_pos, q, 2);
}

bool Tracer::draw(Walker& w, int f, const SurfacePoint& from, const Vec3& from_pos,
                  const SurfacePoint& q, double reach) {
  const Vec3 qpos = position(top_, q);
  const double len = detail::norm(detail::sub(qpos, from_pos));
  SurfacePoint hit;
  int other = -1;
  const double s = first_hit(f, w.trace, from_pos, qpos, hit, other);
  if (s >= 0 && s < reach) {
    traces_[w.trace].end_angle = line_angle(detail::sub(qpos, from_pos), hit_direction_);
    // A hit right where it stands (another trace ended here, head on): stop without a step.
    if (s * len > 1e-9 * face_scale(f)) {
      traces_[w.trace].points.push_back(hit);
      w.length += s * len;
      traces_[w.trace].length = w.length;
      record(f, {w.trace, from, hit, from_pos, position(top_, hit)});
    }
    finish(w.trace, Trace::End::Trace, other);
    return false;
  }
  if (free_ && observe(w, f, from_pos, qpos)) return false;
  record(f, {w.trace, from, q, from_pos, qpos});
  return arrive(w, q, qpos, f, detail::sub(qpos, from_pos), false, -1);
}

bool Tracer::move_along_edge(Walker& w, int h) {
  const int v = top_.from(h), u = top_.to(h);
  w.steered = 0;
  if (curve_[top_.edge(h)]) {
    finish(w.trace, Trace::End::Curve, -1);
    return false;
  }
  const SurfacePoint from = SurfacePoint::at_vertex(v), to = SurfacePoint::at_vertex(u);
  const Vec3 pv = m_.vertices[v], pu = m_.vertices[u];
  SurfacePoint hit;
  int other = -1;
  double s = first_hit(h / 3, w.trace, pv, pu, hit, other);
  Vec3 met = hit_direction_;
  const int g = top_.opposite(h);
  if (g >= 0) {
    SurfacePoint hit2;
    int other2 = -1;
    const double s2 = first_hit(g / 3, w.trace, pv, pu, hit2, other2);
    if (s2 >= 0 && (s < 0 || s2 < s)) s = s2, hit = hit2, other = other2, met = hit_direction_;
  }
  if (s >= 0) {
    traces_[w.trace].end_angle = line_angle(detail::sub(pu, pv), met);
    if (s * detail::norm(detail::sub(pu, pv)) > 1e-9 * face_scale(h / 3)) {
      traces_[w.trace].points.push_back(hit);
      w.length += s * detail::norm(detail::sub(pu, pv));
      traces_[w.trace].length = w.length;
      const Segment seg{w.trace, from, hit, pv, position(top_, hit)};
      record(h / 3, seg);
      if (g >= 0) record(g / 3, seg);
    }
    finish(w.trace, Trace::End::Trace, other);
    return false;
  }
  if (free_ && observe(w, h / 3, pv, pu)) return false;
  const Segment seg{w.trace, from, to, pv, pu};
  record(h / 3, seg);
  if (g >= 0) record(g / 3, seg);
  return arrive(w, to, pu, h / 3, detail::sub(pu, pv), true, h);
}

bool Tracer::advance(Walker& w) {
  const Trace& t = traces_[w.trace];
  const SurfacePoint at = t.points.back();
  if (w.face >= 0) return move_in_face(w, at, position(top_, at));
  // At a vertex: to its paired singularity if that is a neighbour, else the way on closest
  // to straight ahead.
  const int v = at.id;
  if (may_close(w))
    for (int h : top_.outgoing(v))
      if (top_.to(h) == w.target) return move_along_edge(w, h);
  const std::vector<Leave> ways = leaves(v);
  const double total = ring_total(v);
  const double ahead = top_.on_border(v) ? -1 : std::fmod(w.back + total / 2, total);
  const Leave* best = nullptr;
  double best_off = 1e300;
  for (const Leave& l : ways) {
    if (ahead < 0) break;
    const double d = std::fabs(l.ring_angle - ahead);
    const double off = std::min(d, total - d);
    if (off < best_off) best_off = off, best = &l;
  }
  // Near a singularity the field turns fast and no way may be close to straight on; the
  // closest is still the best guess (stopping would leave a dangling trace).
  if (!best) {
    finish(w.trace, Trace::End::Unfinished, -1);
    return false;
  }
  if (best->face < 0) {
    if (best->edge_half_edge < 0) {  // along the border edge that ends the fan
      finish(w.trace, Trace::End::Curve, -1);
      return false;
    }
    return move_along_edge(w, best->edge_half_edge);
  }
  w.face = best->face;
  w.angle = best->angle;
  return move_in_face(w, at, m_.vertices[v]);
}

// Which of the ways out of v start separatrices: all of them at an interior singularity; at a
// vertex on curves, in each sector between two consecutive curve edges spanning q quarter
// turns, the ways at the 2nd, 4th, … quarter (so that no patch corner there exceeds a half
// turn: a concave corner or a curve's free end is continued straight).
void Tracer::start_directions(int v, std::vector<Leave>& out) const {
  out.clear();
  const std::vector<Leave> ways = leaves(v);
  if (!curve_vertex_[v]) {
    if (quarter_index_[v] != 0 || is_seed_[v]) out = ways;
    return;
  }
  const std::vector<int> ring = top_.outgoing(v);
  const std::vector<double> at = ring_quarters(v);
  // Positions (ring_quarters) of the curve edges at v.
  std::vector<double> cuts;
  for (size_t j = 0; j < ring.size(); ++j)
    if (curve_[top_.edge(ring[j])]) cuts.push_back(at[j]);
  const double total = at.back();
  if (top_.on_border(v)) cuts.push_back(total);  // the fan's last (border) edge
  if (cuts.empty()) return;
  const bool closed = !top_.on_border(v);
  const int C = static_cast<int>(cuts.size());
  for (int c = 0; c < (closed ? C : C - 1); ++c) {
    const double lo = cuts[c];
    const double hi = c + 1 < C ? cuts[c + 1] : cuts[0] + total;
    // The sector spans q quarters; traces leave it at the 2nd, 4th, … (a seed's at every one),
    // the way nearest each, so that no corner there exceeds a half turn. Counting in the
    // parameter plane (not by the ways inside the sector) keeps a curve that passes straight
    // through v free of starts even where the ways are not quite aligned to it.
    const int q = static_cast<int>(std::lround(hi - lo));
    for (int k = is_seed_[v] ? 1 : 2; k < q; k += is_seed_[v] ? 1 : 2) {
      const double want = lo + k * (hi - lo) / q;
      const Leave* best = nullptr;
      double best_off = 0.5;
      for (const Leave& l : ways) {
        const double a = l.quarters < lo - 1e-9 ? l.quarters + total : l.quarters;
        if (std::fabs(a - want) < best_off) best_off = std::fabs(a - want), best = &l;
      }
      if (best) out.push_back(*best);
    }
  }
}

double Tracer::steer(const Walker& w, int f, const Vec3& pos) const {
  if (!may_close(w) || w.partner_way < 0 || options_.steer_radius <= 0) return NAN;
  const Vec3& target = m_.vertices[w.target];
  const double d = detail::norm(detail::sub(pos, target));
  if (d > options_.steer_radius * approach_radius_) return NAN;
  const Vec3 aim =
      detail::along(target, options_.steer_lead * d, leave_vectors_[w.target][w.partner_way]);
  const double angle = frames_.angle(f, detail::sub(aim, pos));
  // Behind or far to the side: the pairing's head-on approach is gone; keep the way. Else
  // turn by at most kMaxSteer, so that the trace stays recognisably on its way.
  const double off = std::remainder(angle - w.angle, 2 * M_PI);
  if (std::fabs(off) > M_PI / 2) return NAN;
  return w.angle + std::clamp(off, -kMaxSteer, kMaxSteer);
}

Vec3 Tracer::leave_vector(int v, const Leave& l) const {
  if (l.face >= 0) return frames_.direction(l.face, l.angle);
  if (l.edge_half_edge >= 0)
    return detail::normalized(detail::sub(m_.vertices[top_.to(l.edge_half_edge)], m_.vertices[v]));
  const int p = -2 - l.edge_half_edge;  // the border edge ending the fan, into v
  return detail::normalized(detail::sub(m_.vertices[top_.from(p)], m_.vertices[v]));
}

// While pairing: whether segment p→q (in face f) passes a singularity of another start, closer
// than the approach radius and head on to one of its separatrices. Notes the first.
bool Tracer::observe(const Walker& w, int f, const Vec3& p, const Vec3& q) {
  const int own = traces_[w.trace].start_vertex;
  const Vec3 d = detail::sub(q, p);
  const double len2 = detail::dot(d, d);
  if (len2 <= 0) return false;
  const Vec3 dir = detail::normalized(d);
  for (int x : m_.faces[f]) {
    // A seed's two opposite ways are one loop when it closes around a tube: its own start
    // counts for a seed, once the trace has gone some way.
    const bool own_loop = x == own && is_seed_[x] && w.length > 4 * approach_radius_;
    if (!start_vertex_[x] || (x == own && !own_loop) || curve_vertex_[x]) continue;
    if (quarter_index_[x] == 0 && !is_seed_[x]) continue;
    const double t = std::clamp(detail::dot(detail::sub(m_.vertices[x], p), d) / len2, 0.0, 1.0);
    const Vec3 closest = detail::along(p, t, d);
    const double lateral = detail::norm(detail::sub(m_.vertices[x], closest));
    if (lateral > approach_radius_) continue;
    // Two seeds side by side (on couplingdown the two seeds of a hole's wall are often
    // neighbours) are not head on: paired, the trace would step sideways onto the other seed
    // and the cut across the patch would be a Z whose two corners become a valence-3/5 pair of
    // the quad mesh. Traced apart, each cuts straight across (couplingdown: 176 → 116
    // singular vertices). A seed already behind the piece's start was passed sideways. Only
    // between seeds: applied to singularities as well, the rule cost ChineseDragon-10kv an
    // inverted quad.
    const double along = w.length + t * std::sqrt(len2);
    if (is_seed_[x] && is_seed_[own] && x != own &&
        (lateral > kSeedsSideways * along || (t == 0 && w.length > 0)))
      continue;
    for (size_t j = 0; j < leave_vectors_[x].size(); ++j)
      if (detail::dot(dir, leave_vectors_[x][j]) < -0.85) {
        approach_ = {x, static_cast<int>(j), along};
        return true;
      }
  }
  return false;
}

// Separatrices that run into another singularity head on, against one of its own, are one
// line of the layout traced from both ends: traced separately they pass each other a little
// apart and leave a two-cornered sliver. Each is traced freely (ignoring the others) until it
// passes a singularity within the approach radius, head on to one of its separatrices; such
// pairs, shortest first and each separatrix in one pair at most, become one trace from the
// first singularity to the second (`target`), and the second's separatrix is not traced.
void Tracer::pair_separatrices(const std::vector<std::vector<Leave>>& starts,
                               std::vector<std::vector<int>>& target,
                               std::vector<std::vector<bool>>& skip,
                               std::vector<std::vector<int>>& partner) {
  struct Pair {
    double length;
    int from, from_leave, to, to_leave;
  };
  std::vector<Pair> pairs;
  free_ = true;
  const int V = m_.num_vertices();
  for (int v = 0; v < V; ++v) {
    if ((quarter_index_[v] == 0 && !is_seed_[v]) || curve_vertex_[v]) continue;
    for (size_t i = 0; i < starts[v].size(); ++i) {
      const Leave& l = starts[v][i];
      traces_.assign(1, Trace{});
      traces_[0].start_vertex = v;
      traces_[0].points.push_back(SurfacePoint::at_vertex(v));
      Walker w;
      w.trace = 0;
      w.face = l.face;
      w.angle = l.angle;
      approach_ = {};
      bool going = l.face >= 0 ? move_in_face(w, traces_[0].points[0], m_.vertices[v])
                               : l.edge_half_edge >= 0 && move_along_edge(w, l.edge_half_edge);
      while (going && approach_.vertex < 0 && w.length < max_length_) going = advance(w);
      if (approach_.vertex >= 0)
        pairs.push_back(
            {approach_.length, v, static_cast<int>(i), approach_.vertex, approach_.leave});
    }
  }
  free_ = false;
  traces_.clear();
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.length != b.length ? a.length < b.length : a.from < b.from;
  });
  std::vector<std::vector<bool>> used(V);
  for (int v = 0; v < V; ++v) used[v].assign(starts[v].size(), false);
  for (const Pair& p : pairs) {
    if (used[p.from][p.from_leave] || used[p.to][p.to_leave]) continue;
    used[p.from][p.from_leave] = used[p.to][p.to_leave] = true;
    target[p.from][p.from_leave] = p.to;
    partner[p.from][p.from_leave] = p.to_leave;
    skip[p.to][p.to_leave] = true;
  }
}

MotorcycleGraph Tracer::run() {
  const int V = m_.num_vertices();
  start_vertex_.assign(V, false);
  std::priority_queue<Walker> queue;
  MotorcycleGraph graph;
  std::vector<std::vector<Leave>> starts(V);
  for (int v = 0; v < V; ++v) {
    if (top_.outgoing(v).empty()) continue;
    start_directions(v, starts[v]);
    if (starts[v].empty()) continue;
    start_vertex_[v] = true;
    ++graph.starts;
  }
  leave_vectors_.assign(V, {});
  std::vector<std::vector<int>> target(V);
  std::vector<std::vector<bool>> skip(V);
  std::vector<std::vector<int>> partner(V);
  for (int v = 0; v < V; ++v) {
    partner[v].assign(starts[v].size(), -1);
    for (const Leave& l : starts[v]) leave_vectors_[v].push_back(leave_vector(v, l));
    target[v].assign(starts[v].size(), -1);
    skip[v].assign(starts[v].size(), false);
  }
  if (options_.pair_singularities) pair_separatrices(starts, target, skip, partner);
  for (const auto& [v, i] : options_.banned)
    if (v >= 0 && v < V && i >= 0 && i < static_cast<int>(skip[v].size())) skip[v][i] = true;
  // Starts separatrix i of v: its trace, and its first step along the chosen way. False when
  // that step already ends it.
  const auto start = [&](int v, int i, Walker& w) {
    const Leave& l = starts[v][i];
    Trace t;
    t.start_vertex = v;
    t.start_way = i;
    t.start_ways = static_cast<int>(starts[v].size());
    t.points.push_back(SurfacePoint::at_vertex(v));
    traces_.push_back(t);
    w = Walker{};
    w.trace = static_cast<int>(traces_.size()) - 1;
    if (owner_[v] < 0) owner_[v] = w.trace;
    w.face = l.face;
    w.angle = l.angle;
    w.target = target[v][i];
    w.partner_way = partner[v][i];
    if (w.face >= 0) return move_in_face(w, SurfacePoint::at_vertex(v), m_.vertices[v]);
    if (l.edge_half_edge < 0) {
      finish(w.trace, Trace::End::Curve, -1);
      return false;
    }
    return move_along_edge(w, l.edge_half_edge);
  };
  // A paired separatrix that stopped before its singularity leaves the one it stood for
  // untraced: that one is traced after all.
  const auto ended = [&](Walker w) {
    while (w.target >= 0) {
      const SurfacePoint& last = traces_[w.trace].points.back();
      if (last.kind == SurfacePoint::Kind::Vertex && last.id == w.target) return;
      Walker next;
      if (start(w.target, w.partner_way, next)) {
        queue.push(next);
        return;
      }
      w = next;
    }
  };
  // Every start's first step is taken before any trace goes on, in start order.
  for (int v = 0; v < V; ++v)
    for (size_t i = 0; i < starts[v].size(); ++i) {
      if (skip[v][i]) continue;
      Walker w;
      if (start(v, static_cast<int>(i), w))
        queue.push(w);
      else
        ended(w);
    }
  while (!queue.empty()) {
    Walker w = queue.top();
    queue.pop();
    if (w.length >= max_length_) {
      finish(w.trace, Trace::End::Unfinished, -1);
      ended(w);
      continue;
    }
    if (advance(w))
      queue.push(w);
    else
      ended(w);
  }
  graph.traces = std::move(traces_);
  return graph;
}

}  // namespace

FaceWays face_ways(const FaceFrames& frames,
                   const std::vector<std::array<detail::Vec3, 2>>& directions) {
  FaceWays ways(directions.size());
  for (size_t f = 0; f < directions.size(); ++f) {
    const int face = static_cast<int>(f);
    const double w0 = frames.angle(face, directions[f][0]);
    const double w1 = frames.angle(face, directions[f][1]);
    ways[f] = {w0, w1, w0 + M_PI, w1 + M_PI};
  }
  return ways;
}

MotorcycleGraph trace_motorcycle_graph(const SurfaceTopology& top, const FaceFrames& frames,
                                       const FaceWays& ways, const std::vector<int>& quarter_index,
                                       const std::vector<bool>& curve_edge,
                                       const TraceOptions& options) {
  if (top.mesh().num_faces() == 0) return {};
  Tracer tracer(top, frames, ways, quarter_index, curve_edge, options);
  return tracer.run();
}

}  // namespace bimdf::layout
