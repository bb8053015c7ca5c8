#include "random_problem.hpp"

#include <algorithm>
#include <cmath>

namespace bimdf::testing {
namespace {

double random_double(std::mt19937_64& rng) {
  // Mix of "nice" values and arbitrary bit patterns, so round-trips see both.
  switch (rng() % 3) {
    case 0:
      return static_cast<double>(rng() % 11) / 2.0;
    case 1:
      return std::uniform_real_distribution<double>(0.0, 10.0)(rng);
    default: {
      // Exponent first: see random_cost on the order of draws.
      const int exponent = -static_cast<int>(rng() % 30);
      return std::ldexp(std::uniform_real_distribution<double>(0.5, 1.0)(rng), exponent);
    }
  }
}

}  // namespace

Cost random_cost(std::mt19937_64& rng, const RandomProblemOptions& o, int64_t lower, int64_t upper,
                 int depth) {
  const bool ext = o.all_cost_kinds;
  const bool scale_ok = lower >= 0;
  for (;;) {
    const int kind = static_cast<int>(rng() % (ext ? 8 : 5));
    Cost c;
    switch (kind) {
      case 0:
        c = Cost::zero(ext ? static_cast<int64_t>(rng() % 7) - 2 : 0);
        break;
      // Parameters are drawn into locals, last first: the order gcc evaluated them in as call
      // arguments, whose order is the compiler's. So every compiler draws the same problems.
      case 1: {
        const double weight = random_double(rng), target = random_double(rng);
        c = Cost::abs_deviation(target, weight);
        break;
      }
      case 2: {
        const double weight = random_double(rng), target = random_double(rng);
        c = Cost::quad_deviation(target, weight);
        break;
      }
      case 3: {
        if (!scale_ok) continue;
        const double eps = 0.1 + random_double(rng), weight = random_double(rng),
                     target = random_double(rng);
        c = Cost::scale_factor(target, weight, eps);
        break;
      }
      case 4: {
        if (depth > 1) continue;
        std::vector<Cost> terms;
        const int k = 1 + static_cast<int>(rng() % 3);
        for (int i = 0; i < k; ++i) terms.push_back(random_cost(rng, o, lower, upper, depth + 1));
        c = Cost::sum(std::move(terms));
        break;
      }
      case 5:
        c = Cost::linear(random_double(rng) - 5.0);
        break;
      case 6: {
        const double above = random_double(rng), below = random_double(rng),
                     target = random_double(rng);
        c = Cost::asym_abs_deviation(target, below, above);
        break;
      }
      default: {
        // Convex: increasing slopes.
        std::vector<double> values{random_double(rng)};
        double slope = -random_double(rng);
        const int k = static_cast<int>(rng() % 5);
        for (int i = 0; i < k; ++i) {
          values.push_back(values.back() + slope);
          slope += random_double(rng);
        }
        c = Cost::piecewise_linear(static_cast<int64_t>(rng() % 5) - 2, std::move(values));
        break;
      }
    }
    if (!validate_cost(c, lower, upper)) return c;
  }
}

Problem random_problem(std::mt19937_64& rng, const RandomProblemOptions& o) {
  Problem p;
  const int n = o.min_nodes + static_cast<int>(rng() % (o.max_nodes - o.min_nodes + 1));
  for (int v = 0; v < n; ++v) p.add_node(static_cast<int64_t>(rng() % 7) - 3);
  const int m = o.min_edges + static_cast<int>(rng() % (o.max_edges - o.min_edges + 1));
  for (int e = 0; e < m; ++e) {
    End a{static_cast<int>(rng() % n), rng() % 2 == 0};
    std::optional<End> b;
    if (!o.outer_edges || rng() % 6 != 0) {
      b = End{static_cast<int>(rng() % n), rng() % 2 == 0};
      if (b->node == a.node) b->head = a.head;  // loops are head-head or tail-tail
    }
    int64_t lo = 0, up = kInfinity;
    switch (rng() % 5) {
      case 0:
        lo = static_cast<int64_t>(rng() % 3);
        break;
      case 1:
        lo = static_cast<int64_t>(rng() % 3);
        up = lo + static_cast<int64_t>(rng() % 4);
        break;
      case 2:
        lo = up = static_cast<int64_t>(rng() % 4);
        break;
      case 3:
        if (o.all_cost_kinds) lo = rng() % 2 ? -kInfinity : -static_cast<int64_t>(rng() % 3);
        break;
      default:
        break;
    }
    p.add_edge(a, b, lo, up, random_cost(rng, o, lo, up));
  }
  if (o.names) {
    p.node_name.resize(n);
    p.edge_name.resize(m);
    for (int v = 0; v < n; ++v)
      if (rng() % 3) p.node_name[v] = "n" + std::to_string(v) + (rng() % 2 ? " \"q\"" : "");
    for (int e = 0; e < m; ++e)
      if (rng() % 2) p.edge_name[e] = "edge-" + std::to_string(e);
    // The canonical form readers produce: no vector when nothing is named.
    auto all_empty = [](const auto& names) {
      return std::all_of(names.begin(), names.end(), [](const auto& s) { return s.empty(); });
    };
    if (all_empty(p.node_name)) p.node_name.clear();
    if (all_empty(p.edge_name)) p.edge_name.clear();
  }
  return p;
}

void plant_feasible_demands(Problem& p, std::mt19937_64& rng) {
  std::fill(p.demand.begin(), p.demand.end(), 0);
  for (int e = 0; e < p.num_edges(); ++e) {
    const int64_t lo = std::max<int64_t>(p.lower[e], -3), hi = std::min<int64_t>(p.upper[e], 5);
    const int64_t x = lo + static_cast<int64_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
    p.demand[p.end_a[e].node] += p.end_a[e].sign() * x;
    if (!p.is_outer(e)) p.demand[p.end_b[e].node] += p.end_b[e].sign() * x;
  }
}

}  // namespace bimdf::testing
