// What the passes that move vertices after smoothing (quality_polish.hpp, tangled_regions.hpp)
// see of the quad mesh and of the surface it lies on.
#pragma once

#include <functional>
#include <vector>

#include "bimdf/mesh.hpp"
#include "mesh/vec3.hpp"

namespace bimdf::detail {

struct MeshOnSurface {
  QuadMesh& mesh;                                     // positions are updated in place
  const std::vector<std::vector<int>>& vertex_quads;  // per vertex, the quads containing it
  const std::vector<std::vector<int>>& neighbours;    // per vertex, its edge neighbours
  std::function<Vec3(int, const Vec3&)> project;      // a point back onto the vertex's surface
};

}  // namespace bimdf::detail
