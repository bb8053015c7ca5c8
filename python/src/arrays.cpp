// arrays.hpp: numpy ↔ vectors.
#include "arrays.hpp"

#include <cmath>

#include "bimdf/problem.hpp"

namespace bimdf::python {

namespace {

// `values` as a numpy array of numbers with `ndim` dimensions, or TypeError/ValueError.
py::array numeric_array(py::handle values, const std::string& name, int ndim) {
  py::array a = py::array::ensure(values);
  if (!a) throw py::type_error(name + ": expected an array of numbers");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f' && kind != 'b')
    throw py::type_error(name + ": expected an array of numbers, got dtype " +
                         std::string(py::str(a.dtype())));
  if (a.ndim() != ndim)
    throw py::value_error(name + ": expected a " + std::to_string(ndim) + "-D array, got " +
                          std::to_string(a.ndim()) + "-D");
  return a;
}

bool is_integer_dtype(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'i' || kind == 'u' || kind == 'b';
}

void check_size(py::ssize_t size, py::ssize_t expected, const std::string& name) {
  if (expected >= 0 && size != expected)
    throw py::value_error(name + ": expected " + std::to_string(expected) + " values, got " +
                          std::to_string(size));
}

// A double that must be a whole number within the model's range (or ±inf if allowed).
int64_t whole_number(double x, const std::string& name, py::ssize_t i, bool allow_infinity) {
  if (std::isinf(x) && allow_infinity) return x > 0 ? kInfinity : -kInfinity;
  if (!std::isfinite(x) || x != std::floor(x) || std::fabs(x) > double(kMaxMagnitude))
    throw py::value_error(name + "[" + std::to_string(i) + "]: expected an integer" +
                          (allow_infinity ? " or ±inf" : "") + ", got " +
                          std::string(py::str(py::float_(x))));
  return static_cast<int64_t>(x);
}

}  // namespace

py::array_t<int64_t> to_numpy(const std::vector<int64_t>& values) {
  return py::array_t<int64_t>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::array_t<double> to_numpy(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

std::vector<int64_t> int64_vector(py::handle values, const std::string& name,
                                  py::ssize_t expected_size, bool allow_infinity) {
  const py::array a = numeric_array(values, name, 1);
  check_size(a.shape(0), expected_size, name);
  std::vector<int64_t> out(static_cast<size_t>(a.shape(0)));
  if (is_integer_dtype(a)) {
    if (a.dtype().kind() == 'u' && a.dtype().itemsize() == 8) {
      // `held` owns the converted copy; an unchecked view does not keep its array alive.
      const auto held = py::array_t<uint64_t, py::array::forcecast>::ensure(a);
      const auto u = held.unchecked<1>();
      for (py::ssize_t i = 0; i < u.shape(0); ++i) {
        if (u(i) > uint64_t(kInfinity))
          throw py::value_error(name + "[" + std::to_string(i) + "]: value out of range");
        out[i] = static_cast<int64_t>(u(i));
      }
      return out;
    }
    const auto held = py::array_t<int64_t, py::array::forcecast>::ensure(a);
    const auto v = held.unchecked<1>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i) out[i] = v(i);
    return out;
  }
  const auto held = py::array_t<double, py::array::forcecast>::ensure(a);
  const auto v = held.unchecked<1>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) out[i] = whole_number(v(i), name, i, allow_infinity);
  return out;
}

std::vector<double> double_vector(py::handle values, const std::string& name,
                                  py::ssize_t expected_size) {
  const py::array a = numeric_array(values, name, 1);
  check_size(a.shape(0), expected_size, name);
  const auto held = py::array_t<double, py::array::forcecast>::ensure(a);
  const auto v = held.unchecked<1>();
  std::vector<double> out(static_cast<size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    if (!std::isfinite(v(i)))
      throw py::value_error(name + "[" + std::to_string(i) + "]: expected a finite number");
    out[i] = v(i);
  }
  return out;
}

std::vector<std::array<double, 3>> point_rows(py::handle values, const std::string& name) {
  const py::array a = numeric_array(values, name, 2);
  if (a.shape(1) != 3)
    throw py::value_error(name + ": expected shape (n, 3), got (" + std::to_string(a.shape(0)) +
                          ", " + std::to_string(a.shape(1)) + ")");
  const auto held = py::array_t<double, py::array::forcecast>::ensure(a);
  const auto v = held.unchecked<2>();
  std::vector<std::array<double, 3>> out(static_cast<size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    for (int j = 0; j < 3; ++j) {
      if (!std::isfinite(v(i, j)))
        throw py::value_error(name + "[" + std::to_string(i) + "]: expected finite coordinates");
      out[i][j] = v(i, j);
    }
  return out;
}

template <size_t N>
std::vector<std::array<int, N>> index_rows(py::handle values, const std::string& name) {
  const py::array a = numeric_array(values, name, 2);
  if (a.shape(1) != static_cast<py::ssize_t>(N))
    throw py::value_error(name + ": expected shape (m, " + std::to_string(N) + "), got (" +
                          std::to_string(a.shape(0)) + ", " + std::to_string(a.shape(1)) + ")");
  if (!is_integer_dtype(a))
    throw py::type_error(name + ": expected an integer array, got dtype " +
                         std::string(py::str(a.dtype())));
  const auto held = py::array_t<int64_t, py::array::forcecast>::ensure(a);
  const auto v = held.unchecked<2>();
  std::vector<std::array<int, N>> out(static_cast<size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    for (size_t j = 0; j < N; ++j) {
      if (v(i, j) < -1 || v(i, j) > std::numeric_limits<int>::max())
        throw py::value_error(name + "[" + std::to_string(i) + "]: index " +
                              std::to_string(v(i, j)) + " out of range");
      out[i][j] = static_cast<int>(v(i, j));
    }
  return out;
}

template std::vector<std::array<int, 2>> index_rows<2>(py::handle, const std::string&);
template std::vector<std::array<int, 3>> index_rows<3>(py::handle, const std::string&);
template std::vector<std::array<int, 4>> index_rows<4>(py::handle, const std::string&);

}  // namespace bimdf::python
