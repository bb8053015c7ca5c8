#include "generality_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>

#include "backend/min_cost_flow.hpp"
#include "backend/perfect_matching.hpp"
#include "bench_util.hpp"
#include "bimdf/problem.hpp"
#include "bimdf/solve.hpp"

namespace bimdf::bench {
namespace {

using Clock = std::chrono::steady_clock;

// One instance: the Bi-MDF form, and the dedicated solve, which returns its objective.
struct Instance {
  std::string family, name;
  Problem problem;
  int lemon_nodes = 0, lemon_edges = 0;  // the graph LEMON solves
  std::function<double()> solve_dedicated;
};

struct Point {
  double x, y;
};

std::vector<Point> random_points(int n, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> points(n);
  for (Point& p : points) p = {unit(random), unit(random)};
  return points;
}

// The pairs (i, j), i < j, with j among i's k nearest points or i among j's, and the extra
// pairs given; no duplicates.
std::vector<std::pair<int, int>> neighbour_pairs(const std::vector<Point>& p, int k,
                                                 std::vector<std::pair<int, int>> pairs) {
  const int n = static_cast<int>(p.size());
  std::vector<std::pair<double, int>> by_distance;
  for (int i = 0; i < n; ++i) {
    by_distance.clear();
    for (int j = 0; j < n; ++j)
      if (j != i) by_distance.push_back({std::hypot(p[i].x - p[j].x, p[i].y - p[j].y), j});
    const int take = std::min(k, n - 1);
    std::partial_sort(by_distance.begin(), by_distance.begin() + take, by_distance.end());
    for (int r = 0; r < take; ++r)
      pairs.push_back({std::min(i, by_distance[r].second), std::max(i, by_distance[r].second)});
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

Instance perfect_matching_instance(int n, uint64_t seed) {
  std::mt19937_64 random(seed);
  const std::vector<Point> p = random_points(n, random);
  std::vector<std::pair<int, int>> partners;
  for (int i = 0; i + 1 < n; i += 2) partners.push_back({i, i + 1});
  const auto pairs = neighbour_pairs(p, 8, partners);
  Instance inst{
      "perfect matching", "n=" + std::to_string(n), {}, n, static_cast<int>(pairs.size()), {}};
  std::vector<double> weight;
  for (int i = 0; i < n; ++i) inst.problem.add_node(1);
  for (const auto& [i, j] : pairs) {
    weight.push_back(1 + std::round(1000 * std::hypot(p[i].x - p[j].x, p[i].y - p[j].y)));
    inst.problem.add_edge({i, true}, End{j, true}, 0, 1, Cost::linear(weight.back()));
  }
  inst.solve_dedicated = [n, pairs, weight] {
    detail::MatchingGraph g;
    g.num_nodes = n;
    for (size_t e = 0; e < pairs.size(); ++e) {
      g.end_a.push_back(pairs[e].first);
      g.end_b.push_back(pairs[e].second);
      g.weight.push_back(-weight[e]);
    }
    const auto matched = detail::max_weight_perfect_matching(g);
    if (!matched) throw std::runtime_error("LEMON found no perfect matching");
    double total = 0;
    for (size_t e = 0; e < pairs.size(); ++e) total += (*matched)[e] ? weight[e] : 0;
    return total;
  };
  return inst;
}

Instance min_cost_flow_instance(int n, int m, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<int> node(0, n - 1), capacity(1, 50), unit_cost(1, 100);
  detail::DirectedMcf mcf;
  mcf.supply.assign(n, 0);
  const auto add_arc = [&](int s, int t, int64_t cap, double c) {
    mcf.source.push_back(s);
    mcf.target.push_back(t);
    mcf.capacity.push_back(cap);
    mcf.cost.push_back(c);
  };
  for (int v = 0; v < n; ++v) add_arc(v, (v + 1) % n, INT64_MAX, 100);
  while (mcf.num_arcs() < m) {
    const int s = node(random), t = node(random);
    if (s != t) add_arc(s, t, capacity(random), unit_cost(random));
  }
  // A tenth of the nodes supply, a tenth demand, the same total.
  std::uniform_int_distribution<int> amount(1, 100);
  for (int k = 0; k < n / 10; ++k) {
    const int a = amount(random);
    mcf.supply[node(random)] += a;
    mcf.supply[node(random)] -= a;
  }
  Instance inst{
      "directed min-cost flow", "n=" + std::to_string(n) + " m=" + std::to_string(m), {}, n, m, {}};
  for (int v = 0; v < n; ++v) inst.problem.add_node(-mcf.supply[v]);
  for (int a = 0; a < m; ++a)
    inst.problem.add_edge({mcf.source[a], false}, End{mcf.target[a], true}, 0,
                          mcf.capacity[a] == INT64_MAX ? kInfinity : mcf.capacity[a],
                          Cost::linear(mcf.cost[a]));
  inst.solve_dedicated = [mcf] {
    const detail::MinCostFlowResult r = detail::solve_min_cost_flow(mcf);
    if (r.status != detail::MinCostFlowStatus::Optimal)
      throw std::runtime_error("LEMON's network simplex found no optimal flow");
    double total = 0;
    for (int a = 0; a < mcf.num_arcs(); ++a) total += mcf.cost[a] * r.flow[a];
    return total;
  };
  return inst;
}

Instance b_matching_instance(int n, uint64_t seed) {
  std::mt19937_64 random(seed);
  const std::vector<Point> p = random_points(n, random);
  const auto pairs = neighbour_pairs(p, 6, {});
  std::uniform_int_distribution<int> capacity(1, 3);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<int> cap;
  std::vector<Cost> cost;
  std::vector<int64_t> b(n, 0);
  for (const auto& [i, j] : pairs) {
    cap.push_back(capacity(random));
    cost.push_back(Cost::quad_deviation(cap.back() * unit(random), 0.5 + unit(random)));
    const int x = std::uniform_int_distribution<int>(0, cap.back())(random);
    b[i] += x, b[j] += x;
  }
  Instance inst{"b-matching, quadratic, two-tailed", "n=" + std::to_string(n), {}, 0, 0, {}};
  for (int v = 0; v < n; ++v) inst.problem.add_node(-b[v]);
  for (size_t e = 0; e < pairs.size(); ++e)
    inst.problem.add_edge({pairs[e].first, false}, End{pairs[e].second, false}, 0, cap[e], cost[e]);
  // The perfect matching: b(v) copies of node v, then per unit copy (edge e, unit k) two gadget
  // nodes; weights are negated costs.
  detail::MatchingGraph g;
  std::vector<int> first_copy(n + 1, 0);
  for (int v = 0; v < n; ++v) first_copy[v + 1] = first_copy[v] + static_cast<int>(b[v]);
  g.num_nodes = first_copy[n];
  std::vector<std::pair<int, double>> unit_of_edge;  // per gadget edge a–b: (edge, increment)
  const auto add = [&g](int a, int c, double w) {
    g.end_a.push_back(a);
    g.end_b.push_back(c);
    g.weight.push_back(w);
  };
  std::vector<int> middle_edge;  // the a–b edge of each unit copy
  double base = 0;               // Σ cost(0)
  for (size_t e = 0; e < pairs.size(); ++e) {
    const auto [u, v] = pairs[e];
    base += cost[e](0);
    for (int k = 1; k <= cap[e]; ++k) {
      const double increment = cost[e](k) - cost[e](k - 1);
      const int a = g.num_nodes++, c = g.num_nodes++;
      for (int i = first_copy[u]; i < first_copy[u + 1]; ++i) add(i, a, -increment);
      middle_edge.push_back(g.num_edges());
      unit_of_edge.push_back({static_cast<int>(e), increment});
      add(a, c, 0);
      for (int j = first_copy[v]; j < first_copy[v + 1]; ++j) add(c, j, 0);
    }
  }
  inst.lemon_nodes = g.num_nodes;
  inst.lemon_edges = g.num_edges();
  inst.solve_dedicated = [g, middle_edge, unit_of_edge, base] {
    const auto matched = detail::max_weight_perfect_matching(g);
    if (!matched) throw std::runtime_error("LEMON found no perfect matching");
    double total = base;
    for (size_t u = 0; u < middle_edge.size(); ++u)
      if (!(*matched)[middle_edge[u]]) total += unit_of_edge[u].second;
    return total;
  };
  return inst;
}

std::vector<Instance> instances() {
  std::vector<Instance> all;
  for (int n : {200, 1000, 3000}) all.push_back(perfect_matching_instance(n, 11 + n));
  for (auto [n, m] : {std::pair{1000, 5000}, {3000, 15000}})
    all.push_back(min_cost_flow_instance(n, m, 23 + n));
  for (int n : {100, 300}) all.push_back(b_matching_instance(n, 37 + n));
  return all;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

std::string benchmark_generality(int repeats) {
  std::ostringstream md;
  md << "Generated by `bimdf_bench --only-generality` on " << shell("date -u +%Y-%m-%d")
     << ", commit `" << shell("git rev-parse --short HEAD 2>/dev/null") << "`, median of "
     << repeats << " runs. bimdf: `Solver::run()` (exact). LEMON: its dedicated algorithm "
     << "through bimdf's adapters (graph built, costs scaled, solved).\n\n"
     << "| family | instance | Bi-MDF nodes / edges | LEMON nodes / edges | objective | "
        "bimdf ms | LEMON ms | bimdf / LEMON |\n|---|---|---|---|---|---|---|---|\n";
  double total_bimdf = 0, total_lemon = 0, worst_ratio = 0;
  for (Instance& inst : instances()) {
    std::vector<double> bimdf_s, lemon_s;
    double objective = NAN, dedicated = NAN;
    for (int r = 0; r < repeats; ++r) {
      Solver solver(inst.problem);
      const Clock::time_point start = Clock::now();
      if (solver.run() != SolveStatus::Optimal)
        throw std::runtime_error(inst.family + " " + inst.name + ": bimdf found no optimum");
      bimdf_s.push_back(seconds_since(start));
      objective = solver.solution().objective;
      const Clock::time_point lemon_start = Clock::now();
      dedicated = inst.solve_dedicated();
      lemon_s.push_back(seconds_since(lemon_start));
    }
    if (std::fabs(objective - dedicated) > 1e-6 * std::max(1.0, std::fabs(dedicated)))
      throw std::runtime_error(inst.family + " " + inst.name + ": bimdf's optimum " +
                               fmt(objective, 6) + " differs from LEMON's " + fmt(dedicated, 6));
    const double b = median(bimdf_s) * 1000, l = median(lemon_s) * 1000;
    total_bimdf += b, total_lemon += l, worst_ratio = std::max(worst_ratio, b / l);
    md << "| " << inst.family << " | " << inst.name << " | " << inst.problem.num_nodes() << " / "
       << inst.problem.num_edges() << " | " << inst.lemon_nodes << " / " << inst.lemon_edges
       << " | " << fmt(objective, 3) << " | " << fmt(b, 1) << " | " << fmt(l, 1) << " | "
       << fmt(b / l, 2) << "× |\n";
  }
  md << "\nTotal: bimdf " << fmt(total_bimdf, 1) << " ms, LEMON " << fmt(total_lemon, 1) << " ms ("
     << fmt(total_bimdf / total_lemon, 2) << "×); worst instance " << fmt(worst_ratio, 2)
     << "×. Every objective equal (relative difference ≤ 10⁻⁶).\n";
  return md.str();
}

}  // namespace bimdf::bench
