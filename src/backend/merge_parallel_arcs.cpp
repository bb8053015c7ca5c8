// merge_parallel_arcs.hpp: grouping arcs by their pair of ends, and the split back.
#include "backend/merge_parallel_arcs.hpp"

#include <algorithm>
#include <limits>

namespace bimdf::detail {
namespace {

constexpr int64_t kInfiniteCapacity = std::numeric_limits<int64_t>::max();
constexpr int64_t kMaxRange = int64_t{1} << 62;

// Appends one merged arc from `lo` to `hi` made of `forward` (arcs lo → hi) and `backward`
// (arcs hi → lo), each sorted by ascending cost; false if its range would leave ±2^62. Appends
// nothing when every piece has capacity 0 (its arcs carry nothing).
bool append_arc(const DirectedMcf& mcf, const std::vector<int64_t>& cost, int lo, int hi,
                std::vector<int> forward, std::vector<int> backward, MergedArcs& out) {
  // An infinite piece takes any amount at its cost: dearer pieces after it never fill.
  auto cut_after_infinite = [&](std::vector<int>& pieces) {
    for (size_t i = 0; i < pieces.size(); ++i)
      if (mcf.capacity[pieces[i]] == kInfiniteCapacity) {
        pieces.resize(i + 1);
        return;
      }
  };
  cut_after_infinite(forward);
  cut_after_infinite(backward);
  // Segments from the left: backward pieces dearest first (the infinite one, if any, is the
  // leftmost), then forward ones cheapest first; zero-length pieces add nothing.
  struct Segment {
    int64_t length, slope;
  };
  std::vector<Segment> segments;
  int64_t left = 0;
  for (auto it = backward.rbegin(); it != backward.rend(); ++it)
    if (mcf.capacity[*it] > 0) {
      segments.push_back({mcf.capacity[*it], -cost[*it]});
      if (mcf.capacity[*it] != kInfiniteCapacity && (left -= mcf.capacity[*it]) < -kMaxRange)
        return false;
    }
  const size_t zero_at = segments.size();  // 0 is the breakpoint before this segment
  int64_t right = 0;
  for (int a : forward)
    if (mcf.capacity[a] > 0) {
      segments.push_back({mcf.capacity[a], cost[a]});
      if (mcf.capacity[a] != kInfiniteCapacity && (right += mcf.capacity[a]) > kMaxRange)
        return false;
    }
  if (segments.empty()) return true;

  ConvexMcf& c = out.convex;
  const bool infinite_left =
      !backward.empty() && mcf.capacity[backward.back()] == kInfiniteCapacity;
  int64_t p = infinite_left ? -kUnboundedPoint : left;
  int start = -1;
  for (size_t i = 0; i < segments.size(); ++i) {
    if (i == zero_at) start = static_cast<int>(c.point.size());
    // A joint between equal slopes is no breakpoint, unless it is the start.
    if (i > 0 && i != zero_at && segments[i - 1].slope == segments[i].slope) {
    } else {
      c.point.push_back(p);
      c.slope.push_back(segments[i].slope);
    }
    if (segments[i].length == kInfiniteCapacity)
      p = p == -kUnboundedPoint ? left : kUnboundedPoint;
    else
      p += segments[i].length;
  }
  if (start < 0) start = static_cast<int>(c.point.size());  // 0 is the last breakpoint
  c.point.push_back(p);
  c.slope.push_back(0);  // unused
  c.source.push_back(lo);
  c.target.push_back(hi);
  c.start.push_back(start);
  c.first.push_back(static_cast<int>(c.point.size()));
  out.forward_count.push_back(static_cast<int>(forward.size()));
  out.member.insert(out.member.end(), forward.begin(), forward.end());
  out.member.insert(out.member.end(), backward.begin(), backward.end());
  out.member_first.push_back(static_cast<int>(out.member.size()));
  return true;
}

}  // namespace

std::optional<MergedArcs> merge_parallel_arcs(const DirectedMcf& mcf,
                                              const std::vector<int64_t>& cost) {
  const int n = mcf.num_nodes(), m = mcf.num_arcs();
  MergedArcs out;
  out.convex.supply = mcf.supply;
  out.convex.first.push_back(0);
  out.member_first.push_back(0);
  // Arcs grouped by (smaller end, larger end), in a stable counting sort by each end.
  std::vector<int> by_hi(m), order(m), count(n + 1, 0);
  auto lo_of = [&](int a) { return std::min(mcf.source[a], mcf.target[a]); };
  auto hi_of = [&](int a) { return std::max(mcf.source[a], mcf.target[a]); };
  for (int a = 0; a < m; ++a) ++count[hi_of(a) + 1];
  for (int v = 0; v < n; ++v) count[v + 1] += count[v];
  for (int a = 0; a < m; ++a) by_hi[count[hi_of(a)]++] = a;
  std::fill(count.begin(), count.end(), 0);
  for (int a = 0; a < m; ++a) ++count[lo_of(a) + 1];
  for (int v = 0; v < n; ++v) count[v + 1] += count[v];
  for (int a : by_hi) order[count[lo_of(a)]++] = a;

  auto by_cost = [&](int a, int b) { return cost[a] != cost[b] ? cost[a] < cost[b] : a < b; };
  std::vector<int> forward, backward;
  for (int i = 0; i < m;) {
    const int lo = lo_of(order[i]), hi = hi_of(order[i]);
    int end = i;
    forward.clear();
    backward.clear();
    for (; end < m && lo_of(order[end]) == lo && hi_of(order[end]) == hi; ++end)
      (mcf.source[order[end]] == lo ? forward : backward).push_back(order[end]);
    i = end;
    if (lo == hi) {  // loops: each its own arc
      for (int a : forward)
        if (!append_arc(mcf, cost, lo, hi, {a}, {}, out)) return std::nullopt;
      continue;
    }
    std::sort(forward.begin(), forward.end(), by_cost);
    std::sort(backward.begin(), backward.end(), by_cost);
    if (!forward.empty() && !backward.empty() && cost[forward[0]] + cost[backward[0]] < 0) {
      // A negative two-cycle: the directions are not one convex function.
      if (!append_arc(mcf, cost, lo, hi, forward, {}, out) ||
          !append_arc(mcf, cost, hi, lo, backward, {}, out))
        return std::nullopt;
      continue;
    }
    if (!append_arc(mcf, cost, lo, hi, forward, backward, out)) return std::nullopt;
  }
  return out;
}

std::vector<int64_t> MergedArcs::split(const std::vector<int64_t>& merged_flow,
                                       const std::vector<int64_t>& capacity) const {
  std::vector<int64_t> flow(capacity.size(), 0);
  for (size_t j = 0; j < merged_flow.size(); ++j) {
    const int begin = member_first[j], mid = begin + forward_count[j], end = member_first[j + 1];
    int64_t left = merged_flow[j] >= 0 ? merged_flow[j] : -merged_flow[j];
    const int from = merged_flow[j] >= 0 ? begin : mid, to = merged_flow[j] >= 0 ? mid : end;
    for (int i = from; i < to && left > 0; ++i) {
      const int a = member[i];
      flow[a] = std::min(left, capacity[a]);
      left -= flow[a];
    }
  }
  return flow;
}

}  // namespace bimdf::detail
