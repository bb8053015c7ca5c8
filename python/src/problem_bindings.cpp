// bimdf.Problem and bimdf.Cost: a Bi-MDF problem (include/bimdf/problem.hpp) built from numpy
// arrays or edge by edge, read from and written to both file formats, validated with the
// library's messages.
#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>

#include "arrays.hpp"
#include "bimdf/io.hpp"
#include "bindings.hpp"
#include "io/report_issue.hpp"

namespace bimdf::python {

namespace {

// An end given as (node, "head"|"tail"|True|False).
End end_from_python(py::handle end, const std::string& name) {
  const auto t = py::reinterpret_borrow<py::object>(end);
  if (!py::isinstance<py::tuple>(t) && !py::isinstance<py::list>(t))
    throw py::type_error(name + ": expected (node, 'head' | 'tail')");
  const auto seq = py::reinterpret_borrow<py::sequence>(t);
  if (seq.size() != 2) throw py::value_error(name + ": expected (node, 'head' | 'tail')");
  End e;
  e.node = seq[0].cast<int>();
  const py::object kind = seq[1];
  if (py::isinstance<py::str>(kind)) {
    const std::string s = kind.cast<std::string>();
    if (s != "head" && s != "tail")
      throw py::value_error(name + ": end kind must be 'head' or 'tail', got '" + s + "'");
    e.head = s == "head";
  } else {
    e.head = kind.cast<bool>();
  }
  return e;
}

int64_t bound_from_python(py::handle value, const std::string& name) {
  return int64_vector(py::make_tuple(value), name, 1, true)[0];
}

// Costs from a sequence of Cost objects or a dict of arrays {"kind": …, "target": …, …}.
std::vector<Cost> costs_from_python(py::handle cost, py::ssize_t m) {
  std::vector<Cost> out;
  if (cost.is_none()) return std::vector<Cost>(m);
  if (py::isinstance<py::dict>(cost)) {
    const auto d = py::reinterpret_borrow<py::dict>(cost);
    if (!d.contains("kind")) throw py::value_error("cost: a dict of arrays needs a 'kind'");
    const std::string kind = d["kind"].cast<std::string>();
    const auto column = [&](const char* key, double fallback = 0, bool required = true) {
      if (!d.contains(key)) {
        if (required) throw py::value_error("cost: kind '" + kind + "' needs '" + key + "'");
        return std::vector<double>(m, fallback);
      }
      const py::object v = d[key];
      if (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v))
        return std::vector<double>(m, v.cast<double>());
      return double_vector(v, std::string("cost['") + key + "']", m);
    };
    for (const auto& item : d) {
      const std::string key = item.first.cast<std::string>();
      static const char* known[] = {"kind",         "target",       "weight", "slope",
                                    "weight_below", "weight_above", "eps"};
      if (std::find_if(std::begin(known), std::end(known),
                       [&](const char* k) { return key == k; }) == std::end(known))
        throw py::value_error("cost: unknown key '" + key + "'");
    }
    out.reserve(m);
    if (kind == "zero") {
      out.assign(m, Cost::zero());
    } else if (kind == "linear") {
      for (double s : column("slope")) out.push_back(Cost::linear(s));
    } else if (kind == "abs" || kind == "quad") {
      const auto t = column("target"), w = column("weight", 1, false);
      for (py::ssize_t i = 0; i < m; ++i)
        out.push_back(kind == "abs" ? Cost::abs_deviation(t[i], w[i])
                                    : Cost::quad_deviation(t[i], w[i]));
    } else if (kind == "asym_abs") {
      const auto t = column("target"), lo = column("weight_below"), hi = column("weight_above");
      for (py::ssize_t i = 0; i < m; ++i)
        out.push_back(Cost::asym_abs_deviation(t[i], lo[i], hi[i]));
    } else if (kind == "scale_factor") {
      const auto t = column("target"), w = column("weight", 1, false),
                 e = column("eps", 0.1, false);
      for (py::ssize_t i = 0; i < m; ++i) out.push_back(Cost::scale_factor(t[i], w[i], e[i]));
    } else {
      throw py::value_error(
          "cost: kind must be one of zero, linear, abs, asym_abs, quad, "
          "scale_factor for arrays (other kinds: a list of bimdf.Cost), got '" +
          kind + "'");
    }
    return out;
  }
  for (py::handle c : cost) out.push_back(c.cast<Cost>());
  if (static_cast<py::ssize_t>(out.size()) != m)
    throw py::value_error("cost: expected " + std::to_string(m) + " costs, got " +
                          std::to_string(out.size()));
  return out;
}

Problem problem_from_arrays(int num_nodes, py::object ends, py::object kinds, py::object lower,
                            py::object upper, py::object cost, py::object demand) {
  if (num_nodes < 0) throw py::value_error("num_nodes must be >= 0");
  Problem p;
  p.demand = demand.is_none() ? std::vector<int64_t>(num_nodes, 0)
                              : int64_vector(demand, "demand", num_nodes);
  if (ends.is_none()) {
    if (!kinds.is_none() || !lower.is_none() || !upper.is_none() || !cost.is_none())
      throw py::value_error("edge arrays given without ends");
    return p;
  }
  const auto e = index_rows<2>(ends, "ends");
  const auto m = static_cast<py::ssize_t>(e.size());
  if (kinds.is_none()) throw py::value_error("kinds: required with ends (+1 head, -1 tail)");
  const auto k = index_rows<2>(kinds, "kinds");
  if (static_cast<py::ssize_t>(k.size()) != m)
    throw py::value_error("kinds: expected " + std::to_string(m) + " rows, got " +
                          std::to_string(k.size()));
  p.lower = lower.is_none() ? std::vector<int64_t>(m, 0) : int64_vector(lower, "lower", m, true);
  p.upper =
      upper.is_none() ? std::vector<int64_t>(m, kInfinity) : int64_vector(upper, "upper", m, true);
  p.cost = costs_from_python(cost, m);
  for (py::ssize_t i = 0; i < m; ++i) {
    End ends_of[2];
    for (int j = 0; j < 2; ++j) {
      const int sign = (k[i][j] == 0 && e[i][j] == kNoNode) ? 0 : k[i][j];
      if (e[i][j] == kNoNode ? sign != 0 : (sign != 1 && sign != -1))
        throw py::value_error("kinds[" + std::to_string(i) + "]: expected +1 (head) or -1 (tail)" +
                              (e[i][j] == kNoNode ? " where ends is -1: 0" : "") + ", got " +
                              std::to_string(k[i][j]));
      ends_of[j] = End{e[i][j], sign == 1};
    }
    if (ends_of[0].node == kNoNode) std::swap(ends_of[0], ends_of[1]);
    if (ends_of[0].node == kNoNode)
      throw py::value_error("ends[" + std::to_string(i) + "]: an edge needs at least one node");
    p.end_a.push_back(ends_of[0]);
    p.end_b.push_back(ends_of[1]);
  }
  return p;
}

std::string problem_repr(const Problem& p) {
  return "<bimdf.Problem: " + std::to_string(p.num_nodes()) + " nodes, " +
         std::to_string(p.num_edges()) + " edges>";
}

py::array_t<int8_t> end_kinds(const Problem& p) {
  py::array_t<int8_t> out({static_cast<py::ssize_t>(p.num_edges()), py::ssize_t{2}});
  auto v = out.mutable_unchecked<2>();
  for (int e = 0; e < p.num_edges(); ++e) {
    v(e, 0) = static_cast<int8_t>(p.end_a[e].sign());
    v(e, 1) = static_cast<int8_t>(p.is_outer(e) ? 0 : p.end_b[e].sign());
  }
  return out;
}

}  // namespace

void validate_problem(const Problem& p, const std::string& source) {
  detail::validate_or_throw(
      p, source, [](const ProblemIssue&) { return std::string(); }, false);
}

void bind_problem(py::module_& m) {
  py::class_<Cost>(m, "Cost", "A convex cost function of one edge's flow (bimdf/cost.hpp).")
      .def(py::init<>(), "The zero cost.")
      .def_static("zero", &Cost::zero, py::arg("guess") = 0)
      .def_static("linear", &Cost::linear, py::arg("slope"))
      .def_static("abs", &Cost::abs_deviation, py::arg("target"), py::arg("weight") = 1.0,
                  "weight * |x - target|")
      .def_static("asym_abs", &Cost::asym_abs_deviation, py::arg("target"), py::arg("weight_below"),
                  py::arg("weight_above"))
      .def_static("quad", &Cost::quad_deviation, py::arg("target"), py::arg("weight") = 1.0,
                  "weight * (x - target)**2")
      .def_static("piecewise", &Cost::piecewise_linear, py::arg("first"), py::arg("values"),
                  "Values at first, first+1, …; linear between and beyond (convex).")
      .def_static("scale_factor", &Cost::scale_factor, py::arg("target"), py::arg("weight") = 1.0,
                  py::arg("eps") = 0.1)
      .def_static("sum", &Cost::sum, py::arg("terms"))
      .def_property_readonly("kind",
                             [](const Cost& c) { return std::string(cost_kind_name(c.kind())); })
      .def_property_readonly("target", &Cost::target)
      .def_property_readonly("weight", &Cost::weight)
      .def(
          "__call__", [](const Cost& c, int64_t x) { return c(x); }, py::arg("x"))
      .def("__eq__", [](const Cost& a, const Cost& b) { return a == b; })
      .def("__repr__", [](const Cost& c) {
        return "<bimdf.Cost " + std::string(cost_kind_name(c.kind())) + ">";
      });

  py::class_<Problem>(m, "Problem",
                      R"doc(A Bi-MDF problem: nodes with demands, edges with one or two
ends (node, head/tail), integer bounds and convex costs (docs/formats.md).

Problem(num_nodes, ends=…, kinds=…, lower=…, upper=…, cost=…, demand=…) builds it from arrays:
ends (m, 2) node ids (-1 as the second end: an outer edge), kinds (m, 2) +1 head / -1 tail (0 for
a missing end), lower / upper (m,) integers (±inf or bimdf.INF for unbounded; defaults 0 / inf),
cost a list of bimdf.Cost or a dict of arrays such as {"kind": "quad", "target": t, "weight": w},
demand (num_nodes,) integers. Problem() and add_node / add_edge build it element by element.)doc")
      .def(py::init(&problem_from_arrays), py::arg("num_nodes") = 0, py::arg("ends") = py::none(),
           py::arg("kinds") = py::none(), py::arg("lower") = py::none(),
           py::arg("upper") = py::none(), py::arg("cost") = py::none(),
           py::arg("demand") = py::none())
      .def(
          "add_node", [](Problem& p, int64_t demand) { return p.add_node(demand); },
          py::arg("demand") = 0, "Appends a node; returns its id.")
      .def(
          "add_edge",
          [](Problem& p, py::handle a, py::handle b, py::handle lower, py::handle upper,
             const Cost& cost) {
            const End ea = end_from_python(a, "a");
            std::optional<End> eb;
            if (!b.is_none()) eb = end_from_python(b, "b");
            return p.add_edge(ea, eb, bound_from_python(lower, "lower"),
                              bound_from_python(upper, "upper"), cost);
          },
          py::arg("a"), py::arg("b") = py::none(), py::arg("lower") = 0,
          py::arg("upper") = py::float_(INFINITY), py::arg("cost") = Cost(),
          "Appends an edge between ends a and b, each (node, 'head' | 'tail'); b None: an outer "
          "edge. Returns its id.")
      .def_property_readonly("num_nodes", &Problem::num_nodes)
      .def_property_readonly("num_edges", &Problem::num_edges)
      .def_property_readonly("demand", [](const Problem& p) { return to_numpy(p.demand); })
      .def_property_readonly("lower", [](const Problem& p) { return to_numpy(p.lower); })
      .def_property_readonly("upper", [](const Problem& p) { return to_numpy(p.upper); })
      .def_property_readonly("ends",
                             [](const Problem& p) {
                               std::vector<std::array<int, 2>> rows;
                               for (int e = 0; e < p.num_edges(); ++e)
                                 rows.push_back({p.end_a[e].node, p.end_b[e].node});
                               return rows_to_numpy<int64_t>(rows);
                             })
      .def_property_readonly("kinds", &end_kinds)
      .def_property_readonly("costs", [](const Problem& p) { return p.cost; })
      .def(
          "validate", [](const Problem& p) { validate_problem(p, "<problem>"); },
          "Raises bimdf.InputError (a ValueError) naming the first node or edge that breaks a "
          "rule of the model; infeasibility is not checked here.")
      .def(
          "write",
          [](const Problem& p, const std::string& path, const std::string& format,
             bool libsatsuma_compatible) {
            const bool json =
                format == "json" ||
                (format.empty() && std::filesystem::path(path).extension() == ".json");
            if (!format.empty() && format != "json" && format != "bimdf")
              throw py::value_error("format must be 'bimdf' or 'json', got '" + format + "'");
            const std::string text =
                json ? to_json_problem(p) : to_bimdf(p, {libsatsuma_compatible});
            std::ofstream out(path, std::ios::binary);
            if (!out) throw py::value_error(path + ": cannot be written");
            out << text;
            if (!out.flush()) throw py::value_error(path + ": writing failed");
          },
          py::arg("path"), py::arg("format") = "", py::arg("libsatsuma_compatible") = false,
          "Writes the problem: JSON if format='json' or the path ends in .json, else the .bimdf "
          "text format.")
      .def("__eq__", [](const Problem& a, const Problem& b) { return a == b; })
      .def("__repr__", &problem_repr);

  m.def(
      "read",
      [](const std::string& path) {
        require_file(path);
        return read_problem_file(path);
      },
      py::arg("path"), "Reads a problem file (.bimdf text or JSON, told apart by content).");
  m.def(
      "parse", [](const std::string& text) { return parse_problem(text, "<string>"); },
      py::arg("text"), "Parses problem text (.bimdf or JSON).");
}

}  // namespace bimdf::python
