// bimdf's JSON problem and solution formats (docs/formats.md). Problems:
//   {"format": "bimdf-problem", "version": 1,
//    "nodes": [{"demand": 0, "name": "a"}, …],
//    "edges": [{"ends": [[0, "head"], ["a", "tail"]], "lower": 0, "upper": "inf",
//               "cost": {"kind": "abs", "target": 2.5, "weight": 1}, "name": "e0"}, …]}
// Every field but "nodes"/"edges"/"ends" has a default; unknown keys are errors so that a typo
// never silently changes a problem. Errors name the JSON path of the offending value.
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "bimdf/io.hpp"
#include "json_document.hpp"
#include "report_issue.hpp"
#include "text_scan.hpp"

namespace bimdf {
namespace {

using nlohmann::json;

constexpr int kMaxCostDepth = 64;

class JsonProblemReader {
 public:
  explicit JsonProblemReader(const std::string& source) : source_(source) {}

  Problem read(std::string_view text) {
    const json root = parse_document(text, source_);
    if (!root.is_object()) fail("", "expected a JSON object with \"nodes\" and \"edges\"");
    check_keys(root, "", {"format", "version", "nodes", "edges", "comment"});
    if (root.contains("format") && root["format"] != "bimdf-problem")
      fail("/format", "expected \"bimdf-problem\", got " + root["format"].dump());
    if (root.contains("version") && root["version"] != 1)
      fail("/version", "unsupported version " + root["version"].dump() + ", expected 1");
    Problem p;
    read_nodes(root, p);
    read_edges(root, p);
    detail::validate_or_throw(p, source_, [](const ProblemIssue& issue) {
      switch (issue.where) {
        case ProblemIssue::Where::Node:
          return "/nodes/" + std::to_string(issue.index) + "/" + issue.field;
        case ProblemIssue::Where::Edge:
          return "/edges/" + std::to_string(issue.index) + "/" + issue.field;
        default:
          return std::string("/");
      }
    }, /*location_names_field=*/true);
    return p;
  }

  static json parse_document(std::string_view text, const std::string& source) {
    return detail::parse_json_document(text, source);
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(source_, path.empty() ? "/" : path, what);
  }

  void check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> allowed) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* k : allowed) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(path + "/" + it.key(), "unknown key \"" + it.key() + "\" (expected one of: " + list + ")");
      }
    }
  }

  int64_t get_int(const json& v, const std::string& path, const std::string& what) const {
    if (v.is_number_integer()) {
      if (v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(INT64_MAX))
        fail(path, what + " is too large: " + v.dump());
      return v.get<int64_t>();
    }
    fail(path, "expected " + what + " (an integer), got " + v.dump());
  }

  double get_double(const json& v, const std::string& path, const std::string& what) const {
    if (v.is_number()) return v.get<double>();
    fail(path, "expected " + what + " (a number), got " + v.dump());
  }

  int64_t get_bound(const json& v, const std::string& path, bool is_upper) const {
    if (v.is_string()) {
      const std::string s = v.get<std::string>();
      if (s == "inf" || s == "+inf" || s == "infinity") return kInfinity;
      if (s == "-inf" || s == "-infinity") return -kInfinity;
    }
    if (v.is_number_integer()) return get_int(v, path, "a bound");
    fail(path, std::string("expected an integer or ") + (is_upper ? "\"inf\"" : "\"-inf\"") +
                   ", got " + v.dump());
  }

  void read_nodes(const json& root, Problem& p) {
    if (!root.contains("nodes")) fail("/nodes", "missing: expected an array of nodes");
    const json& nodes = root["nodes"];
    if (!nodes.is_array()) fail("/nodes", "expected an array of nodes, got " + nodes.dump());
    bool any_name = false;
    for (size_t v = 0; v < nodes.size(); ++v) {
      const std::string path = "/nodes/" + std::to_string(v);
      const json& node = nodes[v];
      if (!node.is_object()) fail(path, "expected a node object like {\"demand\": 0}, got " + node.dump());
      check_keys(node, path, {"demand", "name"});
      p.demand.push_back(node.contains("demand") ? get_int(node["demand"], path + "/demand", "a demand") : 0);
      std::string name;
      if (node.contains("name")) {
        if (!node["name"].is_string()) fail(path + "/name", "expected a string, got " + node["name"].dump());
        name = node["name"].get<std::string>();
        if (!name.empty() && !node_by_name_.emplace(name, static_cast<int>(v)).second)
          fail(path + "/name", "duplicate node name \"" + name + "\"");
        any_name = any_name || !name.empty();
      }
      p.node_name.push_back(std::move(name));
    }
    if (!any_name) p.node_name.clear();
  }

  End read_end(const json& end, const std::string& path, int n) const {
    if (!end.is_array() || end.size() != 2 || !end[1].is_string())
      fail(path, "expected an end [node, \"head\"|\"tail\"], got " + end.dump());
    int node = kNoNode;
    if (end[0].is_string()) {
      const auto it = node_by_name_.find(end[0].get<std::string>());
      if (it == node_by_name_.end()) fail(path + "/0", "unknown node name " + end[0].dump());
      node = it->second;
    } else {
      const int64_t id = get_int(end[0], path + "/0", "a node id or name");
      if (id < 0 || id >= n)
        fail(path + "/0", "node id " + std::to_string(id) + " is out of range [0, " + std::to_string(n) + ")");
      node = static_cast<int>(id);
    }
    const std::string side = end[1].get<std::string>();
    if (side != "head" && side != "tail")
      fail(path + "/1", "expected \"head\" or \"tail\", got " + end[1].dump());
    return End{node, side == "head"};
  }

  void read_edges(const json& root, Problem& p) {
    if (!root.contains("edges")) fail("/edges", "missing: expected an array of edges");
    const json& edges = root["edges"];
    if (!edges.is_array()) fail("/edges", "expected an array of edges, got " + edges.dump());
    bool any_name = false;
    std::vector<std::string> names;
    for (size_t e = 0; e < edges.size(); ++e) {
      const std::string path = "/edges/" + std::to_string(e);
      const json& edge = edges[e];
      if (!edge.is_object()) fail(path, "expected an edge object, got " + edge.dump());
      check_keys(edge, path, {"ends", "lower", "upper", "cost", "name"});
      if (!edge.contains("ends")) fail(path + "/ends", "missing: expected one or two ends");
      const json& ends = edge["ends"];
      if (!ends.is_array() || ends.empty() || ends.size() > 2)
        fail(path + "/ends", "expected an array of one or two ends, got " + ends.dump());
      const End a = read_end(ends[0], path + "/ends/0", p.num_nodes());
      std::optional<End> b;
      if (ends.size() == 2) b = read_end(ends[1], path + "/ends/1", p.num_nodes());
      const int64_t lo = edge.contains("lower") ? get_bound(edge["lower"], path + "/lower", false) : 0;
      const int64_t up = edge.contains("upper") ? get_bound(edge["upper"], path + "/upper", true) : kInfinity;
      Cost c = edge.contains("cost") ? read_cost(edge["cost"], path + "/cost", 0) : Cost::zero();
      p.add_edge(a, b, lo, up, std::move(c));
      std::string name;
      if (edge.contains("name")) {
        if (!edge["name"].is_string()) fail(path + "/name", "expected a string, got " + edge["name"].dump());
        name = edge["name"].get<std::string>();
        any_name = any_name || !name.empty();
      }
      names.push_back(std::move(name));
    }
    if (any_name) p.edge_name = std::move(names);
  }

  Cost read_cost(const json& c, const std::string& path, int depth) const {
    if (!c.is_object() || !c.contains("kind") || !c["kind"].is_string())
      fail(path, "expected a cost object with a \"kind\", got " + c.dump());
    const std::string kind_name = c["kind"].get<std::string>();
    const auto kind = cost_kind_from_name(kind_name);
    if (!kind)
      fail(path + "/kind", "unknown cost kind \"" + kind_name +
                               "\" (expected zero, linear, abs, asym_abs, quad, piecewise, scale_factor or sum)");
    auto num = [&](const char* key, std::optional<double> dflt = std::nullopt) {
      if (!c.contains(key)) {
        if (dflt) return *dflt;
        fail(path + "/" + key, std::string("missing: a ") + kind_name + " cost needs \"" + key + "\"");
      }
      return get_double(c[key], path + "/" + key, key);
    };
    switch (*kind) {
      case CostKind::Zero:
        check_keys(c, path, {"kind", "guess"});
        return Cost::zero(c.contains("guess") ? get_int(c["guess"], path + "/guess", "a guess") : 0);
      case CostKind::Linear:
        check_keys(c, path, {"kind", "slope"});
        return Cost::linear(num("slope"));
      case CostKind::AbsDeviation:
        check_keys(c, path, {"kind", "target", "weight"});
        return Cost::abs_deviation(num("target"), num("weight"));
      case CostKind::QuadDeviation:
        check_keys(c, path, {"kind", "target", "weight"});
        return Cost::quad_deviation(num("target"), num("weight"));
      case CostKind::AsymAbsDeviation:
        check_keys(c, path, {"kind", "target", "weight_below", "weight_above"});
        return Cost::asym_abs_deviation(num("target"), num("weight_below"), num("weight_above"));
      case CostKind::ScaleFactor:
        check_keys(c, path, {"kind", "target", "weight", "eps"});
        return Cost::scale_factor(num("target"), num("weight"), num("eps", 0.1));
      case CostKind::PiecewiseLinear: {
        check_keys(c, path, {"kind", "first", "values"});
        if (!c.contains("first")) fail(path + "/first", "missing: the integer where values start");
        const int64_t first = get_int(c["first"], path + "/first", "the first point");
        if (!c.contains("values") || !c["values"].is_array())
          fail(path + "/values", "expected an array of cost values at first, first+1, ...");
        std::vector<double> values;
        for (size_t i = 0; i < c["values"].size(); ++i)
          values.push_back(get_double(c["values"][i], path + "/values/" + std::to_string(i), "a cost value"));
        return Cost::piecewise_linear(first, std::move(values));
      }
      case CostKind::Sum: {
        check_keys(c, path, {"kind", "terms"});
        if (depth >= kMaxCostDepth)
          fail(path, "cost sums nested deeper than " + std::to_string(kMaxCostDepth));
        if (!c.contains("terms") || !c["terms"].is_array())
          fail(path + "/terms", "expected an array of cost terms");
        std::vector<Cost> terms;
        for (size_t i = 0; i < c["terms"].size(); ++i)
          terms.push_back(read_cost(c["terms"][i], path + "/terms/" + std::to_string(i), depth + 1));
        return Cost::sum(std::move(terms));
      }
    }
    fail(path, "unreachable cost kind");
  }

  std::string source_;
  std::unordered_map<std::string, int> node_by_name_;
};

json bound_json(int64_t v) {
  if (v == kInfinity) return "inf";
  if (v == -kInfinity) return "-inf";
  return v;
}

json cost_json(const Cost& c) {
  json j = {{"kind", cost_kind_name(c.kind())}};
  switch (c.kind()) {
    case CostKind::Zero:
      if (c.guess() != 0) j["guess"] = c.guess();
      break;
    case CostKind::Linear:
      j["slope"] = c.slope();
      break;
    case CostKind::AbsDeviation:
    case CostKind::QuadDeviation:
      j["target"] = c.target();
      j["weight"] = c.weight();
      break;
    case CostKind::AsymAbsDeviation:
      j["target"] = c.target();
      j["weight_below"] = c.weight_below();
      j["weight_above"] = c.weight_above();
      break;
    case CostKind::ScaleFactor:
      j["target"] = c.target();
      j["weight"] = c.weight();
      j["eps"] = c.eps();
      break;
    case CostKind::PiecewiseLinear:
      j["first"] = c.first();
      j["values"] = c.values();
      break;
    case CostKind::Sum:
      j["terms"] = json::array();
      for (const Cost& t : c.terms()) j["terms"].push_back(cost_json(t));
      break;
  }
  return j;
}

json end_json(const End& end) { return json::array({end.node, end.head ? "head" : "tail"}); }

json stat_json(const StatValue& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

}  // namespace

Problem parse_json_problem(std::string_view text, const std::string& source) {
  return JsonProblemReader(source).read(text);
}

std::string to_json_problem(const Problem& p) {
  // One node or edge per line: diff-friendly and compact for large networks.
  std::string out = "{\n  \"format\": \"bimdf-problem\",\n  \"version\": 1,\n  \"nodes\": [";
  for (int v = 0; v < p.num_nodes(); ++v) {
    json node = {{"demand", p.demand[v]}};
    if (!p.node_name.empty() && !p.node_name[v].empty()) node["name"] = p.node_name[v];
    out += (v ? ",\n    " : "\n    ") + node.dump();
  }
  out += p.num_nodes() ? "\n  ],\n  \"edges\": [" : "],\n  \"edges\": [";
  for (int e = 0; e < p.num_edges(); ++e) {
    json ends = json::array({end_json(p.end_a[e])});
    if (!p.is_outer(e)) ends.push_back(end_json(p.end_b[e]));
    json edge = {{"ends", ends},
                 {"lower", bound_json(p.lower[e])},
                 {"upper", bound_json(p.upper[e])},
                 {"cost", cost_json(p.cost[e])}};
    if (!p.edge_name.empty() && !p.edge_name[e].empty()) edge["name"] = p.edge_name[e];
    out += (e ? ",\n    " : "\n    ") + edge.dump();
  }
  out += p.num_edges() ? "\n  ]\n}\n" : "]\n}\n";
  return out;
}

std::string to_json_solution(const Solution& s) {
  json j;
  j["status"] = status_name(s.status);
  j["objective"] = std::isfinite(s.objective) ? json(s.objective) : json(nullptr);
  j["flow"] = s.flow;
  j["stats"] = json::object();
  for (const auto& [key, value] : s.stats) j["stats"][key] = stat_json(value);
  return j.dump(2) + "\n";
}

std::vector<int64_t> parse_flow(std::string_view text, const std::string& source) {
  const size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || (text[start] != '{' && text[start] != '[')) {
    detail::TextScanner scan(text, source);
    std::vector<int64_t> flow;
    while (!scan.at_end()) flow.push_back(scan.expect_int("flow value " + std::to_string(flow.size()) + " (an integer)"));
    return flow;
  }
  const json doc = JsonProblemReader::parse_document(text, source);
  const json* arr = &doc;
  std::string path;
  if (doc.is_object()) {
    if (!doc.contains("flow")) throw InputError(source, "/flow", "missing: expected the solution's flow array");
    arr = &doc["flow"];
    path = "/flow";
  }
  if (!arr->is_array()) throw InputError(source, path.empty() ? "/" : path, "expected an array of integers");
  std::vector<int64_t> flow;
  for (size_t i = 0; i < arr->size(); ++i) {
    const json& v = (*arr)[i];
    if (!v.is_number_integer() || (v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(INT64_MAX)))
      throw InputError(source, path + "/" + std::to_string(i), "expected an integer flow value, got " + v.dump());
    flow.push_back(v.get<int64_t>());
  }
  return flow;
}

}  // namespace bimdf
