// Line-oriented OBJ reader for triangle meshes (mesh.hpp).
#include <charconv>
#include <cmath>
#include <string>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/mesh.hpp"
#include "io/text_scan.hpp"

namespace bimdf {
namespace {

// The whitespace-separated words of one line.
std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

}  // namespace

TriangleMesh parse_obj_triangles(std::string_view text, const std::string& source) {
  TriangleMesh mesh;
  int line_number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const std::string where = "line " + std::to_string(line_number);
    const std::vector<std::string_view> w = words_of(line);
    if (w.empty() || w[0].front() == '#') continue;
    if (w[0] == "v") {
      if (w.size() < 4)
        throw InputError(source, where, "a vertex needs three coordinates (v x y z)");
      std::array<double, 3> p{};
      for (int k = 0; k < 3; ++k)
        if (!detail::parse_double(w[k + 1], p[k]) || !std::isfinite(p[k]))
          throw InputError(
              source, where,
              "vertex coordinate " + detail::quote(w[k + 1]) + " is not a finite number");
      mesh.vertices.push_back(p);
    } else if (w[0] == "f") {
      if (w.size() != 4)
        throw InputError(source, where,
                         "face " + std::to_string(mesh.faces.size()) + " has " +
                             std::to_string(w.size() - 1) + " vertices, expected a triangle");
      std::array<int, 3> f{};
      for (int k = 0; k < 3; ++k) {
        const std::string_view ref = w[k + 1].substr(0, w[k + 1].find('/'));
        int64_t index = 0;
        if (!detail::parse_int64(ref, index) || index == 0)
          throw InputError(
              source, where,
              "vertex reference " + detail::quote(w[k + 1]) + " is not a non-zero integer");
        const int64_t n = mesh.num_vertices();
        const int64_t id = index > 0 ? index - 1 : n + index;
        if (id < 0 || id >= n)
          throw InputError(source, where,
                           "vertex reference " + std::to_string(index) + " is out of range (" +
                               std::to_string(n) + " vertices defined so far)");
        f[k] = static_cast<int>(id);
      }
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
        throw InputError(source, where,
                         "face " + std::to_string(mesh.faces.size()) + " repeats a vertex");
      mesh.faces.push_back(f);
    }
  }
  return mesh;
}

TriangleMesh read_obj_triangles(const std::string& path) {
  return parse_obj_triangles(read_text_file(path), path);
}

}  // namespace bimdf
