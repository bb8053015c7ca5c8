// Small helpers shared by the test files.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

#include "bimdf/error.hpp"
#include "bimdf/mesh.hpp"

namespace bimdf::testing {

// a equals b up to a relative 1e-9 (absolute below magnitude 1): objectives recomputed in
// double by different routes.
inline bool relatively_close(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::max(1.0, std::fabs(b));
}

// The message of the InputError that `f` throws; fails the test if it throws nothing.
inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

// A 2 × 2 grid of unit quads in the plane z = 0, vertex 3·y + x at (x, y); the lower two
// quads are patch 0, the upper two patch 1.
inline QuadMesh quad_grid_2x2() {
  QuadMesh m;
  for (int y = 0; y <= 2; ++y)
    for (int x = 0; x <= 2; ++x) m.vertices.push_back({double(x), double(y), 0});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      m.quads.push_back({3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3});
  m.quad_patch = {0, 0, 1, 1};
  return m;
}

// `count` scaled by the environment variable BIMDF_TEST_SCALE (default 1): the sanitizer run in
// CI sets it below 1 so that the property suites keep their full checks on fewer random
// instances under instrumentation; the plain run always uses the full counts.
inline int scaled(int count) {
  const char* env = std::getenv("BIMDF_TEST_SCALE");
  const double scale = env ? std::atof(env) : 1.0;
  return std::max(1, static_cast<int>(count * (scale > 0 ? scale : 1.0)));
}

}  // namespace bimdf::testing
