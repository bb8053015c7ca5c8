// Line-oriented OBJ reading and writing for triangle and quad meshes (mesh.hpp).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/mesh.hpp"
#include "io/text_scan.hpp"

namespace bimdf {
namespace {

// The patch a `g` statement names: N for `g patch_N`, else −1.
int patch_of_group(const std::vector<std::string_view>& words) {
  int64_t id = 0;
  if (words.size() > 1 && words[1].substr(0, 6) == "patch_" &&
      detail::parse_int64(words[1].substr(6), id) && id >= 0 && id <= INT32_MAX)
    return static_cast<int>(id);
  return -1;
}

template <typename Face>
constexpr bool kAnyPolygon = std::is_same_v<Face, std::vector<int>>;

// The vertices and faces of OBJ text; every face must have as many vertices as Face holds, or
// at least three for a polygon (std::vector<int>). With `face_patch`, each face's patch
// (patch_of_group of the last `g`) is appended to it; with `face_line`, its line number.
template <typename Face>
void parse_obj(std::string_view text, const std::string& source,
               std::vector<std::array<double, 3>>& vertices, std::vector<Face>& faces,
               std::vector<int>* face_patch, std::vector<int>* face_line = nullptr) {
  std::string expected = "at least 3";
  if constexpr (!kAnyPolygon<Face>)
    expected = std::tuple_size_v<Face> == 3 ? "a triangle" : "a quad";
  int line_number = 0, patch = -1;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const std::string where = std::to_string(line_number);
    const std::vector<std::string_view> w = detail::line_words(line);
    if (w.empty()) continue;
    if (w[0] == "g") {
      patch = patch_of_group(w);
    } else if (w[0] == "v") {
      if (w.size() < 4)
        throw InputError(source, where, "a vertex needs three coordinates (v x y z)");
      std::array<double, 3> p{};
      for (int k = 0; k < 3; ++k)
        if (!detail::parse_double(w[k + 1], p[k]) || !std::isfinite(p[k]))
          throw InputError(
              source, where,
              "vertex coordinate " + detail::quote(w[k + 1]) + " is not a finite number");
      vertices.push_back(p);
    } else if (w[0] == "f") {
      Face f{};
      if constexpr (kAnyPolygon<Face>) f.resize(w.size() < 4 ? 0 : w.size() - 1);
      const int arity = static_cast<int>(f.size());
      if (arity < 3 || static_cast<int>(w.size()) != arity + 1)
        throw InputError(source, where,
                         "face " + std::to_string(faces.size()) + " has " +
                             std::to_string(w.size() - 1) + " vertices, expected " + expected);
      for (int k = 0; k < arity; ++k) {
        const std::string_view ref = w[k + 1].substr(0, w[k + 1].find('/'));
        int64_t index = 0;
        if (!detail::parse_int64(ref, index) || index == 0)
          throw InputError(
              source, where,
              "vertex reference " + detail::quote(w[k + 1]) + " is not a non-zero integer");
        const int64_t n = static_cast<int64_t>(vertices.size());
        const int64_t id = index > 0 ? index - 1 : n + index;
        if (id < 0 || id >= n)
          throw InputError(source, where,
                           "vertex reference " + std::to_string(index) + " is out of range (" +
                               std::to_string(n) + " vertices defined so far)");
        f[k] = static_cast<int>(id);
      }
      for (int a = 0; a < arity; ++a)
        for (int b = a + 1; b < arity; ++b)
          if (f[a] == f[b])
            throw InputError(source, where,
                             "face " + std::to_string(faces.size()) + " repeats a vertex");
      faces.push_back(std::move(f));
      if (face_patch) face_patch->push_back(patch);
      if (face_line) face_line->push_back(line_number);
    }
  }
}

}  // namespace

TriangleMesh parse_obj_triangles(std::string_view text, const std::string& source) {
  TriangleMesh mesh;
  parse_obj(text, source, mesh.vertices, mesh.faces, nullptr);
  return mesh;
}

QuadMesh parse_obj_quads(std::string_view text, const std::string& source) {
  QuadMesh mesh;
  parse_obj(text, source, mesh.vertices, mesh.quads, &mesh.quad_patch);
  return mesh;
}

PolygonMesh parse_obj_polygons(std::string_view text, const std::string& source) {
  PolygonMesh mesh;
  parse_obj(text, source, mesh.vertices, mesh.faces, nullptr, &mesh.face_line);
  return mesh;
}

QuadMesh read_obj_quads(const std::string& path) {
  return parse_obj_quads(read_text_file(path), path);
}

void write_obj(std::ostream& out, const QuadMesh& mesh, const std::string& comment) {
  if (!comment.empty()) out << "# " << comment << "\n";
  // Shortest digits that read back to the same double: the file measures like the mesh.
  out.precision(std::numeric_limits<double>::max_digits10);
  for (const auto& v : mesh.vertices) out << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  int patch = -2;
  for (size_t f = 0; f < mesh.quads.size(); ++f) {
    const int p = f < mesh.quad_patch.size() ? mesh.quad_patch[f] : -1;
    if (p != patch) {
      out << (p >= 0 ? "g patch_" + std::to_string(p) : std::string("g default")) << '\n';
      patch = p;
    }
    const auto& q = mesh.quads[f];
    out << "f " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << ' ' << q[3] + 1 << '\n';
  }
}

TriangleMesh read_obj_triangles(const std::string& path) {
  return parse_obj_triangles(read_text_file(path), path);
}

}  // namespace bimdf
