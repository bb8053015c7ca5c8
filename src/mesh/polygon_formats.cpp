// OFF and PLY readers for polygon meshes, and the reader that picks a format by extension
// (mesh.hpp). OBJ polygons are read by obj_reader.cpp. Every index is checked against the
// vertex count here, so later stages can trust the faces.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/mesh.hpp"
#include "io/text_scan.hpp"

namespace bimdf {
namespace {

// Splits text into lines, remembering each line's number; yields only lines with tokens.
struct LineReader {
  std::string_view text;
  size_t pos = 0;
  int line = 0;

  bool next(std::vector<std::string_view>& words) {
    while (pos < text.size()) {
      size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view l = text.substr(pos, end - pos);
      pos = end + 1;
      ++line;
      words = detail::line_words(l);
      if (!words.empty()) return true;
    }
    return false;
  }
};

// Checks one face's vertex ids (range, repeats) and appends it.
void add_face(PolygonMesh& mesh, std::vector<int> face, int line, const std::string& source,
              const std::string& where) {
  const int n = mesh.num_vertices();
  for (int v : face)
    if (v < 0 || v >= n)
      throw InputError(source, where,
                       "face " + std::to_string(mesh.num_faces()) + ": vertex index " +
                           std::to_string(v) + " is out of range (" + std::to_string(n) +
                           " vertices)");
  for (size_t a = 0; a < face.size(); ++a)
    for (size_t b = a + 1; b < face.size(); ++b)
      if (face[a] == face[b])
        throw InputError(source, where,
                         "face " + std::to_string(mesh.num_faces()) + " repeats vertex " +
                             std::to_string(face[a]));
  mesh.faces.push_back(std::move(face));
  mesh.face_line.push_back(line);
}

int64_t parse_count(std::string_view token, const std::string& source, const std::string& where,
                    const std::string& what) {
  int64_t n = 0;
  if (!detail::parse_int64(token, n) || n < 0 || n > INT32_MAX)
    throw InputError(source, where,
                     what + " " + detail::quote(token) + " is not a non-negative integer");
  return n;
}

// ---- PLY ----

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool ply_type(std::string_view name, PlyType& t) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [n, type] : names)
    if (name == n) {
      t = type;
      return true;
    }
  return false;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool list = false;
  PlyType count_type = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> properties;
};

// Reads values one by one from a PLY body, ascii or binary.
class PlyBody {
 public:
  PlyBody(std::string_view bytes, size_t start, int format, const std::string& source)
      : bytes_(bytes), pos_(start), format_(format), source_(source) {}

  // The next value of type t, as a double (every integer type fits exactly).
  double read(PlyType t, const std::string& element) {
    if (format_ == 0) {
      while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
      const size_t start = pos_;
      while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_])))
        ++pos_;
      double v = 0;
      if (start == pos_) fail(element, "the file ends early");
      if (!detail::parse_double(bytes_.substr(start, pos_ - start), v))
        fail(element, detail::quote(bytes_.substr(start, pos_ - start)) + " is not a number");
      return v;
    }
    const int size = ply_size(t);
    if (pos_ + size > bytes_.size()) fail(element, "the file ends early");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, size);
    pos_ += size;
    const bool file_little = format_ == 1;
    if (file_little != (std::endian::native == std::endian::little)) std::reverse(raw, raw + size);
    switch (t) {
      case PlyType::Int8:
        return static_cast<int8_t>(raw[0]);
      case PlyType::UInt8:
        return raw[0];
      case PlyType::Int16:
        return load<int16_t>(raw);
      case PlyType::UInt16:
        return load<uint16_t>(raw);
      case PlyType::Int32:
        return load<int32_t>(raw);
      case PlyType::UInt32:
        return load<uint32_t>(raw);
      case PlyType::Float32:
        return load<float>(raw);
      case PlyType::Float64:
        return load<double>(raw);
    }
    return 0;
  }

  [[noreturn]] void fail(const std::string& element, const std::string& what) const {
    throw InputError(source_, "", element + ": " + what);
  }

 private:
  template <typename T>
  static double load(const unsigned char* raw) {
    T v;
    std::memcpy(&v, raw, sizeof v);
    return static_cast<double>(v);
  }

  std::string_view bytes_;
  size_t pos_;
  int format_;  // 0 ascii, 1 binary little endian, 2 binary big endian
  const std::string& source_;
};

}  // namespace

PolygonMesh parse_off(std::string_view text, const std::string& source) {
  LineReader lines{text};
  std::vector<std::string_view> w;
  if (!lines.next(w)) throw InputError(source, "", "empty file, expected an OFF header");
  const std::string_view magic = w[0];
  if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF")
    throw InputError(source, std::to_string(lines.line),
                     "expected the OFF header, got " + detail::quote(magic));
  // The counts may follow the keyword on its line.
  std::vector<std::string_view> counts(w.begin() + 1, w.end());
  if (counts.empty() && !lines.next(counts))
    throw InputError(source, "", "the file ends before the vertex and face counts");
  const std::string where_counts = std::to_string(lines.line);
  if (counts.size() < 2)
    throw InputError(source, where_counts, "expected the vertex and face counts");
  const int64_t nv = parse_count(counts[0], source, where_counts, "vertex count");
  const int64_t nf = parse_count(counts[1], source, where_counts, "face count");
  PolygonMesh mesh;
  mesh.vertices.reserve(nv);
  for (int64_t i = 0; i < nv; ++i) {
    if (!lines.next(w))
      throw InputError(
          source, "",
          "the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    const std::string where = std::to_string(lines.line);
    if (w.size() < 3) throw InputError(source, where, "a vertex needs three coordinates");
    std::array<double, 3> p{};
    for (int k = 0; k < 3; ++k)
      if (!detail::parse_double(w[k], p[k]) || !std::isfinite(p[k]))
        throw InputError(source, where,
                         "vertex coordinate " + detail::quote(w[k]) + " is not a finite number");
    mesh.vertices.push_back(p);
  }
  for (int64_t i = 0; i < nf; ++i) {
    if (!lines.next(w))
      throw InputError(
          source, "",
          "the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    const std::string where = std::to_string(lines.line);
    const int64_t n = parse_count(w[0], source, where, "face size");
    if (n < 3 || static_cast<int64_t>(w.size()) < n + 1)
      throw InputError(source, where,
                       "face " + std::to_string(i) + " has " + std::to_string(n) +
                           " vertices, expected at least 3 indices after its size");
    std::vector<int> face(n);
    for (int64_t k = 0; k < n; ++k) {
      int64_t v = 0;
      if (!detail::parse_int64(w[k + 1], v) || v < INT32_MIN || v > INT32_MAX)
        throw InputError(source, where,
                         "vertex index " + detail::quote(w[k + 1]) + " is not an integer");
      face[k] = static_cast<int>(v);
    }
    add_face(mesh, std::move(face), lines.line, source, where);
  }
  return mesh;
}

PolygonMesh parse_ply(std::string_view bytes, const std::string& source) {
  LineReader lines{bytes};
  std::vector<std::string_view> w;
  if (!lines.next(w) || w[0] != "ply")
    throw InputError(source, "1", "expected the PLY magic word 'ply'");
  int format = -1;
  std::vector<PlyElement> elements;
  for (;;) {
    if (!lines.next(w)) throw InputError(source, "", "the header has no end_header line");
    const std::string where = std::to_string(lines.line);
    if (w[0] == "end_header") break;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() < 2) throw InputError(source, where, "the format line names no format");
      if (w[1] == "ascii")
        format = 0;
      else if (w[1] == "binary_little_endian")
        format = 1;
      else if (w[1] == "binary_big_endian")
        format = 2;
      else
        throw InputError(source, where, "unknown PLY format " + detail::quote(w[1]));
    } else if (w[0] == "element") {
      if (w.size() < 3) throw InputError(source, where, "expected 'element NAME COUNT'");
      elements.push_back(
          {std::string(w[1]), parse_count(w[2], source, where, "element count"), {}});
    } else if (w[0] == "property") {
      if (elements.empty()) throw InputError(source, where, "a property before any element");
      PlyProperty p;
      const bool list = w.size() >= 2 && w[1] == "list";
      if (list ? w.size() < 5 : w.size() < 3)
        throw InputError(source, where, "expected 'property TYPE NAME' or a list property");
      p.list = list;
      if ((list && (!ply_type(w[2], p.count_type) || !ply_type(w[3], p.type))) ||
          (!list && !ply_type(w[1], p.type)))
        throw InputError(source, where, "unknown property type");
      p.name = std::string(w[list ? 4 : 2]);
      elements.back().properties.push_back(p);
    } else {
      throw InputError(source, where, "unexpected header line " + detail::quote(w[0]));
    }
  }
  if (format < 0) throw InputError(source, "", "the header has no format line");
  // The body starts right after the end_header line's newline.
  PlyBody body(bytes, std::min(lines.pos, bytes.size()), format, source);
  PolygonMesh mesh;
  bool have_vertices = false, have_faces = false;
  for (const PlyElement& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, indices = -1;
    for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
      const std::string& n = e.properties[k].name;
      if (is_vertex && !e.properties[k].list && (n == "x" || n == "y" || n == "z"))
        xyz[n[0] - 'x'] = k;
      if (is_face && e.properties[k].list && (n == "vertex_indices" || n == "vertex_index"))
        indices = k;
    }
    if (is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      throw InputError(source, "", "element vertex: expected properties x, y and z");
    if (is_face && indices < 0)
      throw InputError(source, "", "element face: expected a list property vertex_indices");
    if (is_face && !have_vertices)
      throw InputError(source, "", "element face: faces come before the vertex element");
    have_vertices |= is_vertex;
    have_faces |= is_face;
    for (int64_t i = 0; i < e.count; ++i) {
      const std::string where = "element " + e.name + " " + std::to_string(i);
      std::array<double, 3> p{};
      std::vector<int> face;
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const PlyProperty& prop = e.properties[k];
        if (!prop.list) {
          const double v = body.read(prop.type, where);
          for (int c = 0; c < 3; ++c)
            if (k == xyz[c]) {
              if (!std::isfinite(v)) body.fail(where, "vertex coordinate is not finite");
              p[c] = v;
            }
          continue;
        }
        const double count = body.read(prop.count_type, where);
        if (!(count >= 0) || count > 1e6) body.fail(where, "bad list size");
        for (int64_t j = 0; j < static_cast<int64_t>(count); ++j) {
          const double v = body.read(prop.type, where);
          if (k == indices) {
            if (v != std::floor(v) || v < INT32_MIN || v > INT32_MAX)
              body.fail(where, "vertex index is not an integer");
            face.push_back(static_cast<int>(v));
          }
        }
      }
      if (is_vertex) mesh.vertices.push_back(p);
      if (is_face) {
        if (face.size() < 3)
          body.fail(where,
                    "face has " + std::to_string(face.size()) + " vertices, expected at least 3");
        add_face(mesh, std::move(face), 0, source, "");
      }
    }
  }
  if (!have_faces) throw InputError(source, "", "the file has no face element");
  return mesh;
}

PolygonMesh read_polygon_mesh(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                        ? ""
                        : path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != "obj" && ext != "off" && ext != "ply")
    throw InputError(path, "",
                     "unknown mesh format " +
                         (ext.empty() ? std::string("(no extension)") : detail::quote(ext)) +
                         ", expected .obj, .off or .ply");
  const std::string bytes = read_text_file(path);
  if (ext == "obj") return parse_obj_polygons(bytes, path);
  if (ext == "off") return parse_off(bytes, path);
  return parse_ply(bytes, path);
}

}  // namespace bimdf
