// Small helpers shared by the test files.
#pragma once

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "bimdf/error.hpp"

namespace bimdf::testing {

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

}  // namespace bimdf::testing
