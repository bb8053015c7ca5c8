// The double cover of a Bi-MCF (paper §3.6, after Hochbaum 2004): each node v becomes v⁺ and v⁻
// (v⁻ with negated signs), and each bidirected arc becomes two directed arcs, so that an
// ordinary min-cost flow solver applies. For an arc with ends (u, hu), (v, hv):
//   A0: (hu ? u⁻ : u⁺) → (hv ? v⁺ : v⁻)        A1: (hv ? v⁻ : v⁺) → (hu ? u⁺ : u⁻)
// (a head–tail arc u→v gives u⁺→v⁺ and v⁻→u⁻; head–head gives u⁻→v⁺ and v⁻→u⁺). For any
// directed flow, netin(v⁺) − netin(v⁻) equals the bidirected balance of y = f(A0) + f(A1) at v.
// A ±2 loop gets A0 only (one unit on u⁻→u⁺ moves the balance by 2), with the loop's capacity
// (twice that in the relaxation, whose directed flow is 2y — the reference implementation's
// lower bound misses this, ../shared/reference/libsatsuma.md §2.11).
//
// Kinds:
//   Asymmetric  supplies −b/2 at v⁺, +b/2 at v⁻ (b must be even); capacity c split as ⌊c/2⌋ on
//               A0 and ⌈c/2⌉ on A1 (§3.6.2, "asymmetric double cover"): bounds are kept
//               exactly in sum, and y = f(A0) + f(A1) is an integral Bi-MCF flow.
//   AsymmetricSwapped  the same with the odd unit on A0 — a different restriction of the
//               feasible region, tried when the first is infeasible.
//   Symmetric   odd capacities rounded down to even, c/2 on each copy.
//   Relaxation  supplies −b, +b (any parity) and capacity c on both copies: the directed flow
//               is 2y for a half-integral y, and this MCF is exactly the LP relaxation of the
//               Bi-MCF. Its infeasibility proves the Bi-MCF (and any integer problem it was
//               linearized from) infeasible.
// Arcs of capacity 0 are still created so that arc ids are predictable; their flow is 0.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "reduce/bimcf.hpp"
#include "graph/directed_mcf.hpp"

namespace bimdf::detail {

enum class DoubleCoverKind { Asymmetric, AsymmetricSwapped, Symmetric, Relaxation };

struct DoubleCover {
  DirectedMcf mcf;
  std::vector<int> arc_of;  // directed arc → Bi-MCF arc
  DoubleCoverKind kind = DoubleCoverKind::Asymmetric;

  // Σ of both copies per Bi-MCF arc: y for the half kinds, 2y for Relaxation.
  std::vector<int64_t> lift(std::span<const int64_t> directed_flow, int num_bimcf_arcs) const;
};

// Throws std::invalid_argument if a half kind is asked for with an odd demand.
DoubleCover build_double_cover(const BiMcf& bimcf, DoubleCoverKind kind);

}  // namespace bimdf::detail
