// Conversions between numpy arrays and the library's plain vectors, with the checks a Python
// user needs: a wrong shape or dtype raises TypeError/ValueError naming the argument, never a
// silent reinterpretation (a float array of non-integers is not truncated into flows).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bimdf::python {

namespace py = pybind11;

// A 1-D int64 numpy array that owns a copy of `values`.
py::array_t<int64_t> to_numpy(const std::vector<int64_t>& values);
py::array_t<double> to_numpy(const std::vector<double>& values);
// An (n, N) array of the rows, of element type T (e.g. int64 for int face indices).
template <typename T, typename From, size_t N>
py::array_t<T> rows_to_numpy(const std::vector<std::array<From, N>>& rows) {
  py::array_t<T> out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(N)});
  auto view = out.template mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < N; ++j) view(i, j) = static_cast<T>(rows[i][j]);
  return out;
}

// The values of a 1-D array-like of integers (any integer dtype, or floats that are whole
// numbers; with `allow_infinity`, ±inf become ±kInfinity). `name` is the argument's name in
// messages. `expected_size` < 0: any length.
std::vector<int64_t> int64_vector(py::handle values, const std::string& name,
                                  py::ssize_t expected_size = -1, bool allow_infinity = false);
// The values of a 1-D array-like of finite numbers.
std::vector<double> double_vector(py::handle values, const std::string& name,
                                  py::ssize_t expected_size = -1);
// The rows of an (n, N) array-like of numbers; integer rows must hold whole numbers.
std::vector<std::array<double, 3>> point_rows(py::handle values, const std::string& name);
template <size_t N>
std::vector<std::array<int, N>> index_rows(py::handle values, const std::string& name);

}  // namespace bimdf::python
