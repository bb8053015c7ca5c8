// The exception bimdf throws for invalid input: a malformed or inconsistent file, or a problem
// that breaks a rule of the model. Its message is complete and meant for the user, e.g.
//   "net.bimdf:12: edge 9: lower bound 3 is greater than upper bound 1"
// and the location is also available field by field for tools.
#pragma once

#include <stdexcept>
#include <string>

namespace bimdf {

class InputError : public std::runtime_error {
 public:
  // `source`: file name (or "<stdin>", "<string>"); `location`: "line 12" style position or a
  // JSON path ("/edges/3/cost/weight"), may be empty; `what`: the description.
  InputError(std::string source, std::string location, std::string what);

  const std::string& source() const { return source_; }
  const std::string& location() const { return location_; }
  const std::string& description() const { return description_; }

 private:
  std::string source_;
  std::string location_;
  std::string description_;
};

// The description of an InputError for a mesh whose vertices all coincide: no edge length to
// derive a density from, and nothing to parametrize.
inline constexpr char kCoincidentVertices[] =
    "all vertices are at the same position (every edge has length 0), expected a surface";

}  // namespace bimdf
