// Triangle and quad meshes as plain arrays, and reading and writing them as Wavefront OBJ.
//
// The quantizer's input surface (a QuadWild layout's `NAME.obj`) is a triangle mesh whose face
// order and vertex order are meaningful: the layout's companion files refer to faces and
// vertices by 0-based position. The reader therefore keeps both orders exactly as written.
#pragma once

#include <array>
#include <iosfwd>
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

// A polygon mesh as a file holds it (faces of three or more vertices), before it is checked or
// triangulated: the input of the standalone remesher (bimdf/layout/surface.hpp).
// `face_line[f]` is the line face f was read from in a text file (1-based), 0 where a binary
// file has no lines.
struct PolygonMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_line;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_faces() const { return static_cast<int>(faces.size()); }
};

// Parses OBJ text as parse_obj_triangles does, but accepts faces of any size ≥ 3.
PolygonMesh parse_obj_polygons(std::string_view text, const std::string& source);

// Parses OFF text (`OFF`, counts, vertices, faces `n i0 … in-1`; optional colours after a
// face's indices are ignored). Throws InputError naming the line on malformed input.
PolygonMesh parse_off(std::string_view text, const std::string& source);

// Parses PLY (ascii, binary_little_endian or binary_big_endian): the `vertex` element's x, y, z
// and the `face` element's `vertex_indices` (or `vertex_index`) list; other properties and
// elements are skipped. Throws InputError naming the header line or the element on bad input.
PolygonMesh parse_ply(std::string_view bytes, const std::string& source);

// Reads a polygon mesh, choosing the format by the file's extension: .obj, .off or .ply (any
// case). Throws InputError for another extension or a file that cannot be read.
PolygonMesh read_polygon_mesh(const std::string& path);

// An all-quad mesh: what tessellation produces. `quad_patch[f]` is the chart quad f was made
// for (−1 when unknown); written to OBJ as groups `g patch_N`.
struct QuadMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 4>> quads;  // counter-clockwise seen from outside
  std::vector<int> quad_patch;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_quads() const { return static_cast<int>(quads.size()); }
};

// Parses OBJ text whose faces are all quads, as parse_obj_triangles does triangles; a group
// statement `g patch_N` assigns the faces after it to patch N (other groups: −1).
QuadMesh parse_obj_quads(std::string_view text, const std::string& source);
QuadMesh read_obj_quads(const std::string& path);

// Writes `v` and `f` lines (1-based), a `g patch_N` line before each run of quads of patch N,
// and `comment` as a first `#` line if not empty.
void write_obj(std::ostream& out, const QuadMesh& mesh, const std::string& comment = "");

}  // namespace bimdf
