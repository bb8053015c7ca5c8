// bimdf.solve and bimdf.check (include/bimdf/solve.hpp, flow.hpp). The solve runs without the
// GIL, so other Python threads go on meanwhile; Ctrl-C is seen at the solver's next progress
// event (each component's approximation and each refinement round) and cancels the solve with
// KeyboardInterrupt, through the library's own cancellation path (an exception thrown by the
// progress callback).
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cmath>

#include "arrays.hpp"
#include "bimdf/flow.hpp"
#include "bimdf/solve.hpp"
#include "bindings.hpp"

namespace bimdf::python {

namespace {

struct PySolution {
  py::array_t<int64_t> flow;
  double objective = 0;
  std::string status;
  double lower_bound = NAN;
  double gap = NAN;
  int64_t rounds = 0;
  py::dict stats;
  py::dict times;
};

py::object stat_to_python(const StatValue& v) {
  return std::visit([](const auto& x) -> py::object { return py::cast(x); }, v);
}

double stat_number(const Solution& s, const std::string& key, double fallback) {
  const auto it = s.stats.find(key);
  if (it == s.stats.end()) return fallback;
  if (const auto* d = std::get_if<double>(&it->second)) return *d;
  if (const auto* i = std::get_if<int64_t>(&it->second)) return double(*i);
  return fallback;
}

PySolution to_python(const Solution& s) {
  PySolution out;
  out.flow = to_numpy(s.flow);
  out.objective = s.objective;
  out.status = std::string(status_name(s.status));
  out.lower_bound = stat_number(s, "lower_bound", NAN);
  out.gap = stat_number(s, "relative_gap", NAN);
  out.rounds = static_cast<int64_t>(stat_number(s, "refinement_rounds", 0));
  for (const auto& [key, value] : s.stats) {
    out.stats[py::str(key)] = stat_to_python(value);
    // "time_lp_guess_s" → times["lp_guess"]
    if (key.rfind("time_", 0) == 0 && key.size() > 7 && key.substr(key.size() - 2) == "_s")
      out.times[py::str(key.substr(5, key.size() - 7))] = stat_to_python(value);
  }
  return out;
}

py::dict progress_to_python(const SolveProgress& p) {
  py::dict d;
  d["event"] = p.event == SolveProgress::Event::Approximated ? "approximated" : "round";
  d["component"] = p.component;
  d["components"] = p.components;
  d["round"] = p.round;
  d["objective"] = p.objective;
  d["improved"] = p.improved;
  d["elapsed_s"] = p.elapsed_s;
  return d;
}

PySolution solve(const Problem& problem, bool exact, std::optional<double> time_limit, int threads,
                 std::optional<py::function> progress, std::optional<int64_t> max_rounds,
                 int max_deviation) {
  validate_problem(problem, "<problem>");
  if (threads < 1) throw py::value_error("threads must be >= 1, got " + std::to_string(threads));
  if (time_limit && !(*time_limit > 0 && std::isfinite(*time_limit)))
    throw py::value_error("time_limit must be a positive number of seconds");
  if (max_deviation < 0) throw py::value_error("max_deviation must be >= 0");
  Solution s;
  if (!exact) {
    if (time_limit || max_rounds || progress)
      throw py::value_error("time_limit, max_rounds and progress need exact=True");
    ApproximateSolver solver(problem);
    solver.max_deviation(max_deviation);
    {
      py::gil_scoped_release release;
      solver.run();
    }
    s = solver.solution();
  } else {
    Solver solver(problem);
    solver.max_deviation(max_deviation).threads(threads);
    if (time_limit) solver.time_limit(*time_limit);
    if (max_rounds) solver.max_rounds(*max_rounds);
    // Called without the GIL (possibly from a worker thread): take it, look for Ctrl-C, call
    // the user's function. A Python exception from either cancels the solve and is re-raised.
    solver.progress([&progress](const SolveProgress& p) {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (progress) (*progress)(progress_to_python(p));
    });
    {
      py::gil_scoped_release release;
      solver.run();
    }
    s = solver.solution();
  }
  if (s.status == SolveStatus::Infeasible) {
    const auto it = s.stats.find("infeasible_reason");
    const std::string reason =
        it != s.stats.end() && std::holds_alternative<std::string>(it->second)
            ? std::get<std::string>(it->second)
            : "no flow satisfies the bounds and conservation";
    PyErr_SetString(py::module_::import("bimdf._bimdf").attr("Infeasible").ptr(), reason.c_str());
    throw py::error_already_set();
  }
  return to_python(s);
}

}  // namespace

void bind_solve(py::module_& m) {
  py::class_<PySolution>(m, "Solution", "A verified flow and what the solver says about it.")
      .def_readonly("flow", &PySolution::flow, "int64 array, one value per edge")
      .def_readonly("objective", &PySolution::objective)
      .def_readonly("status", &PySolution::status, "'optimal' or 'feasible' (a limit was hit)")
      .def_readonly("lower_bound", &PySolution::lower_bound,
                    "A lower bound on the optimum (NaN without one)")
      .def_readonly("gap", &PySolution::gap, "Relative gap to lower_bound (NaN without one)")
      .def_readonly("rounds", &PySolution::rounds, "Refinement rounds (exact solver)")
      .def_readonly("stats", &PySolution::stats, "All of the solver's statistics")
      .def_readonly("times", &PySolution::times, "Seconds per stage")
      .def("__repr__", [](const PySolution& s) {
        return "<bimdf.Solution " + s.status + ", objective " +
               std::string(py::str(py::float_(s.objective))) + ">";
      });

  py::class_<FlowCheck>(m, "FlowCheck", "The result of bimdf.check.")
      .def_property_readonly("feasible", &FlowCheck::feasible)
      .def_readonly("size_ok", &FlowCheck::size_ok)
      .def_readonly("objective", &FlowCheck::objective)
      .def_property_readonly("bound_violations",
                             [](const FlowCheck& c) {
                               py::list l;
                               for (const auto& v : c.bound_violations)
                                 l.append(py::make_tuple(v.edge, v.flow));
                               return l;
                             })
      .def_property_readonly("conservation_violations", [](const FlowCheck& c) {
        py::list l;
        for (const auto& v : c.conservation_violations)
          l.append(py::make_tuple(v.node, py::int_(static_cast<long long>(v.net_flow)), v.demand));
        return l;
      });

  m.def("solve", &solve, py::arg("problem"), py::kw_only(), py::arg("exact") = true,
        py::arg("time_limit") = py::none(), py::arg("threads") = 1,
        py::arg("progress") = py::none(), py::arg("max_rounds") = py::none(),
        py::arg("max_deviation") = 5,
        R"doc(Solves a Bi-MDF problem. exact=True: proven optimal (status 'optimal') unless
time_limit (seconds) or max_rounds stops refinement first ('feasible', with lower_bound and gap);
exact=False: the fast approximation ('feasible'). progress(dict) is called after each component's
approximation and refinement round; an exception from it cancels the solve. Raises
bimdf.Infeasible (with the proof) when no flow exists, bimdf.InputError for an invalid problem.
Releases the GIL; Ctrl-C cancels at the next progress event.)doc");
  m.def(
      "check",
      [](const Problem& problem, py::handle flow) {
        const std::vector<int64_t> x = int64_vector(flow, "flow");
        return check_flow(problem, x);
      },
      py::arg("problem"), py::arg("flow"),
      "Verifies a flow: bounds, conservation and its objective (exact 128-bit sums).");
}

}  // namespace bimdf::python
