// The standalone remesher's input (issue 51): a user's polygon mesh made into a clean triangle
// mesh that the layout stages (cross field, tracing, patches) can walk, and a summary of what
// was found. QuadWild's own first stage remeshes its input; this one only repairs what is
// unambiguous and refuses the rest with a message naming the face, edge or vertex.
#pragma once

#include <string>
#include <vector>

#include "bimdf/mesh.hpp"

namespace bimdf::layout {

// What prepare_surface changed to make the input usable; all zero for a clean triangle mesh.
struct SurfaceRepairs {
  int triangulated_polygons = 0;  // faces of four or more vertices split into triangles
  int flipped_faces = 0;          // re-oriented to agree with their neighbours
  int unreferenced_vertices = 0;  // dropped: no face uses them
  int split_vertices = 0;         // extra copies made of vertices whose faces form several fans
};

// A manifold, coherently oriented triangle mesh without unused vertices, and where each of its
// triangles and vertices came from in the input (for messages in the input's numbering).
struct Surface {
  TriangleMesh mesh;
  std::vector<int> input_face;    // per triangle: the input face it is part of
  std::vector<int> input_vertex;  // per vertex: the input vertex it copies
  SurfaceRepairs repairs;
};

// Triangulates polygons (ear clipping in the polygon's best-fit plane), drops unreferenced
// vertices, orients every connected piece coherently and splits non-manifold vertices (a vertex
// whose faces form several fans gets one copy per fan). Throws InputError, with `source` as the
// file and the input's face and vertex numbers (and the face's line where known), for what it
// cannot repair: no faces; an edge shared by three or more faces; a piece that is not
// orientable; a face of zero area (collinear or coincident vertices) or a polygon that cannot
// be triangulated without one.
Surface prepare_surface(const PolygonMesh& input, const std::string& source);

// Reads a mesh file (OBJ, OFF or PLY; read_polygon_mesh) and prepares it.
Surface read_surface(const std::string& path);

// Counts that describe a surface, for `--info` and reports.
struct SurfaceInfo {
  int vertices = 0, faces = 0, edges = 0;
  int components = 0;
  int border_loops = 0;
  int euler_characteristic = 0;  // V − E + F over the whole mesh
  // Per component: its genus (handles), from its Euler characteristic and border loops.
  std::vector<int> component_genus;
  std::vector<int> component_border_loops;
  double average_edge_length = 0;  // over the undirected edges
  double bounding_box_diagonal = 0;
  double area = 0;
};

// Describes a mesh that prepare_surface returned (manifold and oriented).
SurfaceInfo describe_surface(const TriangleMesh& mesh);

}  // namespace bimdf::layout
