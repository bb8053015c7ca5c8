// search_density_factor (density_search.hpp).
#include "tmesh/density_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bimdf::tmesh::detail {

DensitySearch search_density_factor(double wanted, double start, double tolerance, int max_solves,
                                    double limit, const std::function<double(double)>& quads_at) {
  DensitySearch best;
  best.factor = start;
  double factor = start, quads = quads_at(factor);
  best.solves = 1;
  if (quads < 0) return best;
  best.quads = quads;
  double last_factor = 0, last_quads = 0;
  double too_few = 0, too_many = std::numeric_limits<double>::infinity();
  const auto note = [&](double f, double q) {
    if (q < wanted) too_few = std::max(too_few, f);
    if (q > wanted) too_many = std::min(too_many, f);
  };
  note(factor, quads);
  double slope = 2;
  while (best.solves < max_solves && quads > 0 && std::abs(quads / wanted - 1) > tolerance) {
    if (last_factor > 0 && last_quads > 0 && last_quads == quads) {
      slope = std::max(0.25, slope / 2);  // on a step's flat: stride out, doubling
    } else {
      slope = 2;
      if (last_factor > 0 && last_quads > 0) {
        slope = std::log(quads / last_quads) / std::log(factor / last_factor);
        if (!(slope >= 0.5 && slope <= 4)) slope = 2;
      }
    }
    double next = std::clamp(factor * std::exp(std::log(wanted / quads) / slope), 1 / limit, limit);
    if (too_few > 0 && std::isfinite(too_many) && !(next > too_few && next < too_many))
      next = std::sqrt(too_few * too_many);
    if (std::abs(next / factor - 1) < 1e-6) break;  // at a limit, or the bracket closed
    last_factor = factor, last_quads = quads, factor = next;
    quads = quads_at(factor);
    ++best.solves;
    if (quads < 0) break;
    note(factor, quads);
    if (std::abs(quads - wanted) < std::abs(best.quads - wanted))
      best.quads = quads, best.factor = factor;
  }
  return best;
}

DensitySearch search_density_factor_within_reach(double wanted, double start, double tolerance,
                                                 int max_solves, double limit, double reach,
                                                 const std::function<double(double)>& quads_at) {
  DensitySearch found =
      search_density_factor(wanted, start, tolerance, max_solves, limit, quads_at);
  // Too many quads left: the search ended at the limit or on a flat step on its way there.
  if (!(found.quads > wanted * (1 + tolerance)) || reach <= limit) return found;
  const double probe = quads_at(1 / reach);
  ++found.solves;
  if (probe < 0) return found;
  if (probe > wanted * (1 + tolerance)) {
    found.floor_quads = probe;
    return found;
  }
  if (probe >= wanted * (1 - tolerance)) return {1 / reach, probe, found.solves};
  // The wanted count lies between the two factors: search from their geometric middle.
  const DensitySearch wider = search_density_factor(wanted, 1 / std::sqrt(limit * reach), tolerance,
                                                    max_solves, reach, quads_at);
  DensitySearch best = found;
  for (const DensitySearch& candidate : {DensitySearch{1 / reach, probe, 0}, wider})
    if (candidate.quads >= 0 && std::abs(candidate.quads - wanted) < std::abs(best.quads - wanted))
      best = candidate;
  best.solves = found.solves + wider.solves;
  return best;
}

}  // namespace bimdf::tmesh::detail
