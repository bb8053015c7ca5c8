// Where collapse_and_tessellate (tmesh/collapse.hpp) puts the points of zipped two-gons — the
// re-embedding of a half-arc quantization (paper Appendix A, steps 3–4) done in the patches'
// own parameter domains, internal to src/tmesh.
//
// Along a two-gon both sides run over one line of the input (the path's chain, N input edges).
// Each side spreads its quantized positions 0..n over that chain by its own arcs (position k of
// an arc of length x over m input edges at m·k/x of it); where T-junctions traded places the two
// sides disagree. Every zipped point goes to the mean of the two sides' parameters, φ(k), on
// the line; a patch along the line then sees its side there shifted by δ(k) = φ(k) − its own
// side's parameter, and its interior grid points shift by the transfinite blend of those
// shifts (sides off the line shifted linearly between their corners), so that its rows follow
// the moved T-junctions instead of shearing against them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bimdf/mesh.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/tmesh/tmesh.hpp"

namespace bimdf::tmesh::detail {

class ZipPlacement {
 public:
  // `arc_length` per arc of `tmesh`; `zips` as collapse_and_tessellate takes them, each of
  // arcs with chains (others are ignored).
  ZipPlacement(const TMesh& tmesh, const std::vector<int64_t>& arc_length,
               const std::vector<Zip>& zips);

  // Whether arc a lies along a zip.
  bool on_zip(int a) const { return arc_zip_[a] >= 0; }

  // Position k (0..length) of arc a (counted from its tail, half-arc 2a) of an arc along a
  // zip: the point on the input line where it goes.
  std::array<double, 3> arc_point(const QuadMesh& mesh, int a, int64_t k) const;

  // Whether position k of arc a (along a zip) lies strictly inside the line, not at an end.
  bool inside(int a, int64_t k) const;

  // The shift, in input edges along the walking direction of half-arc h (an arc along a zip),
  // of its point at offset q (0..length) from h's tail; 0 for an arc on no zip.
  double shift(int h, int64_t q) const;

 private:
  struct Line {
    std::vector<int> chain;                        // mesh vertices, from the path's tail
    std::array<std::vector<double>, 2> parameter;  // per side and position: input edges
  };
  const TMesh& tmesh_;
  const std::vector<int64_t>& length_;
  std::vector<Line> lines_;
  std::vector<int> arc_zip_;           // per arc: its zip, or −1
  std::vector<int> arc_side_;          // per arc along a zip: 0 or 1
  std::vector<int64_t> arc_position_;  // per arc along a zip: its start's position on the line
  std::vector<char> arc_forward_;      // per arc along a zip: half-arc 2a runs tail → head

  double mean_parameter(int zip, int64_t position) const;
};

}  // namespace bimdf::tmesh::detail
