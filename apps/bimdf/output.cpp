#include "output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace bimdf::cli {

namespace fs = std::filesystem;

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

}  // namespace bimdf::cli
