#include "brute_force.hpp"

#include <algorithm>

namespace bimdf::testing {
namespace {

// Depth-first over edges in id order. When an edge is the last one touching a node, its value
// is forced by that node's conservation constraint instead of enumerated; every node is checked
// as soon as all its edges have values.
class Enumerator {
 public:
  Enumerator(const Problem& p, int64_t window) : p_(p), window_(window) {
    const int n = p.num_nodes(), m = p.num_edges();
    last_edge_.assign(n, -1);
    for (int e = 0; e < m; ++e) {
      last_edge_[p.end_a[e].node] = e;
      if (!p.is_outer(e)) last_edge_[p.end_b[e].node] = e;
    }
    balance_.assign(n, 0);
    x_.assign(m, 0);
    for (int e = 0; e < m; ++e) {
      lo_.push_back(p.lower[e] == -kInfinity ? -window : p.lower[e]);
      hi_.push_back(p.upper[e] == kInfinity ? window : p.upper[e]);
      if (p.lower[e] < -window || p.upper[e] > window) result_.exhaustive = false;
      lo_.back() = std::max(lo_.back(), -window);
      hi_.back() = std::min(hi_.back(), window);
    }
  }

  BruteForceResult run() {
    // Nodes without edges must have demand 0.
    for (int v = 0; v < p_.num_nodes(); ++v)
      if (last_edge_[v] < 0 && p_.demand[v] != 0) return result_;
    visit(0);
    return result_;
  }

 private:
  // Coefficient of edge e at node v (−2..2).
  int coef(int e, int v) const {
    int c = 0;
    if (p_.end_a[e].node == v) c += p_.end_a[e].sign();
    if (!p_.is_outer(e) && p_.end_b[e].node == v) c += p_.end_b[e].sign();
    return c;
  }

  void visit(int e) {
    if (e == p_.num_edges()) {
      ++result_.flows_checked;
      double total = 0;
      for (int f = 0; f < p_.num_edges(); ++f) total += p_.cost[f](x_[f]);
      if (!result_.feasible || total < result_.optimum) {
        result_.feasible = true;
        result_.optimum = total;
        result_.flow = x_;
      }
      return;
    }
    // A node completed by this edge forces its value.
    int forcing = -1;
    for (int v : {p_.end_a[e].node, p_.is_outer(e) ? -1 : p_.end_b[e].node})
      if (v >= 0 && last_edge_[v] == e && coef(e, v) != 0) forcing = v;
    if (forcing >= 0) {
      const int c = coef(e, forcing);
      const int64_t rest = p_.demand[forcing] - balance_[forcing];
      if (rest % c != 0) return;
      try_value(e, rest / c);
    } else {
      for (int64_t x = lo_[e]; x <= hi_[e]; ++x) try_value(e, x);
    }
  }

  void try_value(int e, int64_t x) {
    if (x < lo_[e] || x > hi_[e]) return;
    x_[e] = x;
    const int a = p_.end_a[e].node, b = p_.is_outer(e) ? -1 : p_.end_b[e].node;
    balance_[a] += p_.end_a[e].sign() * x;
    if (b >= 0) balance_[b] += p_.end_b[e].sign() * x;
    bool ok = true;
    for (int v : {a, b})
      if (v >= 0 && last_edge_[v] == e && balance_[v] != p_.demand[v]) ok = false;
    if (ok) visit(e + 1);
    balance_[a] -= p_.end_a[e].sign() * x;
    if (b >= 0) balance_[b] -= p_.end_b[e].sign() * x;
  }

  const Problem& p_;
  int64_t window_;
  std::vector<int> last_edge_;
  std::vector<int64_t> balance_, x_, lo_, hi_;
  BruteForceResult result_;
};

}  // namespace

BruteForceResult brute_force(const Problem& problem, int64_t window) {
  return Enumerator(problem, window).run();
}

}  // namespace bimdf::testing
