// The "random" family of generate.hpp.
#include <algorithm>

#include "generate/generators.hpp"

namespace bimdf::detail {
namespace {

Cost random_cost(RandomSource& r, int64_t lo, int64_t up, int depth = 0) {
  for (;;) {
    const double t = r.real(-2, 12), w = r.real(0.01, 3);
    Cost c;
    switch (r.below(8)) {
      case 0: c = Cost::zero(r.between(-2, 6)); break;
      case 1: c = Cost::abs_deviation(t, w); break;
      case 2: c = Cost::quad_deviation(t, w); break;
      case 3: c = Cost::asym_abs_deviation(t, w, r.real(0.01, 3)); break;
      case 4: c = Cost::linear(r.real(-2, 2)); break;
      case 5: c = Cost::scale_factor(r.real(0.5, 10), w, 0.1); break;
      case 6: {
        std::vector<double> values{r.real(0, 5)};
        double slope = -r.real(0, 3);
        for (int i = 0, k = static_cast<int>(r.between(1, 5)); i < k; ++i) {
          values.push_back(values.back() + slope);
          slope += r.real(0, 2);
        }
        c = Cost::piecewise_linear(r.between(-3, 6), std::move(values));
        break;
      }
      default:
        if (depth > 0) continue;
        c = Cost::sum({random_cost(r, lo, up, 1), random_cost(r, lo, up, 1)});
    }
    if (!validate_cost(c, lo, up)) return c;
  }
}

}  // namespace

Problem generate_random_network(int64_t size, uint64_t seed) {
  RandomSource r(seed);
  Problem p;
  const int n = static_cast<int>(std::max<int64_t>(1, size / 3));
  for (int v = 0; v < n; ++v) p.add_node(0);
  std::vector<int64_t> planted;
  for (int64_t e = 0; e < size; ++e) {
    const int u = static_cast<int>(r.below(n));
    int v = static_cast<int>(r.below(n));
    End a{u, r.chance(0.5)};
    std::optional<End> b;
    const int64_t kind = r.below(20);  // 2 in 20 loops, 2 in 20 outer edges
    if (kind < 2) b = End{u, a.head};
    else if (kind >= 4 || n == 1) b = End{v == u ? (v + 1) % n : v, r.chance(0.5)};
    if (b && b->node == u) b->head = a.head;
    int64_t lo = 0, up = kInfinity;
    switch (r.below(10)) {
      case 0: case 1: lo = r.between(0, 3), up = lo + r.between(1, 8); break;
      case 2: lo = up = r.between(0, 5); break;
      case 3: lo = -r.between(1, 6); break;
      case 4: lo = -kInfinity, up = r.between(0, 10); break;
      default: lo = r.between(0, 1);
    }
    Cost c = random_cost(r, lo, up);
    p.add_edge(a, b, lo, up, std::move(c));
    // The planted flow: within the bounds and near the origin.
    planted.push_back(std::clamp<int64_t>(r.between(-2, 10), lo, up));
  }
  for (int e = 0; e < p.num_edges(); ++e) {
    p.demand[p.end_a[e].node] += p.end_a[e].sign() * planted[e];
    if (!p.is_outer(e)) p.demand[p.end_b[e].node] += p.end_b[e].sign() * planted[e];
  }
  return p;
}

}  // namespace bimdf::detail
