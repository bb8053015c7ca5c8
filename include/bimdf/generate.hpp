// Deterministic instance generators for benchmarks and stress tests (`bimdf generate`). The same
// family, size and seed give the same problem on every run: randomness comes from
// std::mt19937_64 (specified bit for bit by the standard) through bimdf's own integer and real
// mappings, never through the implementation-defined standard distributions; only normally
// distributed targets also depend on the C library's log and cos.
//
//   random     a random bidirected network with every edge kind (head–tail, head–head,
//              tail–tail, ±2 loops, outer edges), bounds (finite, infinite, fixed, negative),
//              every cost kind, and demands planted from a random flow, so it is feasible.
//   quadwild   a synthetic QuadWild-like quantization model (../shared/reference/
//              quadwild_modeling.md §3): charts of valence 3–6 whose sides are nodes, with side
//              self-loops, neighbour and opposite emergency edges, strip edges, singularity-on-
//              boundary edges, quadratic subside edges between charts, a boundary node, and
//              alignment gadgets (half nodes, virtual subsides, unaligners). The chart adjacency
//              is random rather than planar, but every gadget and weight follows the reference
//              model, so sizes and structure match real instances.
// `size` is the approximate number of edges; the result may differ by a few percent.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/problem.hpp"

namespace bimdf {

// "random", "quadwild".
std::vector<std::string> generator_family_names();

// Throws std::invalid_argument for an unknown family name or size < 1.
Problem generate_problem(const std::string& family, int64_t size, uint64_t seed);

}  // namespace bimdf
