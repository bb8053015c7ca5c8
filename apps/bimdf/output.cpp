#include "output.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace bimdf::cli {

namespace fs = std::filesystem;

void add_output_options(CLI::App* cmd, OutputOptions& out) {
  cmd->add_flag("--json", out.json, "Print the result as JSON on stdout");
  cmd->add_option("-o,--output", out.file, "Write the result JSON to this file");
}

void deliver(const OutputOptions& out, const std::string& human, const std::string& json_text,
             const std::vector<std::string>& inputs) {
  if (!out.file.empty()) write_output_file(out.file, json_text, inputs);
  std::cout << (out.json ? json_text : human);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string ms(double seconds, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f ms", decimals, seconds * 1e3);
  return buf;
}

std::string significant(double v, int significant_digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

std::string shortest_decimal(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

void write_output_file(const std::string& path, const std::string& content,
                       const std::vector<std::string>& inputs) {
  std::error_code ec;
  for (const std::string& in : inputs)
    if (fs::exists(path, ec) && fs::equivalent(path, in, ec))
      throw UsageError{"output file " + path + " is the input file " + in +
                       "; refusing to overwrite an input"};
  if (fs::is_directory(path, ec)) throw UsageError{"output path " + path + " is a directory"};

  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw UsageError{"cannot write " + path + ": " + std::strerror(errno)};
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  const int saved_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    std::remove(tmp.c_str());
    throw UsageError{"cannot write " + path + ": " + std::strerror(saved_errno)};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw UsageError{"cannot write " + path + ": " + std::strerror(err)};
  }
}

void print_stage(double elapsed_s, const std::string& stage, const std::string& detail) {
  char head[48];
  std::snprintf(head, sizeof head, "progress %.3f s: ", elapsed_s);
  std::cerr << head << stage << ": " << detail << std::endl;
}

}  // namespace bimdf::cli
