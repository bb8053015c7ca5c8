// Building blocks of quad patterns (quant/pattern.hpp): polygons whose boundary vertices are
// already numbered, their regular patterns, and the check that a set of quads is a disk.
#pragma once

#include <array>
#include <vector>

namespace bimdf::quant::detail {

// A polygon to be filled with quads: `ring` holds its boundary vertex ids counter-clockwise,
// `corners` the ring positions of its corners in increasing order; side j runs from corner j
// to corner j+1 (cyclically).
struct PatchPolygon {
  std::vector<int> ring;
  std::vector<int> corners;

  int size() const { return static_cast<int>(ring.size()); }
  std::vector<int> side_lengths() const;
};

// Quads under construction; `next_vertex` is the id the next new interior vertex gets.
struct QuadSoup {
  int next_vertex = 0;
  std::vector<std::array<int, 4>> quads;
};

// Appends the regular pattern of `polygon` (see regular_strip_counts in quant/pattern.hpp)
// to `soup`, creating its interior vertices; returns false, leaving `soup` unchanged, when the
// side vector is not regular.
bool add_regular_pattern(const PatchPolygon& polygon, QuadSoup& soup);

// Whether `quads` form a topological disk whose boundary is `ring` walked counter-clockwise:
// every quad has four distinct vertices, every interior edge has two quads on opposite sides,
// every ring edge has one quad on its left and no other edge is on the boundary, every vertex
// has one fan of quads, and V − E + F = 1.
bool is_disk_with_boundary(const std::vector<std::array<int, 4>>& quads, int num_vertices,
                           const std::vector<int>& ring);

}  // namespace bimdf::quant::detail
