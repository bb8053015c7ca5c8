// The `bimdf` Python module's compiled part, `bimdf._bimdf` (docs/python.md): exceptions, the
// infinity marker and version, and the bindings of bindings.hpp. python/bimdf/__init__.py
// re-exports it; python/bimdf/_bimdf.pyi documents its types.
#include <filesystem>

#include "bimdf/error.hpp"
#include "bimdf/solve.hpp"
#include "bimdf/tmesh/collapse.hpp"
#include "bimdf/version.hpp"
#include "bindings.hpp"

namespace bimdf::python {

void require_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    PyErr_SetString(PyExc_FileNotFoundError, (path + ": no such file").c_str());
    throw py::error_already_set();
  }
}

}  // namespace bimdf::python

PYBIND11_MODULE(_bimdf, m) {
  namespace py = pybind11;
  using namespace bimdf::python;
  m.doc() = "Exact minimum-deviation flows in bidirected graphs, and quad-mesh quantization.";
  m.attr("__version__") = BIMDF_VERSION;
  m.attr("INF") = py::int_(bimdf::kInfinity);

  // InputError carries the library's whole message ("file:line: edge 3: …").
  static py::exception<bimdf::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<bimdf::SolverError> solver_error(m, "SolverError", PyExc_RuntimeError);
  static py::exception<bimdf::tmesh::CollapseError> collapse_error(m, "CollapseError",
                                                                   PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const bimdf::InputError& e) {
      input_error(e.what());
    } catch (const bimdf::SolverError& e) {
      solver_error(e.what());
    } catch (const bimdf::tmesh::CollapseError& e) {
      collapse_error(e.what());
    }
  });
  // Raised by solve() when the problem is proven infeasible; .args[0] says why.
  m.attr("Infeasible") = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "bimdf.Infeasible", "The problem has no feasible flow (proven); the message gives the proof.",
      PyExc_Exception, nullptr));

  bind_problem(m);
  bind_solve(m);
  bind_mesh(m);
}
