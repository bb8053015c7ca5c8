// A test fixture that runs the bimdf CLI in a scratch directory and captures exit code,
// stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace bimdf::testing {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code;
  std::string out, err;
};

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("bimdf_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

  static std::string slurp(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // `environment`, if given, prefixes the command (e.g. "env -u GLIBC_TUNABLES").
  CliRun run(const std::string& args, const std::string& environment = "") const {
    const std::string cmd = (environment.empty() ? "" : environment + " ") +
                            std::string(BIMDF_CLI_PATH) + " " + args + " >" + path("stdout") +
                            " 2>" + path("stderr");
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(path("stdout")),
            slurp(path("stderr"))};
  }

  fs::path dir_;
};

}  // namespace bimdf::testing
