// The measured angular deviation of a requantized mesh's separatrices from the input's grid
// (tmesh/separatrix_deviation.hpp): zero where nothing moved, and on planar meshes of unit
// squares — whose grid coordinates are the plane's — equal to the angle an independent reading
// of the plane gives.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "bimdf/metrics.hpp"
#include "bimdf/tmesh/requantize.hpp"
#include "bimdf/tmesh/separatrix_deviation.hpp"
#include "tmesh_fixtures.hpp"

namespace bimdf::tmesh {
namespace {

const TMesh& collapsed_tmesh(const RequantizeResult& r) {
  return r.half_arc ? r.half_arc->inflated.tmesh : r.traced.tmesh;
}

// Output vertex v's singular input vertex (as the measure picks it: the first in the
// collapse's list whose valence is irregular), by an independent count of quads per vertex.
int singular_input_vertex(const QuadMesh& input, const RequantizeResult& r, int v) {
  std::vector<int> quads(input.num_vertices(), 0);
  std::vector<std::set<int>> neighbours(input.num_vertices());
  for (const auto& q : input.quads)
    for (int k = 0; k < 4; ++k) {
      ++quads[q[k]];
      neighbours[q[k]].insert(q[(k + 1) % 4]);
      neighbours[q[k]].insert(q[(k + 3) % 4]);
    }
  for (int t : r.collapsed.origin[v].tmesh_vertices) {
    const int m = collapsed_tmesh(r).vertex_mesh_vertex[t];
    const bool border = int(neighbours[m].size()) != quads[m];
    if (border ? neighbours[m].size() != 3 : quads[m] != 4) return m;
  }
  return -1;
}

TEST(TMeshDeviation, NothingMovedMeansNoDeviation) {
  const QuadMesh cube = test::subdivided_cube(3);  // 8 × 8 per face, corners valence 3
  RequantizeOptions o;
  o.smoothing.iterations = 0;
  const RequantizeResult r = requantize(cube, o, "cube");
  ASSERT_EQ(r.collapsed.mesh.quads.size(), cube.quads.size());
  const SeparatrixDeviation d = measure_separatrix_deviation(cube, r, 20);
  // Each of the 12 cube edges is one separatrix, from one corner to another.
  EXPECT_EQ(d.measured, 12);
  EXPECT_EQ(d.unmeasured, 0);
  EXPECT_EQ(d.max_deg, 0);
  EXPECT_EQ(d.over_bound, 0);
  for (const auto& s : d.separatrices) EXPECT_FALSE(s.to_border);
}

// The same on random meshes (singular vertices of valence 3, 5, 6 and more, border corners): the
// identity quantization measures every separatrix, each at 0°.
TEST(TMeshDeviation, NothingMovedOnRandomMeshes) {
  for (uint64_t seed = 0; seed < 12; ++seed) {
    std::string description;
    const QuadMesh mesh = test::random_quad_mesh(seed, &description);
    RequantizeOptions o;
    o.smoothing.iterations = 0;
    const RequantizeResult r = requantize(mesh, o, "random");
    ASSERT_EQ(r.quantization.objective, 0) << description;  // every arc at its input length
    ASSERT_EQ(r.collapsed.mesh.num_quads(), mesh.num_quads()) << description;
    const SeparatrixDeviation& d = r.deviation;
    EXPECT_GT(d.measured, 0) << description;
    EXPECT_EQ(d.unmeasured, 0) << description;
    EXPECT_EQ(d.max_deg, 0) << description;
    EXPECT_EQ(d.max_to_border_deg, 0) << description;
  }
}

// The staircase's reflex corners A = (3, 3) and B = (7, 4) lie at offset (4, 1): 14.04°. A
// coarse layout at 45° may join them by one straight line (its traces allow it from 14.04° on);
// every separatrix between singular vertices is compared with the plane's own displacement
// between the input vertices at its ends.
TEST(TMeshDeviation, PlanarStaircaseMatchesThePlane) {
  const QuadMesh mesh = test::thin_strip_mesh();
  for (const std::string mode : {"off", "bounded"})
    for (double angle : {10.0, 45.0}) {
      RequantizeOptions o;
      o.quantize.coarse = o.quantize.coarse_uniform = true;
      o.trace.max_angle_deg = angle;
      o.trace.sharp_angle_deg = 180;
      set_half_arc_mode(o, mode);
      const RequantizeResult r = requantize(mesh, o, "staircase");
      const SeparatrixDeviation d = measure_separatrix_deviation(mesh, r, angle);
      const std::string where = mode + " at " + std::to_string(angle);
      EXPECT_EQ(d.unmeasured, 0) << where;
      ASSERT_GT(d.measured, 0) << where;
      double max_deg = 0;
      int over = 0;
      for (const auto& s : d.separatrices) {
        if (s.to_border) continue;
        const int a = singular_input_vertex(mesh, r, s.from);
        const int b = singular_input_vertex(mesh, r, s.to);
        ASSERT_GE(a, 0) << where;
        ASSERT_GE(b, 0) << where;
        const double dx = mesh.vertices[b][0] - mesh.vertices[a][0];
        const double dy = mesh.vertices[b][1] - mesh.vertices[a][1];
        // Against the nearer axis (the measure's own axis when the line turns by less than 45°).
        const double deg =
            std::atan2(std::min(std::abs(dx), std::abs(dy)), std::max(std::abs(dx), std::abs(dy))) *
            180 / std::numbers::pi;
        EXPECT_NEAR(s.deg, deg, 1e-9) << where << ": " << s.from << " → " << s.to;
        max_deg = std::max(max_deg, s.deg);
        over += s.deg > angle + 1e-9;
      }
      EXPECT_EQ(d.max_deg, max_deg) << where;
      EXPECT_EQ(d.over_bound, over) << where;
      if (angle == 45) {
        EXPECT_GT(d.max_deg, 14) << where;  // B slid onto A's line
      }
      if (angle == 10) {
        EXPECT_EQ(d.max_deg, 0) << where;
      }
    }
}

TEST(TMeshDeviation, RejectsAMeshThatIsNotTheCollapse) {
  const QuadMesh cube = test::subdivided_cube(2);
  RequantizeOptions o;
  RequantizeResult r = requantize(cube, o, "cube");
  r.collapsed.quad_grid_uv.pop_back();
  EXPECT_THROW(measure_separatrix_deviation(cube, r), std::invalid_argument);
}

}  // namespace
}  // namespace bimdf::tmesh
