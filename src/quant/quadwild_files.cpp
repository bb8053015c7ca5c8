// QuadWild's step-2 files (../shared/reference/quadwild_modeling.md §1.1): NAME.patch (face
// count, then one patch id per face), NAME.corners (patch count, then per patch a corner count
// and that many vertex ids), NAME.feature (count, then `face,edge` pairs) and NAME.c_feature
// (count, then vertex ids). All ids 0-based.
#include <filesystem>

#include "bimdf/error.hpp"
#include "bimdf/io.hpp"
#include "bimdf/quant/layout.hpp"
#include "io/text_scan.hpp"

namespace bimdf::quant {
namespace {

namespace fs = std::filesystem;

int expect_index(detail::TextScanner& in, const std::string& what, int64_t count) {
  const detail::Token t = in.peek();
  const int64_t v = in.expect_int(what);
  if (v < 0 || v >= count)
    in.fail(t.line, what + ": " + std::to_string(v) + " is out of range (expected 0.." +
                        std::to_string(count - 1) + ")");
  return static_cast<int>(v);
}

int64_t expect_count(detail::TextScanner& in, const std::string& what, int64_t max) {
  const detail::Token t = in.peek();
  const int64_t n = in.expect_int(what);
  if (n < 0 || n > max)
    in.fail(t.line, what + ": " + std::to_string(n) + " is out of range (expected 0.." +
                        std::to_string(max) + ")");
  return n;
}

void expect_end(detail::TextScanner& in, const std::string& what) {
  const detail::Token t = in.peek();
  if (!t.text.empty())
    in.fail(t.line, "unexpected " + detail::quote(t.text) + " after the last " + what);
}

}  // namespace

std::vector<std::array<int, 2>> read_feature_edges(const std::string& path,
                                                   const TriangleMesh& mesh) {
  const int F = mesh.num_faces();
  std::vector<std::array<int, 2>> feature_edges;
  const std::string text = read_text_file(path);
  detail::TextScanner in(text, path);
  const int64_t n = expect_count(in, "the feature edge count", 3 * int64_t{F});
  for (int64_t k = 0; k < n; ++k) {
    const std::string what = "feature edge " + std::to_string(k) + " (face,edge)";
    const detail::Token t = in.expect(what);
    const size_t comma = t.text.find(',');
    int64_t f = -1, e = -1;
    if (comma == std::string_view::npos || !detail::parse_int64(t.text.substr(0, comma), f) ||
        !detail::parse_int64(t.text.substr(comma + 1), e))
      in.fail(t.line, what + ": expected two integers separated by a comma, found " +
                          detail::quote(t.text));
    if (f < 0 || f >= F || e < 0 || e > 2)
      in.fail(t.line, what + ": face " + std::to_string(f) + " edge " + std::to_string(e) +
                          " is out of range (faces 0.." + std::to_string(F - 1) + ", edges 0..2)");
    feature_edges.push_back({mesh.faces[f][e], mesh.faces[f][(e + 1) % 3]});
  }
  expect_end(in, "feature edge");
  return feature_edges;
}

std::vector<int> read_feature_corners(const std::string& path, int num_vertices) {
  std::vector<int> feature_corners;
  const std::string text = read_text_file(path);
  detail::TextScanner in(text, path);
  const int64_t n = expect_count(in, "the feature corner count", num_vertices);
  for (int64_t k = 0; k < n; ++k)
    feature_corners.push_back(
        expect_index(in, "feature corner " + std::to_string(k), num_vertices));
  expect_end(in, "feature corner");
  return feature_corners;
}

Layout read_quadwild_layout(const std::string& obj_path) {
  TriangleMesh mesh = read_obj_triangles(obj_path);
  const int F = mesh.num_faces(), V = mesh.num_vertices();
  auto companion = [&](const char* ext) {
    return fs::path(obj_path).replace_extension(ext).string();
  };

  const std::string patch_path = companion(".patch");
  const std::string patch_text = read_text_file(patch_path);
  detail::TextScanner patch(patch_text, patch_path);
  const detail::Token count_token = patch.peek();
  const int64_t labelled = patch.expect_int("the face count");
  if (labelled != F)
    patch.fail(count_token.line, "the face count is " + std::to_string(labelled) + ", but " +
                                     obj_path + " has " + std::to_string(F) + " faces");
  std::vector<int> face_chart(F);
  int max_patch = -1;
  for (int f = 0; f < F; ++f) {
    face_chart[f] = expect_index(patch, "the patch id of face " + std::to_string(f), INT32_MAX);
    max_patch = std::max(max_patch, face_chart[f]);
  }
  expect_end(patch, "patch id");

  const std::string corners_path = companion(".corners");
  const std::string corners_text = read_text_file(corners_path);
  detail::TextScanner cin(corners_text, corners_path);
  const detail::Token patches_token = cin.peek();
  const int64_t P = expect_count(cin, "the patch count", F);
  if (P < max_patch + 1)
    cin.fail(patches_token.line, "the patch count is " + std::to_string(P) + ", but " + patch_path +
                                     " uses patch id " + std::to_string(max_patch));
  std::vector<std::vector<int>> corners(P);
  for (int p = 0; p < P; ++p) {
    const int64_t n = expect_count(cin, "the corner count of patch " + std::to_string(p), V);
    for (int64_t k = 0; k < n; ++k)
      corners[p].push_back(
          expect_index(cin, "corner " + std::to_string(k) + " of patch " + std::to_string(p), V));
  }
  expect_end(cin, "patch");

  // Features refer to faces as written; convert them to vertex pairs before re-orientation.
  std::vector<std::array<int, 2>> feature_edges;
  if (fs::exists(companion(".feature")))
    feature_edges = read_feature_edges(companion(".feature"), mesh);
  std::vector<int> feature_corners;
  if (fs::exists(companion(".c_feature")))
    feature_corners = read_feature_corners(companion(".c_feature"), V);

  Layout layout = build_layout(std::move(mesh), std::move(face_chart), corners, obj_path);
  layout.feature_edges = std::move(feature_edges);
  layout.feature_corners = std::move(feature_corners);
  return layout;
}

}  // namespace bimdf::quant
