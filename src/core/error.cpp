#include "bimdf/error.hpp"

namespace bimdf {
namespace {

// "file:12: what" for line numbers, "file: /json/path: what" for JSON paths, "file: what"
// without a location: the first form is what compilers print, so editors can jump to it.
std::string format_message(const std::string& source, const std::string& location,
                           const std::string& what) {
  if (location.empty()) return source + ": " + what;
  if (location.front() == '/') return source + ": " + location + ": " + what;
  return source + ":" + location + ": " + what;
}

}  // namespace

InputError::InputError(std::string source, std::string location, std::string what)
    : std::runtime_error(format_message(source, location, what)),
      source_(std::move(source)),
      location_(std::move(location)),
      description_(std::move(what)) {}

}  // namespace bimdf
