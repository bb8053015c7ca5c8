// make_quad_pattern (quant/pattern.hpp): the regular pattern when the side vector allows it,
// otherwise the best cut into regular sub-patches (one cut, else two), otherwise a fan.
//
// A cut is a chain of c interior edges from boundary vertex A to boundary vertex B. Both parts
// must be 3- to 6-gons (A and B become corners of both) with even perimeters, which fixes the
// parity of c. Candidates are ranked by the singularities they create — one per non-quad part
// (a boundary one counts less), one per original corner or earlier cut vertex that a cut
// starts from — plus how far c is from the distance |AB| measured in boundary edges, and the
// first candidate whose embedding is convex is taken.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bimdf/quant/pattern.hpp"
#include "mesh/regular_pattern.hpp"

namespace bimdf::quant {

std::string to_string(PatternKind kind) {
  switch (kind) {
    case PatternKind::Regular:
      return "regular";
    case PatternKind::Cut:
      return "cut";
    case PatternKind::Fan:
      return "fan";
  }
  return "?";
}

std::vector<std::array<double, 2>> pattern_polygon(const std::vector<int>& sides) {
  const int k = static_cast<int>(sides.size());
  std::vector<double> l(sides.begin(), sides.end());
  const auto longest = [&] {
    return static_cast<int>(std::max_element(l.begin(), l.end()) - l.begin());
  };
  double sum = 0;
  for (double x : l) sum += x;
  // A cyclic polygon needs its longest side shorter than the others together; keep a margin
  // (a needle-thin domain helps nobody) by blending towards equal sides.
  while (2 * l[longest()] > 0.9 * sum) {
    for (double& x : l) x = 0.5 * (x + sum / k);
  }
  const int m = longest();
  const double big = l[m];
  const auto angle = [](double side, double radius) {
    return 2 * std::asin(std::min(1.0, side / (2 * radius)));
  };
  // Central angles: with the centre inside, all sides' angles add up to 2π; with the centre
  // outside (the longest side subtends more than π), the others add up to the longest's.
  double others_at_half = 0;
  for (int j = 0; j < k; ++j)
    if (j != m) others_at_half += angle(l[j], big / 2);
  const bool centre_inside = others_at_half >= std::numbers::pi;
  const auto excess = [&](double radius) {
    double total = 0;
    for (int j = 0; j < k; ++j)
      if (j != m) total += angle(l[j], radius);
    return centre_inside ? total + angle(big, radius) - 2 * std::numbers::pi
                         : total - angle(big, radius);
  };
  // excess falls with the radius when the centre is inside and rises when it is outside.
  double lo = big / 2, hi = sum;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    ((excess(mid) > 0) == centre_inside ? lo : hi) = mid;
  }
  const double radius = 0.5 * (lo + hi);
  std::vector<std::array<double, 2>> corners(k);
  double phi = std::numbers::pi / 2;
  for (int j = 0; j < k; ++j) {
    corners[j] = {radius * std::cos(phi), radius * std::sin(phi)};
    phi +=
        j == m && !centre_inside ? -angle(big, radius) + 2 * std::numbers::pi : angle(l[j], radius);
  }
  return corners;
}

int QuadPattern::perimeter() const {
  int p = 0;
  for (int l : sides) p += l;
  return p;
}

namespace {

using detail::PatchPolygon;
using detail::QuadSoup;
using Point = std::array<double, 2>;

// Cost of a regular part in the ranking: its singularity (none for a grid; less when it sits
// on the boundary, where it only bends a side).
double regular_part_cost(const std::vector<int>& sides) {
  if (sides.size() == 4) return 0;
  const std::vector<int> e = regular_strip_counts(sides);
  return std::find(e.begin(), e.end(), 0) != e.end() ? 0.7 : 1.0;
}

struct Cut {
  int a = 0, d = 0, c = 0;  // from ring position a to a + d, c edges
  double cost = 0;
  bool first_regular = false, second_regular = false;
};

struct CutParts {
  std::vector<int> first, second;  // side vectors; the cut is the last side of each
};

// Side vectors of the two parts of `polygon` cut from position a to a + d with c edges.
CutParts cut_sides(const PatchPolygon& polygon, int a, int d, int c) {
  const int n = polygon.size();
  std::vector<int> inner_first, inner_second;  // unwrapped corner positions strictly inside
  for (int corner : polygon.corners) {
    int p = corner < a ? corner + n : corner;
    if (p > a && p < a + d) inner_first.push_back(p);
    if (p > a + d && p < a + n) inner_second.push_back(p);
  }
  std::sort(inner_first.begin(), inner_first.end());
  std::sort(inner_second.begin(), inner_second.end());
  CutParts parts;
  int previous = a;
  for (int p : inner_first) parts.first.push_back(p - previous), previous = p;
  parts.first.push_back(a + d - previous);
  parts.first.push_back(c);
  previous = a + d;
  for (int p : inner_second) parts.second.push_back(p - previous), previous = p;
  parts.second.push_back(a + n - previous);
  parts.second.push_back(c);
  return parts;
}

// The two polygons of a cut, with its c − 1 new vertices (ids from soup.next_vertex, domain
// guesses appended to `guess` along the segment from B to A).
std::pair<PatchPolygon, PatchPolygon> split(const PatchPolygon& polygon, const Cut& cut,
                                            QuadSoup& soup, std::vector<Point>& guess) {
  const int n = polygon.size();
  const auto at = [&](int p) { return polygon.ring[p % n]; };
  const int va = at(cut.a), vb = at(cut.a + cut.d);
  std::vector<int> chain;  // from B (exclusive) to A (exclusive)
  for (int i = 1; i < cut.c; ++i) {
    chain.push_back(soup.next_vertex++);
    const double t = double(i) / cut.c;
    guess.push_back({guess[vb][0] + t * (guess[va][0] - guess[vb][0]),
                     guess[vb][1] + t * (guess[va][1] - guess[vb][1])});
  }
  PatchPolygon first, second;
  for (int p = cut.a; p <= cut.a + cut.d; ++p) first.ring.push_back(at(p));
  for (int p = cut.a + cut.d; p <= cut.a + n; ++p) second.ring.push_back(at(p));
  first.ring.insert(first.ring.end(), chain.begin(), chain.end());
  second.ring.insert(second.ring.end(), chain.rbegin(), chain.rend());
  const CutParts parts = cut_sides(polygon, cut.a, cut.d, cut.c);
  for (auto [poly, sides] : {std::pair{&first, &parts.first}, std::pair{&second, &parts.second}}) {
    int position = 0;
    for (int l : *sides) poly->corners.push_back(position), position += l;
  }
  return {first, second};
}

struct CutSearch {
  const PatchPolygon& polygon;
  const std::vector<Point>& guess;
  const std::vector<char>& is_cut_vertex;  // by vertex id: an earlier cut's interior vertex
  double edge_length;                      // mean boundary edge length in the domain
};

// Every cut into two 3- to 6-gons with at least one regular part, cheapest first.
std::vector<Cut> rank_cuts(const CutSearch& s) {
  const PatchPolygon& polygon = s.polygon;
  const int n = polygon.size();
  std::vector<char> is_corner(n, 0);
  for (int c : polygon.corners) is_corner[c] = 1;
  const auto start_cost = [&](int p) {
    const int v = polygon.ring[p % n];
    return (is_corner[p % n] || s.is_cut_vertex[v]) ? 1.0 : 0.0;
  };
  std::vector<Cut> cuts;
  for (int a = 0; a < n; ++a) {
    for (int d = 2; d <= n - 2; ++d) {
      const Point& pa = s.guess[polygon.ring[a]];
      const Point& pb = s.guess[polygon.ring[(a + d) % n]];
      const double span = std::hypot(pa[0] - pb[0], pa[1] - pb[1]) / s.edge_length;
      const int c_mid = std::max(1, static_cast<int>(std::lround(span)));
      for (int c = std::max(1, c_mid - 3); c <= c_mid + 3; ++c) {
        if ((d + c) % 2 != 0) continue;
        const CutParts parts = cut_sides(polygon, a, d, c);
        const int k1 = static_cast<int>(parts.first.size());
        const int k2 = static_cast<int>(parts.second.size());
        if (k1 < 3 || k1 > 6 || k2 < 3 || k2 > 6) continue;
        Cut cut{a, d, c};
        cut.first_regular = !regular_strip_counts(parts.first).empty();
        cut.second_regular = !regular_strip_counts(parts.second).empty();
        if (!cut.first_regular && !cut.second_regular) continue;
        cut.cost = start_cost(a) + start_cost(a + d) + (c - span) * (c - span) / (span + 1);
        if (cut.first_regular) cut.cost += regular_part_cost(parts.first);
        if (cut.second_regular) cut.cost += regular_part_cost(parts.second);
        cuts.push_back(cut);
      }
    }
  }
  std::stable_sort(cuts.begin(), cuts.end(),
                   [](const Cut& x, const Cut& y) { return x.cost < y.cost; });
  return cuts;
}

// Tutte's embedding: boundary fixed, every interior vertex at the mean of its neighbours.
std::vector<Point> embed(const std::vector<std::array<int, 4>>& quads, int num_vertices,
                         const std::vector<Point>& boundary) {
  const int nb = static_cast<int>(boundary.size());
  std::vector<Point> x(num_vertices, Point{0, 0});
  std::copy(boundary.begin(), boundary.end(), x.begin());
  const int ni = num_vertices - nb;
  if (ni == 0) return x;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  std::vector<double> degree(ni, 0);
  // Each undirected edge appears in two quads (or one on the boundary): count it once.
  for (const auto& q : quads)
    for (int a = 0; a < 4; ++a) {
      const int u = q[a], v = q[(a + 1) % 4];
      for (auto [p, r] : {std::pair{u, v}, std::pair{v, u}}) {
        if (p < nb) continue;
        degree[p - nb] += 0.5;
        if (r < nb) {
          rhs(p - nb, 0) += 0.5 * x[r][0];
          rhs(p - nb, 1) += 0.5 * x[r][1];
        } else {
          entries.emplace_back(p - nb, r - nb, -0.5);
        }
      }
    }
  // An edge with an interior end is an interior edge, met once in each of its two quads: the
  // halves above give it weight 1.
  for (int i = 0; i < ni; ++i) entries.emplace_back(i, i, degree[i]);
  Eigen::SparseMatrix<double> laplacian(ni, ni);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  const Eigen::MatrixXd solution = solver.solve(rhs);
  for (int i = 0; i < ni; ++i) x[nb + i] = {solution(i, 0), solution(i, 1)};
  return x;
}

bool all_convex(const std::vector<std::array<int, 4>>& quads, const std::vector<Point>& x) {
  for (const auto& q : quads) {
    double area = 0;
    for (int a = 0; a < 4; ++a) {
      const Point& p = x[q[(a + 3) % 4]];
      const Point& c = x[q[a]];
      const Point& n = x[q[(a + 1) % 4]];
      const double turn = (c[0] - p[0]) * (n[1] - c[1]) - (c[1] - p[1]) * (n[0] - c[0]);
      if (turn < -1e-12) return false;
      area += c[0] * n[1] - c[1] * n[0];
    }
    if (area <= 1e-14) return false;
  }
  return true;
}

class PatternBuilder {
 public:
  explicit PatternBuilder(const std::vector<int>& sides) : sides_(sides) {
    const int k = static_cast<int>(sides.size());
    for (int j = 0; j < k; ++j) {
      root_.corners.push_back(perimeter_);
      perimeter_ += sides[j];
    }
    for (int v = 0; v < perimeter_; ++v) root_.ring.push_back(v);
    corners_ = pattern_polygon(sides);
    const std::vector<Point>& corner = corners_;
    double length = 0;
    for (int j = 0; j < k; ++j) {
      const Point& p = corner[j];
      const Point& q = corner[(j + 1) % k];
      length += std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    edge_length_ = length / perimeter_;
    for (int j = 0; j < k; ++j) {
      const Point& p = corner[j];
      const Point& q = corner[(j + 1) % k];
      for (int t = 0; t < sides[j]; ++t) {
        const double s = double(t) / sides[j];
        boundary_.push_back({p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])});
      }
    }
  }

  QuadPattern build() {
    QuadSoup soup{perimeter_, {}};
    if (detail::add_regular_pattern(root_, soup) && accept(soup, PatternKind::Regular, 0))
      return result_;
    // The root's cuts, ranked once for both kinds of attempt.
    const std::vector<char> no_cut_vertex(perimeter_, 0);
    const std::vector<Cut> cuts = rank_cuts({root_, boundary_, no_cut_vertex, edge_length_});
    if (try_cuts(cuts) || try_double_cuts(cuts)) return result_;
    // Last resorts: quads fanned around one new centre vertex (pairs of boundary edges, from
    // an even or odd start), or around a corner.
    std::vector<QuadSoup> fans;
    for (int start = 0; start < 2; ++start) {
      QuadSoup star{perimeter_ + 1, {}};
      for (int i = 0; 2 * i < perimeter_; ++i)
        star.quads.push_back({perimeter_, (start + 2 * i) % perimeter_,
                              (start + 2 * i + 1) % perimeter_, (start + 2 * i + 2) % perimeter_});
      fans.push_back(star);
    }
    for (int corner : root_.corners) {
      QuadSoup fan{perimeter_, {}};
      const auto at = [&](int i) { return (corner + i) % perimeter_; };
      for (int i = 1; 2 * i + 1 < perimeter_; ++i)
        fan.quads.push_back({at(0), at(2 * i - 1), at(2 * i), at(2 * i + 1)});
      fans.push_back(fan);
    }
    for (const QuadSoup& fan : fans)
      if (accept(fan, PatternKind::Fan, 0)) return result_;
    // A valid all-quad disk whatever its shape: better bad quads than a hole.
    accept(fans.front(), PatternKind::Fan, 0, /*require_convex=*/false);
    return result_;
  }

 private:
  static constexpr int kCandidates = 40;

  // Cuts into two regular parts.
  bool try_cuts(const std::vector<Cut>& cuts) {
    int tried = 0;
    for (const Cut& cut : cuts) {
      if (!cut.first_regular || !cut.second_regular) continue;
      if (++tried > kCandidates) break;
      QuadSoup soup{perimeter_, {}};
      std::vector<Point> guess = boundary_;
      auto [first, second] = split(root_, cut, soup, guess);
      if (detail::add_regular_pattern(first, soup) && detail::add_regular_pattern(second, soup) &&
          accept(soup, PatternKind::Cut, 1))
        return true;
    }
    return false;
  }

  // One part regular, the other cut once more into regular parts.
  bool try_double_cuts(const std::vector<Cut>& cuts) {
    int tried = 0;
    for (const Cut& cut : cuts) {
      if (cut.first_regular && cut.second_regular) continue;
      if (++tried > kCandidates) break;
      QuadSoup soup{perimeter_, {}};
      std::vector<Point> guess = boundary_;
      auto [first, second] = split(root_, cut, soup, guess);
      PatchPolygon& regular = cut.first_regular ? first : second;
      PatchPolygon& rest = cut.first_regular ? second : first;
      if (!detail::add_regular_pattern(regular, soup)) continue;
      std::vector<char> is_cut_vertex(soup.next_vertex, 0);
      for (int v = perimeter_; v < soup.next_vertex; ++v) is_cut_vertex[v] = 1;
      const std::vector<Cut> inner = rank_cuts({rest, guess, is_cut_vertex, edge_length_});
      int inner_tried = 0;
      for (const Cut& second_cut : inner) {
        if (!second_cut.first_regular || !second_cut.second_regular) continue;
        if (++inner_tried > 4) break;
        QuadSoup attempt = soup;
        std::vector<Point> attempt_guess = guess;
        auto [x, y] = split(rest, second_cut, attempt, attempt_guess);
        if (detail::add_regular_pattern(x, attempt) && detail::add_regular_pattern(y, attempt) &&
            accept(attempt, PatternKind::Cut, 2))
          return true;
      }
    }
    return false;
  }

  bool accept(const QuadSoup& soup, PatternKind kind, int cuts, bool require_convex = true) {
    if (!detail::is_disk_with_boundary(soup.quads, soup.next_vertex, root_.ring)) return false;
    std::vector<Point> x = embed(soup.quads, soup.next_vertex, boundary_);
    if (require_convex && !all_convex(soup.quads, x)) return false;
    result_ = QuadPattern{sides_, soup.quads, std::move(x), kind, cuts, corners_};
    return true;
  }

  std::vector<int> sides_;
  int perimeter_ = 0;
  PatchPolygon root_;
  std::vector<Point> corners_;   // pattern_polygon(sides_)
  std::vector<Point> boundary_;  // ring vertex positions on it
  double edge_length_ = 1;
  QuadPattern result_;
};

}  // namespace

QuadPattern make_quad_pattern(const std::vector<int>& sides) {
  const int k = static_cast<int>(sides.size());
  if (k < 3 || k > 6)
    throw std::invalid_argument("quad pattern: " + std::to_string(k) + " sides, expected 3 to 6");
  int perimeter = 0;
  for (int j = 0; j < k; ++j) {
    if (sides[j] < 1)
      throw std::invalid_argument("quad pattern: side " + std::to_string(j) + " has length " +
                                  std::to_string(sides[j]) + ", expected at least 1");
    perimeter += sides[j];
  }
  if (perimeter % 2 != 0 || perimeter < 4)
    throw std::invalid_argument("quad pattern: perimeter " + std::to_string(perimeter) +
                                ", expected an even number of at least 4");
  return PatternBuilder(sides).build();
}

}  // namespace bimdf::quant
