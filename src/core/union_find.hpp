// Union–find over 0..n−1 whose representative is always the smallest member, so that the
// classes' representatives do not depend on the order of the unions (deterministic ids for
// whoever numbers classes by them). Internal.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace bimdf::detail {

class SmallestRootUnionFind {
 public:
  explicit SmallestRootUnionFind(int n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace bimdf::detail
