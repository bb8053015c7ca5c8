// Turns a model-level ProblemIssue (from validate()) into an InputError that points into the
// file the problem came from: each reader supplies where node v and edge e were written.
#pragma once

#include <functional>
#include <string>

#include "bimdf/error.hpp"
#include "bimdf/problem.hpp"

namespace bimdf::detail {

// "edge 5 ('name')" / "node 3": how messages name an element.
std::string describe_node(const Problem& p, int v);
std::string describe_edge(const Problem& p, int e);

// Validates `p`; on an issue throws InputError(source, locate(issue), "<element>: <message>").
// Cost messages get a "cost: " prefix unless the location already names the field (JSON paths).
void validate_or_throw(const Problem& p, const std::string& source,
                       const std::function<std::string(const ProblemIssue&)>& locate,
                       bool location_names_field);

}  // namespace bimdf::detail
