// The CLI contract that scripts depend on: exit codes, --json on stdout, -o files written whole
// or not at all, inputs never overwritten, errors on stderr naming file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using Cli = bimdf::testing::CliFixture;
using bimdf::testing::CliRun;

const std::string kExample =
    std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf";
// Two nodes joined by a head-head edge (x0, target 2) and a tail-tail loop at node 1 (x1):
// node 0: x0 = 2, node 1: x0 - 2·x1 = 0 -> x1 = 1.
const std::string kSmall = "# small\n2\n2\n0\n2\n0 1 1 1 0 inf A 2 1\n1 1 0 0 0 5 Q 0 0.5\n";

TEST_F(Cli, InfoPrintsSummary) {
  const CliRun r = run("info " + kExample);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("nodes         672 (0 with non-zero demand, total demand 0)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("edges         1796"), std::string::npos);
  EXPECT_NE(r.out.find("costs         zero 329, abs 917, quad 550"), std::string::npos);
  EXPECT_TRUE(r.err.empty());
}

TEST_F(Cli, InfoJsonOnStdoutAndInFile) {
  const CliRun r = run("info --json -o " + path("info.json") + " " + kExample);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["nodes"], 672);
  EXPECT_EQ(j["edges"], 1796);
  EXPECT_EQ(j["edge_kinds"]["loop -2"], 397);
  EXPECT_EQ(j["cost_kinds"]["quad"], 550);
  EXPECT_EQ(j["components"], 2);
  EXPECT_EQ(json::parse(slurp(path("info.json"))), j);
}

TEST_F(Cli, CheckFeasibleAndInfeasibleFlows) {
  const std::string problem = write("small.bimdf", kSmall);
  const CliRun ok = run("check --json " + problem + " " + write("good.txt", "2 1\n"));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const json j = json::parse(ok.out);
  EXPECT_EQ(j["feasible"], true);
  EXPECT_EQ(j["objective"], 0.5);

  const CliRun bad = run("check " + problem + " " + write("bad.json", "[3, 9]"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("edge 1: flow 9 is outside its bounds [0, 5]\n"), std::string::npos)
      << bad.out;
  EXPECT_NE(bad.out.find("node 0: net flow 3 differs from its demand 2\n"), std::string::npos);
  EXPECT_NE(bad.out.find("node 1: net flow -15 differs from its demand 0\n"), std::string::npos);
  EXPECT_NE(
      bad.out.find("infeasible flow: 1 bound and 2 conservation violations, objective 41.5\n"),
      std::string::npos);
}

TEST_F(Cli, CheckRejectsFlowOfWrongLength) {
  const std::string problem = write("small.bimdf", kSmall);
  const std::string flow = write("short.txt", "2\n");
  const CliRun r = run("check " + problem + " " + flow);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + flow + ": the flow has 1 values but the problem " + problem +
                       " has 2 edges\n");
}

TEST_F(Cli, InvalidInputExitsTwoWithFileAndLine) {
  const std::string bad = write("bad.bimdf", "# t\n2\n0\n0\n1\n0 1 1 0 4 1 0\n");
  for (const char* cmd : {"info", "convert"}) {
    const CliRun r = run(std::string(cmd) + " " + bad);
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_EQ(r.err, "error: " + bad + ":6: edge 0: lower bound 4 is greater than upper bound 1\n")
        << cmd;
  }
  const CliRun c = run("check " + bad + " " + write("f.txt", "0"));
  EXPECT_EQ(c.exit_code, 2);
  const CliRun missing = run("info " + path("nope.bimdf"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err,
            "error: " + path("nope.bimdf") + ": cannot open file: No such file or directory\n");
}

TEST_F(Cli, UsageErrorsExitTwoHelpExitsZero) {
  // Usage errors read like input errors and name the help of the subcommand they concern.
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"", "error: A subcommand is required\nRun 'bimdf --help' for the options.\n"},
      {"frobnicate",
       "error: unknown subcommand 'frobnicate'\nRun 'bimdf --help' for the options.\n"},
      {"--bogus",
       "error: unknown option '--bogus' (expected a subcommand)\nRun 'bimdf --help' for the "
       "options.\n"},
      {"info", "error: PROBLEM is required\nRun 'bimdf info --help' for the options.\n"},
      {"info --bogus " + kExample,
       "error: The following argument was not expected: --bogus\nRun 'bimdf info --help' for "
       "the options.\n"},
      {"remesh " + kExample,
       "error: --output is required\nRun 'bimdf remesh --help' for the options.\n"},
  };
  for (const auto& [args, message] : refused) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, message) << args;
  }
  const CliRun help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Exit codes: 0 success"), std::string::npos);
  for (const char* cmd : {"info", "check", "convert"})
    EXPECT_EQ(run(std::string(cmd) + " --help").exit_code, 0) << cmd;
  // The usage line names the program as the hints above do, not by the path it was run from.
  EXPECT_NE(run("solve --help").out.find("\nUsage: bimdf solve [OPTIONS] PROBLEM\n"),
            std::string::npos);
  const CliRun version = run("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("bimdf ", 0), 0u);
}

TEST_F(Cli, NoPartialOutputOnError) {
  const std::string bad = write("bad.bimdf", "# t\n2\n0\n0\n1\n0 1 1 0 0 1 A 1\n");
  EXPECT_EQ(run("info -o " + path("out.json") + " " + bad).exit_code, 2);
  EXPECT_EQ(run("convert -o " + path("out.json") + " " + bad).exit_code, 2);
  EXPECT_FALSE(fs::exists(path("out.json")));
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
}

TEST_F(Cli, NeverOverwritesAnInput) {
  const std::string problem = write("small.bimdf", kSmall);
  const CliRun r = run("convert " + problem + " -o " + problem);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: output file " + problem + " is the input file " + problem +
                       "; refusing to overwrite an input\n");
  EXPECT_EQ(slurp(problem), kSmall);
  EXPECT_EQ(run("info -o " + problem + " " + problem).exit_code, 2);
  EXPECT_EQ(slurp(problem), kSmall);
}

TEST_F(Cli, ConvertRoundTrip) {
  const std::string problem = write("small.bimdf", kSmall);
  ASSERT_EQ(run("convert " + problem + " -o " + path("small.json")).exit_code, 0);
  EXPECT_EQ(json::parse(slurp(path("small.json")))["format"], "bimdf-problem");
  ASSERT_EQ(run("convert " + path("small.json") + " --to bimdf -o " + path("back.bimdf")).exit_code,
            0);
  const CliRun a = run("info --json " + problem), b = run("info --json " + path("back.bimdf"));
  json ja = json::parse(a.out), jb = json::parse(b.out);
  ja.erase("file");
  jb.erase("file");
  EXPECT_EQ(ja, jb);
  // libSatsuma-compatible output of the example reads back identically.
  ASSERT_EQ(run("convert --libsatsuma " + kExample + " -o " + path("ex.bimdf")).exit_code, 0);
  EXPECT_EQ(run("convert --libsatsuma " + path("ex.bimdf") + " -o " + path("ex2.bimdf")).exit_code,
            0);
  EXPECT_EQ(slurp(path("ex.bimdf")), slurp(path("ex2.bimdf")));
  // Something libSatsuma cannot read is refused with the user's file named.
  const std::string outer = write("outer.bimdf", "1\n0\n1\n0 -1 1 - 0 1 0\n");
  const CliRun refused = run("convert --libsatsuma " + outer + " -o " + path("o.bimdf"));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "error: " + outer +
                             ": edge 0: outer edges (a single end) cannot be written in "
                             "libSatsuma-compatible .bimdf\n");
}

}  // namespace
