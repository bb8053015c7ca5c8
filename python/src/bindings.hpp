// The parts of the bimdf Python module (module.cpp puts them together).
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "bimdf/problem.hpp"

namespace bimdf::python {

namespace py = pybind11;

void bind_problem(py::module_& m);  // Cost, Problem, read, parse
void bind_solve(py::module_& m);    // Solution, FlowCheck, solve, check
void bind_mesh(py::module_& m);     // quantize, remesh, requantize, metrics, OBJ files

// Raises bimdf.InputError (a ValueError) naming the first issue of `p`.
void validate_problem(const Problem& p, const std::string& source);
// Raises FileNotFoundError unless `path` names an existing file.
void require_file(const std::string& path);

}  // namespace bimdf::python
