// The generality benchmark (issue 25): problems that have a dedicated algorithm, written as
// Bi-MDF and solved by bimdf's exact solver and by that algorithm in LEMON, objectives
// compared and times side by side. It tells a user with a matching or a directed min-cost flow
// what writing it as Bi-MDF costs.
//   * Minimum-weight perfect matching: random points in the unit square, each joined to its 8
//     nearest neighbours and to its partner (2i, 2i + 1) so that a perfect matching exists;
//     integer weights ~1000·distance. Bi-MDF: demand 1 per node, head–head edges in [0, 1].
//     LEMON: MaxWeightedPerfectMatching on the negated weights.
//   * Directed min-cost flow with node supplies: random arcs plus a ring of unbounded arcs
//     (so that every supply can be routed), capacities 1–50, costs 1–100, a tenth of the nodes
//     sources or sinks. Bi-MDF: tail at the arc's source, head at its target, demand
//     inflow − outflow. LEMON: NetworkSimplex.
//   * Capacitated b-matching with quadratic costs on two-tailed edges: random geometric graph
//     (6 nearest neighbours), capacities 1–3, cost w·(x − t)² with real t in [0, capacity],
//     demands b(v) from a random flow (so it is feasible). Bi-MDF: tail–tail edges, demand
//     −b(v). LEMON: MaxWeightedPerfectMatching on the textbook reduction — b(v) copies of each
//     node, one unit copy of each edge per unit of capacity with the cost's increment (convex
//     costs make the cheaper units fill first) and a two-node gadget per unit copy (its two
//     nodes matched together: the unit is unused).
// LEMON is called through bimdf's adapters (src/backend/min_cost_flow.hpp,
// perfect_matching.hpp), which scale costs to integers as LEMON needs and do nothing else;
// their time includes building LEMON's graph. bimdf's time is Solver::run() alone. Both
// objectives are recomputed in double from the returned flows/matchings.
#pragma once

#include <string>

namespace bimdf::bench {

// Runs every instance `repeats` times (median time) and returns the Markdown section
// (table and totals); throws std::runtime_error if the two objectives of an instance differ.
std::string benchmark_generality(int repeats);

}  // namespace bimdf::bench
