#include "bimdf/render.hpp"

#include <zlib.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "mesh/vec3.hpp"

namespace bimdf {
namespace {

using detail::cross;
using detail::dot;
using detail::normalized;
using detail::sub;
using detail::Vec3;

Vec3 quad_normal(const QuadMesh& mesh, const std::array<int, 4>& q) {
  return cross(sub(mesh.vertices[q[2]], mesh.vertices[q[0]]),
               sub(mesh.vertices[q[3]], mesh.vertices[q[1]]));
}

// Pastel colour of patch p: hues spaced by the golden angle.
Vec3 patch_colour(int p) {
  if (p < 0) return {0.80, 0.82, 0.86};
  const double h = std::fmod(p * 0.618033988749895, 1.0) * 6, s = 0.42, v = 0.97;
  const int i = static_cast<int>(h);
  const double f = h - i, a = v * (1 - s), b = v * (1 - s * f), c = v * (1 - s * (1 - f));
  switch (i % 6) {
    case 0:
      return {v, c, a};
    case 1:
      return {b, v, a};
    case 2:
      return {a, v, c};
    case 3:
      return {a, b, v};
    case 4:
      return {c, a, v};
    default:
      return {v, a, b};
  }
}

// The automatic view direction: along the thinnest principal axis, tilted towards the other
// two, from the side that sees the larger projected area of front faces.
Vec3 automatic_view(const QuadMesh& mesh, const Vec3& centre) {
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : mesh.vertices) {
    const Eigen::Vector3d d(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Eigen::Vector3d thin = eigen.eigenvectors().col(0), mid = eigen.eigenvectors().col(1),
                        wide = eigen.eigenvectors().col(2);
  Vec3 best{0, 0, -1};
  double best_area = -1;
  for (double sign : {1.0, -1.0}) {
    const Eigen::Vector3d d = (sign * thin + 0.45 * mid + 0.2 * wide).normalized();
    const Vec3 view{d.x(), d.y(), d.z()};
    double area = 0;
    for (const auto& q : mesh.quads) area += std::max(0.0, -dot(quad_normal(mesh, q), view));
    if (area > best_area) best_area = area, best = view;
  }
  return best;
}

double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

}  // namespace

Image render_quad_mesh(const QuadMesh& mesh, const RenderOptions& options) {
  if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384 ||
      options.supersampling < 1 || options.supersampling > 8)
    throw std::invalid_argument(
        "render: image size must be 1 to 16384 pixels, supersampling 1 to 8");
  const int s = options.supersampling;
  const int W = options.width * s, H = options.height * s;
  std::vector<Vec3> colour(static_cast<size_t>(W) * H);
  for (int y = 0; y < H; ++y) {
    const double t = double(y) / H;  // a soft vertical gradient
    for (int x = 0; x < W; ++x)
      colour[static_cast<size_t>(y) * W + x] = {0.97 - 0.1 * t, 0.97 - 0.1 * t, 0.98 - 0.06 * t};
  }
  std::vector<double> depth(colour.size(), std::numeric_limits<double>::infinity());
  Image image{options.width, options.height, {}};
  if (mesh.vertices.empty() || mesh.quads.empty()) {
    image.rgb.assign(static_cast<size_t>(options.width) * options.height * 3, 245);
    return image;
  }
  Vec3 lo = mesh.vertices[0], hi = lo;
  for (const Vec3& p : mesh.vertices)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
  const Vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  Vec3 view = normalized(options.view);
  if (dot(view, view) == 0) view = automatic_view(mesh, centre);
  Vec3 up{0, 1, 0};
  if (std::abs(dot(up, view)) > 0.95) up = {0, 0, 1};
  up = normalized(
      sub(up, {view[0] * dot(up, view), view[1] * dot(up, view), view[2] * dot(up, view)}));
  const Vec3 right = cross(view, up);
  // Screen coordinates: fit the projected vertices into the image with a margin.
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Vec3& p : mesh.vertices) {
    const Vec3 d = sub(p, centre);
    x0 = std::min(x0, dot(d, right)), x1 = std::max(x1, dot(d, right));
    y0 = std::min(y0, dot(d, up)), y1 = std::max(y1, dot(d, up));
  }
  const double scale =
      0.92 * std::min(W / std::max(x1 - x0, 1e-300), H / std::max(y1 - y0, 1e-300));
  const auto project = [&](const Vec3& p) {
    const Vec3 d = sub(p, centre);
    return Vec3{W / 2.0 + scale * (dot(d, right) - (x0 + x1) / 2),
                H / 2.0 - scale * (dot(d, up) - (y0 + y1) / 2), dot(d, view)};
  };
  std::vector<Vec3> screen(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) screen[v] = project(mesh.vertices[v]);
  const double edge_width = 0.6 * s;

  for (size_t f = 0; f < mesh.quads.size(); ++f) {
    const auto& q = mesh.quads[f];
    const Vec3 n = normalized(quad_normal(mesh, q));
    const double light = 0.3 + 0.7 * std::abs(dot(n, view));
    const Vec3 base = patch_colour(
        options.colour_patches && f < mesh.quad_patch.size() ? mesh.quad_patch[f] : -1);
    const Vec3 shade{base[0] * light, base[1] * light, base[2] * light};
    for (const std::array<int, 3> tri :
         {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      const Vec3 &a = screen[q[tri[0]]], &b = screen[q[tri[1]]], &c = screen[q[tri[2]]];
      const double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
      if (std::abs(area) < 1e-12) continue;
      const int px0 = std::max(0, static_cast<int>(std::floor(std::min({a[0], b[0], c[0]}))));
      const int px1 = std::min(W - 1, static_cast<int>(std::ceil(std::max({a[0], b[0], c[0]}))));
      const int py0 = std::max(0, static_cast<int>(std::floor(std::min({a[1], b[1], c[1]}))));
      const int py1 = std::min(H - 1, static_cast<int>(std::ceil(std::max({a[1], b[1], c[1]}))));
      for (int y = py0; y <= py1; ++y)
        for (int x = px0; x <= px1; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          const double l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) / area;
          const double l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / area;
          const double l0 = 1 - l1 - l2;
          if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
          const double z = l0 * a[2] + l1 * b[2] + l2 * c[2];
          const size_t i = static_cast<size_t>(y) * W + x;
          if (z >= depth[i]) continue;
          depth[i] = z;
          Vec3 pixel = shade;
          if (options.draw_edges) {
            double d = std::numeric_limits<double>::infinity();
            for (int e = 0; e < 4; ++e) {
              const Vec3 &u = screen[q[e]], &w = screen[q[(e + 1) % 4]];
              d = std::min(d, segment_distance(px, py, u[0], u[1], w[0], w[1]));
            }
            if (d < edge_width) pixel = {0.12, 0.12, 0.16};
          }
          colour[i] = pixel;
        }
    }
  }

  if (options.mark_singularities) {
    std::vector<std::set<int>> neighbours(mesh.vertices.size());
    std::map<std::pair<int, int>, int> edge_quads;
    for (const auto& q : mesh.quads)
      for (int a = 0; a < 4; ++a) {
        neighbours[q[a]].insert(q[(a + 1) % 4]);
        neighbours[q[(a + 1) % 4]].insert(q[a]);
        ++edge_quads[{std::min(q[a], q[(a + 1) % 4]), std::max(q[a], q[(a + 1) % 4])}];
      }
    std::vector<char> boundary(mesh.vertices.size(), 0);
    for (const auto& [e, count] : edge_quads)
      if (count == 1) boundary[e.first] = boundary[e.second] = 1;
    const double radius = 3.2 * s;
    const double tolerance = 0.01 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      const int valence = static_cast<int>(neighbours[v].size());
      if (boundary[v] || valence == 4 || valence == 0) continue;
      const Vec3& p = screen[v];
      const int cx = static_cast<int>(p[0]), cy = static_cast<int>(p[1]);
      if (cx < 0 || cy < 0 || cx >= W || cy >= H) continue;
      if (p[2] > depth[static_cast<size_t>(cy) * W + cx] + tolerance) continue;  // hidden
      const Vec3 mark = valence == 3   ? Vec3{0.1, 0.3, 0.95}
                        : valence == 5 ? Vec3{0.9, 0.1, 0.1}
                                       : Vec3{0.1, 0.65, 0.2};
      for (int y = std::max(0, cy - int(radius) - 1); y <= std::min(H - 1, cy + int(radius) + 1);
           ++y)
        for (int x = std::max(0, cx - int(radius) - 1); x <= std::min(W - 1, cx + int(radius) + 1);
             ++x)
          if (std::hypot(x + 0.5 - p[0], y + 0.5 - p[1]) <= radius)
            colour[static_cast<size_t>(y) * W + x] = mark;
    }
  }

  image.rgb.resize(static_cast<size_t>(options.width) * options.height * 3);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double sum = 0;
        for (int dy = 0; dy < s; ++dy)
          for (int dx = 0; dx < s; ++dx)
            sum += colour[static_cast<size_t>(y * s + dy) * W + x * s + dx][ch];
        image.rgb[(static_cast<size_t>(y) * options.width + x) * 3 + ch] =
            static_cast<uint8_t>(std::clamp(sum / (s * s), 0.0, 1.0) * 255 + 0.5);
      }
  return image;
}

namespace {

void put_u32(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((v >> shift) & 0xff));
}

void put_chunk(std::string& out, const char* type, const std::string& data) {
  put_u32(out, static_cast<uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put_u32(out, static_cast<uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()),
                                           static_cast<uInt>(body.size()))));
}

}  // namespace

std::string encode_png(const Image& image) {
  std::string raw;  // each row: filter byte 0, then RGB
  raw.reserve(static_cast<size_t>(image.height) * (image.width * 3 + 1));
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);
    raw.append(
        reinterpret_cast<const char*>(image.rgb.data()) + static_cast<size_t>(y) * image.width * 3,
        static_cast<size_t>(image.width) * 3);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string compressed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
                reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()),
                9) != Z_OK)
    throw std::runtime_error("PNG: compression failed");
  compressed.resize(size);
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put_u32(header, static_cast<uint32_t>(image.width));
  put_u32(header, static_cast<uint32_t>(image.height));
  header += std::string("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB, deflate, no filter, no interlace
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", compressed);
  put_chunk(png, "IEND", "");
  return png;
}

}  // namespace bimdf
