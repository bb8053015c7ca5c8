// Format detection and file access shared by every reader.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bimdf/io.hpp"

namespace bimdf {

ProblemFormat detect_problem_format(std::string_view text) {
  const size_t start = text.find_first_not_of(" \t\r\n");
  return start != std::string_view::npos && text[start] == '{' ? ProblemFormat::Json
                                                               : ProblemFormat::Bimdf;
}

Problem parse_problem(std::string_view text, const std::string& source) {
  return detect_problem_format(text) == ProblemFormat::Json ? parse_json_problem(text, source)
                                                            : parse_bimdf(text, source);
}

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "", "is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot open file: ") + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "read error");
  return s.str();
}

Problem read_problem_file(const std::string& path) { return parse_problem(read_text_file(path), path); }

std::vector<int64_t> read_flow_file(const std::string& path) { return parse_flow(read_text_file(path), path); }


}  // namespace bimdf
