// Every numeric option of every subcommand refuses what it cannot mean — NaN, infinities,
// out-of-range and non-integral values — with exit 2 and a message naming the option and the
// value; and a mesh without extent (all vertices at one point) is refused before any work.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"

namespace bimdf::testing {
namespace {

const std::string kProblem =
    std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf";
const std::string kLayout = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny.obj";

struct BadNumber {
  std::string args;     // after the subcommand and its input
  std::string message;  // the first line of stderr
};

using NumericOptions = CliFixture;

// `command` begins with the subcommand, whose help the message names.
void expect_refused(const CliRun& r, const std::string& command, const std::string& message) {
  const std::string subcommand = command.substr(0, command.find(' '));
  EXPECT_EQ(r.exit_code, 2) << command;
  EXPECT_EQ(r.err,
            "error: " + message + "\nRun 'bimdf " + subcommand + " --help' for the options.\n")
      << command;
}

TEST_F(NumericOptions, SolveRefusesMeaninglessNumbers) {
  const std::vector<BadNumber> cases = {
      {"--time-limit nan", "--time-limit: expected a positive number, got nan"},
      {"--time-limit inf", "--time-limit: expected a positive number, got inf"},
      {"--time-limit 0", "--time-limit: expected a positive number, got 0"},
      {"--time-limit -1", "--time-limit: expected a positive number, got -1"},
      {"--time-limit 2s", "--time-limit: expected a positive number, got 2s"},
      {"--max-rounds 0", "--max-rounds: expected a positive whole number, got 0"},
      {"--max-rounds 1.5", "--max-rounds: expected a positive whole number, got 1.5"},
      {"--threads 0", "--threads: expected a whole number from 1 to 256, got 0"},
      {"--max-deviation -1", "--max-deviation: expected a whole number from 0 to 1000, got -1"},
  };
  for (const BadNumber& c : cases) {
    const std::string command = "solve " + kProblem + " " + c.args;
    expect_refused(run(command), command, c.message);
  }
}

TEST_F(NumericOptions, QuantizeAndRemeshRefuseMeaninglessNumbers) {
  const std::vector<BadNumber> cases = {
      {"--scale 0", "--scale: expected a positive number, got 0"},
      {"--scale nan", "--scale: expected a positive number, got nan"},
      {"--scale inf", "--scale: expected a positive number, got inf"},
      {"--edge-length -1", "--edge-length: expected a positive number, got -1"},
      {"--target-faces 0", "--target-faces: expected a positive whole number, got 0"},
      {"--target-faces 1e3", "--target-faces: expected a positive whole number, got 1e3"},
      {"--alpha 1.5", "--alpha: expected a number from 0 to 1, got 1.5"},
      {"--alpha nan", "--alpha: expected a number from 0 to 1, got nan"},
      {"--align-weight -inf", "--align-weight: expected a number >= 0, got -inf"},
      {"--nonquad-weight -0.5", "--nonquad-weight: expected a number >= 0, got -0.5"},
      {"--unalign-weights 1,nan", "--unalign-weights: expected a number >= 0, got nan"},
      {"--time-limit nan", "--time-limit: expected a positive number, got nan"},
      {"--threads 300", "--threads: expected a whole number from 1 to 256, got 300"},
  };
  for (const char* subcommand : {"quantize", "remesh"})
    for (const BadNumber& c : cases) {
      const std::string command = std::string(subcommand) + " " + kLayout + " " + c.args;
      expect_refused(run(command), command, c.message);
    }
  const std::vector<BadNumber> smoothing = {
      {"--smooth-damping nan", "--smooth-damping: expected a number from 0 to 1, got nan"},
      {"--smooth-iterations -1",
       "--smooth-iterations: expected a whole number from 0 to 100000, got -1"},
  };
  for (const BadNumber& c : smoothing) {
    const std::string command = "remesh " + kLayout + " " + c.args;
    expect_refused(run(command), command, c.message);
  }
}

TEST_F(NumericOptions, RequantizeRenderGenerateRefuseMeaninglessNumbers) {
  const std::string quads = path("quads.obj");
  { std::ofstream(quads) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"; }
  const std::vector<BadNumber> cases = {
      {"--scale -2", "--scale: expected a positive number, got -2"},
      {"--edge-length nan", "--edge-length: expected a positive number, got nan"},
      {"--target-faces -5", "--target-faces: expected a positive whole number, got -5"},
      {"--max-angle 91", "--max-angle: expected a number from 0 to 90, got 91"},
      {"--sharp-angle inf", "--sharp-angle: expected a number from 0 to 180, got inf"},
      {"--relaxed --relaxed-weight 0", "--relaxed-weight: expected a positive number, got 0"},
      {"--threads nan", "--threads: expected a whole number from 1 to 256, got nan"},
      {"--smooth-damping 2", "--smooth-damping: expected a number from 0 to 1, got 2"},
  };
  for (const BadNumber& c : cases) {
    const std::string command = "requantize " + quads + " -o " + path("out.obj") + " " + c.args;
    expect_refused(run(command), command, c.message);
  }
  const std::vector<BadNumber> render = {
      {"--width 0", "--width: expected a whole number from 16 to 8192, got 0"},
      {"--height 1e4", "--height: expected a whole number from 16 to 8192, got 1e4"},
      {"--view 1,nan,0", "--view: expected a finite number, got nan"},
  };
  for (const BadNumber& c : render) {
    const std::string command = "render " + quads + " -o " + path("out.png") + " " + c.args;
    expect_refused(run(command), command, c.message);
  }
  const std::string command = "generate random --size 0";
  expect_refused(run(command), command,
                 "--size: expected a whole number from 1 to 100000000, got 0");
  EXPECT_FALSE(fs::exists(path("out.obj")));
  EXPECT_FALSE(fs::exists(path("out.png")));
}

// Rewrites every `v` line of `obj` to one point.
std::string collapse_vertices(const std::string& obj) {
  std::istringstream in(obj);
  std::string line, out;
  while (std::getline(in, line)) out += (line.rfind("v ", 0) == 0 ? "v 1 2 3" : line) + "\n";
  return out;
}

TEST_F(NumericOptions, MeshWithoutExtentIsRefused) {
  const std::string expected =
      ": all vertices are at the same position (every edge has length 0), expected a surface\n";
  // A QuadWild layout: OBJ, .patch and .corners side by side.
  const std::string stem = std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny/npm_bunny";
  const std::string layout = write("point.obj", collapse_vertices(slurp(stem + ".obj")));
  write("point.patch", slurp(stem + ".patch"));
  write("point.corners", slurp(stem + ".corners"));
  for (const std::string args : {"", " --edge-length 1", " --target-faces 100"}) {
    for (const char* subcommand : {"quantize ", "remesh "}) {
      const std::string out = std::string(subcommand) == "remesh " ? " -o " + path("out.obj") : "";
      const CliRun r = run(subcommand + layout + out + args);
      EXPECT_EQ(r.exit_code, 2) << subcommand << args;
      EXPECT_EQ(r.err, "error: " + layout + expected) << subcommand << args;
    }
    const std::string quads =
        write("point_quads.obj",
              collapse_vertices(
                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n"));
    const CliRun r = run("requantize " + quads + " -o " + path("out.obj") + args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, "error: " + quads + expected) << args;
  }
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

}  // namespace
}  // namespace bimdf::testing
