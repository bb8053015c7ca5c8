// Pictures of quad meshes without a display or GPU: an orthographic software rasterizer with a
// depth buffer, diffuse shading, one colour per patch, drawn edges and marked singularities,
// written as PNG.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf {

struct RenderOptions {
  int width = 1200, height = 900;  // pixels
  // Direction from the camera towards the mesh; all zero: automatic (looking along the mesh's
  // thinnest principal axis, tilted for depth, from the side most faces face).
  std::array<double, 3> view{0, 0, 0};
  bool draw_edges = true;
  bool colour_patches = true;      // by QuadMesh::quad_patch; else one colour
  bool mark_singularities = true;  // interior valence 3 blue, 5 red, other green
  int supersampling = 2;           // samples per pixel along each axis (antialiasing)
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major from the top, 3 bytes per pixel
};

Image render_quad_mesh(const QuadMesh& mesh, const RenderOptions& options = {});

// The image as a PNG file's bytes (8-bit RGB, zlib-compressed).
std::string encode_png(const Image& image);

}  // namespace bimdf
