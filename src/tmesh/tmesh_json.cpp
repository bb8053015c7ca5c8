// The T-mesh JSON form (docs/formats.md, "T-mesh (JSON)"):
//   {"format": "bimdf-tmesh", "version": 1,
//    "vertices": [[x, y, z], …], "vertex_mesh_vertex": [m, …],
//    "arcs": [{"ends": [c, d], "target": t, "chain": [m, …], "feature": true}, …],
//    "patches": [{"sides": [[h, …], [h, …], [h, …], [h, …]],
//                 "grid": {"width": w, "height": h, "vertices": [m, …]}}, …],
//    "nonzero_paths": [[h, …], …]}
// The file mirrors TMesh field by field, so that a T-mesh from another pipeline (QGP/ATQ style)
// needs no translation and a round trip is exact. Reading checks the shape of every value here
// (types, required keys, no unknown keys — a typo must not silently drop a field) and then the
// model's rules through find_tmesh_issue, whose paths point into this same layout; every error
// names the JSON path of the offending value.
#include <climits>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/tmesh/tmesh.hpp"
#include "io/json_document.hpp"

namespace bimdf::tmesh {
namespace {

using nlohmann::json;

class TMeshJsonReader {
 public:
  explicit TMeshJsonReader(const std::string& source) : source_(source) {}

  TMesh read(const std::string& text) {
    const json root = parse_document(text);
    if (!root.is_object())
      fail("", "expected a JSON object with \"vertices\", \"arcs\" and \"patches\"");
    check_keys(root, "",
               {"format", "version", "comment", "vertices", "vertex_mesh_vertex", "arcs", "patches",
                "nonzero_paths"});
    // Required, unlike in the problem format: a T-mesh file is easily confused with the other
    // JSON files bimdf reads and writes (problems, quantizations, reports).
    const json& format = member(root, "", "format", "the format name \"bimdf-tmesh\"");
    if (format != "bimdf-tmesh") fail("/format", "expected \"bimdf-tmesh\", got " + format.dump());
    const json& version = member(root, "", "version", "the format version 1");
    if (version != 1) fail("/version", "unsupported version " + version.dump() + ", expected 1");
    TMesh t;
    read_vertices(root, t);
    read_arcs(root, t);
    read_patches(root, t);
    if (root.contains("nonzero_paths"))
      t.nonzero_paths = int_arrays(root["nonzero_paths"], "/nonzero_paths",
                                   "an array of non-zero paths (arrays of half-arc ids)",
                                   "a non-zero path (an array of half-arc ids)", "a half-arc id");
    if (const auto issue = find_tmesh_issue(t)) fail(issue->path, issue->message);
    return t;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(source_, path.empty() ? "/" : path, what);
  }

  json parse_document(const std::string& text) const {
    return detail::parse_json_document(text, source_);
  }

  void check_keys(const json& obj, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* k : allowed) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(path + "/" + it.key(),
             "unknown key \"" + it.key() + "\" (expected one of: " + list + ")");
      }
    }
  }

  const json& member(const json& obj, const std::string& path, const char* key,
                     const std::string& what) const {
    if (!obj.contains(key)) fail(path + "/" + key, "missing: expected " + what);
    return obj[key];
  }

  const json& array(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_array()) fail(path, "expected " + what + ", got " + v.dump());
    return v;
  }

  // Ids and sizes are `int` in the model; anything outside int's range is reported here rather
  // than wrapped into a valid-looking id.
  int get_int(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_number_integer()) fail(path, "expected " + what + " (an integer), got " + v.dump());
    if (v.is_number_unsigned() ? v.get<uint64_t>() > static_cast<uint64_t>(INT_MAX)
                               : v.get<int64_t>() < INT_MIN || v.get<int64_t>() > INT_MAX)
      fail(path, "expected " + what + ", got " + v.dump() + " (out of range)");
    return v.get<int>();
  }

  double get_double(const json& v, const std::string& path, const std::string& what) const {
    if (!v.is_number()) fail(path, "expected " + what + " (a number), got " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(path, "expected " + what + " (a finite number), got " + v.dump());
    return x;
  }

  std::vector<int> ints(const json& v, const std::string& path, const std::string& what,
                        const std::string& item) const {
    std::vector<int> out;
    for (size_t i = 0; i < array(v, path, what).size(); ++i)
      out.push_back(get_int(v[i], path + "/" + std::to_string(i), item));
    return out;
  }

  // `what`: the whole ("an array of non-zero paths"), `element`: one entry ("a non-zero path
  // (an array of half-arc ids)"), `item`: one id ("a half-arc id").
  std::vector<std::vector<int>> int_arrays(const json& v, const std::string& path,
                                           const std::string& what, const std::string& element,
                                           const std::string& item) const {
    std::vector<std::vector<int>> out;
    for (size_t i = 0; i < array(v, path, what).size(); ++i)
      out.push_back(ints(v[i], path + "/" + std::to_string(i), element, item));
    return out;
  }

  void read_vertices(const json& root, TMesh& t) const {
    const json& vs = array(member(root, "", "vertices", "an array of vertex positions [x, y, z]"),
                           "/vertices", "an array of vertex positions [x, y, z]");
    for (size_t v = 0; v < vs.size(); ++v) {
      const std::string path = "/vertices/" + std::to_string(v);
      if (!vs[v].is_array() || vs[v].size() != 3)
        fail(path, "expected a position [x, y, z], got " + vs[v].dump());
      std::array<double, 3> x{};
      for (int c = 0; c < 3; ++c)
        x[c] = get_double(vs[v][c], path + "/" + std::to_string(c), "a coordinate");
      t.vertices.push_back(x);
    }
    if (root.contains("vertex_mesh_vertex"))
      t.vertex_mesh_vertex =
          ints(root["vertex_mesh_vertex"], "/vertex_mesh_vertex",
               "an array of mesh vertex ids, one per vertex", "a mesh vertex id (-1: none)");
  }

  void read_arcs(const json& root, TMesh& t) const {
    const json& arcs = array(member(root, "", "arcs", "an array of arcs"), "/arcs",
                             "an array of arcs like {\"ends\": [0, 1], \"target\": 2.5}");
    // "chain" and "feature" are per arc but all-or-none, like the model's arrays: the first arc
    // decides, and a later arc that disagrees is an error rather than a silent default.
    bool chains = false, features = false;
    for (size_t a = 0; a < arcs.size(); ++a) {
      const std::string path = "/arcs/" + std::to_string(a);
      const json& arc = arcs[a];
      if (!arc.is_object())
        fail(path, "expected an arc like {\"ends\": [0, 1], \"target\": 2.5}, got " + arc.dump());
      check_keys(arc, path, {"ends", "target", "chain", "feature"});
      const json& ends = member(arc, path, "ends", "the arc's two vertices [tail, head]");
      if (!ends.is_array() || ends.size() != 2)
        fail(path + "/ends", "expected the arc's two vertices [tail, head], got " + ends.dump());
      t.arc_ends.push_back({get_int(ends[0], path + "/ends/0", "a vertex id"),
                            get_int(ends[1], path + "/ends/1", "a vertex id")});
      t.arc_target.push_back(get_double(member(arc, path, "target", "the arc's target length"),
                                        path + "/target", "a target length"));
      if (a == 0) chains = arc.contains("chain"), features = arc.contains("feature");
      if (arc.contains("chain") != chains)
        fail(path + "/chain", chains ? "missing: arc 0 has a chain, so every arc needs one"
                                     : "unexpected: arc 0 has no chain, so no arc may have one");
      if (arc.contains("feature") != features)
        fail(path + "/feature",
             features ? "missing: arc 0 has a feature flag, so every arc needs one"
                      : "unexpected: arc 0 has no feature flag, so no arc may have one");
      if (chains)
        t.arc_chain.push_back(ints(arc["chain"], path + "/chain",
                                   "the mesh vertices the arc runs through (an array of ids)",
                                   "a mesh vertex id"));
      if (features) {
        if (!arc["feature"].is_boolean())
          fail(path + "/feature", "expected true or false, got " + arc["feature"].dump());
        t.arc_feature.push_back(arc["feature"].get<bool>() ? 1 : 0);
      }
    }
  }

  void read_patches(const json& root, TMesh& t) const {
    const json& patches = array(member(root, "", "patches", "an array of patches"), "/patches",
                                "an array of patches like {\"sides\": [[0], [2], [4], [6]]}");
    bool grids = false;
    for (size_t p = 0; p < patches.size(); ++p) {
      const std::string path = "/patches/" + std::to_string(p);
      const json& patch = patches[p];
      if (!patch.is_object())
        fail(path, "expected a patch like {\"sides\": [[0], [2], [4], [6]]}, got " + patch.dump());
      check_keys(patch, path, {"sides", "grid"});
      const json& sides = member(patch, path, "sides", "the patch's four sides");
      if (!sides.is_array() || sides.size() != 4)
        fail(path + "/sides", "expected four sides (arrays of half-arc ids), got " + sides.dump());
      std::array<std::vector<int>, 4> s;
      for (int k = 0; k < 4; ++k)
        s[k] = ints(sides[k], path + "/sides/" + std::to_string(k),
                    "a side (an array of half-arc ids)", "a half-arc id");
      t.patch_sides.push_back(std::move(s));
      if (p == 0) grids = patch.contains("grid");
      if (patch.contains("grid") != grids)
        fail(path + "/grid", grids ? "missing: patch 0 has a grid, so every patch needs one"
                                   : "unexpected: patch 0 has no grid, so no patch may have one");
      if (grids) t.patch_grid.push_back(read_grid(patch["grid"], path + "/grid"));
    }
  }

  PatchGrid read_grid(const json& g, const std::string& path) const {
    const char* shape =
        "a grid like {\"width\": 2, \"height\": 1, \"vertices\": [0, 1, 2, 3, 4, 5]}";
    if (!g.is_object()) fail(path, std::string("expected ") + shape + ", got " + g.dump());
    check_keys(g, path, {"width", "height", "vertices"});
    PatchGrid grid;
    grid.width =
        get_int(member(g, path, "width", "the grid's width in quads"), path + "/width", "a width");
    grid.height = get_int(member(g, path, "height", "the grid's height in quads"), path + "/height",
                          "a height");
    grid.vertices =
        ints(member(g, path, "vertices", "the grid's mesh vertices, row by row"),
             path + "/vertices", "an array of mesh vertex ids, row by row", "a mesh vertex id");
    return grid;
  }

  std::string source_;
};

}  // namespace

void write_tmesh_json(std::ostream& out, const TMesh& t) {
  // One element per line: large T-meshes stay diffable and greppable by id. nlohmann writes
  // doubles in the shortest form that reads back to the same value, so a round trip is exact;
  // ordered_json keeps each object's keys in the documented order rather than sorted.
  using ordered = nlohmann::ordered_json;
  auto list = [&](const char* key, int n, auto&& element, bool last = false) {
    out << "  \"" << key << "\": [";
    for (int i = 0; i < n; ++i) out << (i ? ",\n    " : "\n    ") << element(i).dump();
    out << (n ? "\n  ]" : "]") << (last ? "\n" : ",\n");
  };
  out << "{\n  \"format\": \"bimdf-tmesh\",\n  \"version\": 1,\n";
  list("vertices", t.num_vertices(), [&](int v) { return ordered(t.vertices[v]); });
  if (!t.vertex_mesh_vertex.empty())
    out << "  \"vertex_mesh_vertex\": " << ordered(t.vertex_mesh_vertex).dump() << ",\n";
  list("arcs", t.num_arcs(), [&](int a) {
    ordered arc = {{"ends", t.arc_ends[a]}, {"target", t.arc_target[a]}};
    if (!t.arc_chain.empty()) arc["chain"] = t.arc_chain[a];
    if (!t.arc_feature.empty()) arc["feature"] = t.arc_feature[a] != 0;
    return arc;
  });
  list("patches", t.num_patches(), [&](int p) {
    ordered patch = {{"sides", t.patch_sides[p]}};
    if (!t.patch_grid.empty()) {
      const PatchGrid& g = t.patch_grid[p];
      patch["grid"] = {{"width", g.width}, {"height", g.height}, {"vertices", g.vertices}};
    }
    return patch;
  });
  list(
      "nonzero_paths", static_cast<int>(t.nonzero_paths.size()),
      [&](int i) { return ordered(t.nonzero_paths[i]); }, /*last=*/true);
  out << "}\n";
}

TMesh parse_tmesh_json(const std::string& text, const std::string& source) {
  return TMeshJsonReader(source).read(text);
}

TMesh read_tmesh_json(const std::string& path) {
  return parse_tmesh_json(read_text_file(path), path);
}

}  // namespace bimdf::tmesh
