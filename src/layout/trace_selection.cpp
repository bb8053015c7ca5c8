// Which traced separatrices a layout keeps (trace_selection.hpp).
#include "layout/trace_selection.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace bimdf::layout {
namespace {

bool is_seed(const std::vector<int>& seeds, int v) {
  return std::find(seeds.begin(), seeds.end(), v) != seeds.end();
}

}  // namespace

int drop_dangling(std::vector<Trace>& traces) {
  std::vector<bool> removed(traces.size(), false);
  bool changed = true;
  while (changed) {
    changed = false;
    for (size_t i = 0; i < traces.size(); ++i) {
      if (removed[i]) continue;
      const Trace& t = traces[i];
      // A trace that ends at a singularity keeps its end, whatever becomes of the trace that
      // passed there first; one that ends on a trace loses it with that trace.
      const bool dangling =
          t.end == Trace::End::Unfinished ||
          (t.end == Trace::End::Trace && t.end_trace >= 0 && removed[t.end_trace]) ||
          t.points.size() < 2;
      if (dangling) removed[i] = changed = true;
    }
  }
  int n = 0;
  std::vector<Trace> kept;
  for (size_t i = 0; i < traces.size(); ++i)
    if (removed[i])
      ++n;
    else
      kept.push_back(std::move(traces[i]));
  traces = std::move(kept);
  return n;
}

void ban_shallow_ends(const std::vector<Trace>& traces, double on_trace, double on_curve,
                      const std::vector<int>& seeds, std::vector<std::array<int, 2>>& banned) {
  for (const Trace& t : traces) {
    const double shallow = t.end == Trace::End::Trace   ? on_trace
                           : t.end == Trace::End::Curve ? on_curve
                                                        : 0;
    if (t.end_angle < shallow && (t.end == Trace::End::Curve || !is_seed(seeds, t.start_vertex)))
      banned.push_back({t.start_vertex, t.start_way});
  }
}

void ban_short_to_curve(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                        const std::vector<int>& seeds, double short_length,
                        std::vector<std::array<int, 2>>& banned) {
  if (short_length <= 0) return;
  std::map<int, std::map<int, const Trace*>> short_ones;  // start vertex → way → trace
  for (const Trace& t : traces)
    if (t.end == Trace::End::Curve && t.length < short_length && !curve_vertex[t.start_vertex] &&
        !is_seed(seeds, t.start_vertex))
      short_ones[t.start_vertex][t.start_way] = &t;
  for (const auto& [v, ways] : short_ones) {
    if (ways.size() < 2) continue;
    const int n = ways.begin()->second->start_ways;
    // Walk each run from its first way (one whose predecessor is not short), or from any way
    // when all of them are short.
    std::set<int> done;
    for (const auto& [first, unused] : ways) {
      if (done.count(first) || (ways.count((first + n - 1) % n) && ways.size() < size_t(n)))
        continue;
      std::vector<const Trace*> run;
      for (int w = first; ways.count(w) && !done.count(w); w = (w + 1) % n) {
        done.insert(w);
        run.push_back(ways.at(w));
      }
      if (run.size() < 2) continue;
      const Trace* keep =
          *std::min_element(run.begin(), run.end(),
                            [](const Trace* a, const Trace* b) { return a->length < b->length; });
      for (const Trace* t : run)
        if (t != keep) banned.push_back({v, t->start_way});
    }
  }
}

void ban_seed_loops(const std::vector<Trace>& traces, const std::vector<bool>& curve_vertex,
                    const std::vector<int>& seeds, double short_length,
                    std::vector<std::array<int, 2>>& banned) {
  std::map<int, std::array<const Trace*, 4>> of_seed;
  for (const Trace& t : traces)
    if (t.start_ways == 4 && !curve_vertex[t.start_vertex] && is_seed(seeds, t.start_vertex))
      of_seed[t.start_vertex][t.start_way] = &t;
  for (const auto& [v, ways] : of_seed)
    for (int w = 0; w < 2; ++w) {
      const Trace *a = ways[w], *b = ways[w + 2];
      if (a && b && a->end == Trace::End::Curve && b->end == Trace::End::Curve &&
          a->length < short_length && b->length < short_length) {
        for (int other : {w + 1, (w + 3) % 4})
          if (ways[other]) banned.push_back({v, other});
        break;
      }
    }
}

}  // namespace bimdf::layout
