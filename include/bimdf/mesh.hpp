// Triangle meshes as plain arrays, and reading them from Wavefront OBJ.
//
// The quantizer's input surface (a QuadWild layout's `NAME.obj`) is a triangle mesh whose face
// order and vertex order are meaningful: the layout's companion files refer to faces and
// vertices by 0-based position. The reader therefore keeps both orders exactly as written.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace bimdf {

struct TriangleMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> faces;  // vertex ids, counter-clockwise seen from outside

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_faces() const { return static_cast<int>(faces.size()); }
};

// Parses OBJ text: `v x y z` and `f a b c` lines (indices 1-based or negative, relative to the
// end; `a/t/n` forms accepted, texture and normal references ignored). Other statements (`vn`,
// `vt`, `o`, `g`, `s`, `usemtl`, `mtllib`, comments) are skipped. Throws InputError naming the
// line for a malformed number, an index out of range, a face that is not a triangle, or a
// face that repeats a vertex. `source` names the text in messages.
TriangleMesh parse_obj_triangles(std::string_view text, const std::string& source);

// Reads an OBJ file (see parse_obj_triangles); throws InputError if it cannot be read.
TriangleMesh read_obj_triangles(const std::string& path);

}  // namespace bimdf
