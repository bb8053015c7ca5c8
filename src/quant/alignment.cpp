// Alignment chains (quantize.hpp; ../shared/reference/quadwild_modeling.md §3.5): the
// separatrix leaving a singular chart through a side continues straight through quads, entering
// one side and leaving by the opposite one, until it meets the next singular chart. Aligning
// the two singularities means equal split positions at both ends. A chain qualifies only if
// every side it crosses is a single subside (the reference's FIX_ALIGNMENT_BUG rule), since a
// T-junction on the way would decouple the positions.
#include <set>

#include "bimdf/quant/quantize.hpp"

namespace bimdf::quant {
namespace {

bool singular(int valence) { return valence == 3 || valence == 5 || valence == 6; }

}  // namespace

std::vector<AlignmentPair> find_alignment_pairs(const Layout& layout) {
  std::vector<AlignmentPair> pairs;
  const int C = static_cast<int>(layout.charts.size());
  auto single = [&](int c, int j) { return layout.charts[c].sides[j].subsides.size() == 1; };
  for (int c = 0; c < C; ++c) {
    const Chart& start = layout.charts[c];
    if (start.empty() || !singular(start.valence())) continue;
    for (int j = 0; j < start.valence(); ++j) {
      if (!single(c, j)) continue;
      AlignmentPair pair;
      pair.sides.push_back({c, j});
      std::set<std::array<int, 2>> visited{{c, j}};
      int at_chart = c, at_side = j;
      bool accepted = false;
      for (;;) {
        const Subside& sub = layout.subsides[layout.charts[at_chart].sides[at_side].subsides[0]];
        if (sub.on_border()) break;
        const int slot = sub.charts[0] == at_chart && sub.sides[0] == at_side ? 1 : 0;
        const int x = sub.charts[slot], xs = sub.sides[slot];
        if (!single(x, xs) || !visited.insert({x, xs}).second) break;
        pair.sides.push_back({x, xs});
        const int k = layout.charts[x].valence();
        if (singular(k)) {
          accepted = x > c;  // no self-pairs; each chain once, from its lower-numbered end
          break;
        }
        const int exit = (xs + 2) % 4;
        if (!single(x, exit) || !visited.insert({x, exit}).second) break;
        pair.sides.push_back({x, exit});
        at_chart = x;
        at_side = exit;
      }
      if (accepted) pairs.push_back(std::move(pair));
    }
  }
  return pairs;
}

}  // namespace bimdf::quant
