#include "report_issue.hpp"

namespace bimdf::detail {

std::string describe_node(const Problem& p, int v) {
  std::string s = "node " + std::to_string(v);
  if (v >= 0 && static_cast<size_t>(v) < p.node_name.size() && !p.node_name[v].empty())
    s += " ('" + p.node_name[v] + "')";
  return s;
}

std::string describe_edge(const Problem& p, int e) {
  std::string s = "edge " + std::to_string(e);
  if (e >= 0 && static_cast<size_t>(e) < p.edge_name.size() && !p.edge_name[e].empty())
    s += " ('" + p.edge_name[e] + "')";
  return s;
}

void validate_or_throw(const Problem& p, const std::string& source,
                       const std::function<std::string(const ProblemIssue&)>& locate,
                       bool location_names_field) {
  const auto issue = validate(p);
  if (!issue) return;
  std::string element;
  switch (issue->where) {
    case ProblemIssue::Where::Node:
      element = describe_node(p, issue->index) + ": ";
      break;
    case ProblemIssue::Where::Edge:
      element = describe_edge(p, issue->index) + ": ";
      break;
    case ProblemIssue::Where::Problem:
      break;
  }
  // Cost messages name the parameter, which reads better after the field name.
  const std::string field = issue->field == "cost" && !location_names_field ? "cost: " : "";
  throw InputError(source, locate(*issue), element + field + issue->message);
}

}  // namespace bimdf::detail
