// `bimdf solve`: the solution JSON (status, objective, flow, stats), exit codes 0/1/2, -o files,
// the human report, --progress, and that the written flow passes `bimdf check`.
#include <elf.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using CliSolve = bimdf::testing::CliFixture;
using bimdf::testing::CliRun;

const std::string kExample =
    std::string(BIMDF_EXAMPLES_DIR) + "/npm_bunny__flow_noalign_lemon_0.bimdf";
// x0 on a head–head edge between nodes 0 and 1 (target 2), x1 on a tail–tail loop at node 1:
// node 0 needs x0 = 2, node 1 then needs 2·x1 = 2.
const std::string kSmall = "# small\n2\n2\n0\n2\n0 1 1 1 0 inf A 2 1\n1 1 0 0 0 5 Q 0 0.5\n";

TEST_F(CliSolve, JsonSolutionOnStdout) {
  const CliRun r = run("solve --approx --json " + write("small.bimdf", kSmall));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "feasible");
  EXPECT_EQ(j["flow"], json::array({2, 1}));
  EXPECT_EQ(j["objective"], 0.5);
  EXPECT_EQ(j["stats"]["approximation_path"], "tjoin+asymmetric (1 component)");
  EXPECT_EQ(j["stats"]["solver"], "approximate");
  EXPECT_TRUE(j["stats"]["time_total_s"].is_number());
}

TEST_F(CliSolve, ExactByDefault) {
  const CliRun r = run("solve --json " + write("small.bimdf", kSmall));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "optimal");
  EXPECT_EQ(j["flow"], json::array({2, 1}));
  EXPECT_EQ(j["objective"], 0.5);
  EXPECT_EQ(j["stats"]["solver"], "exact");
  EXPECT_LE(j["stats"]["lower_bound"].get<double>(), 0.5);
  EXPECT_GE(j["stats"]["approximate_objective"].get<double>(), 0.5);
}

TEST_F(CliSolve, ExactOnTheBundledExampleMatchesTheKnownOptimum) {
  const CliRun r = run("solve --threads 2 " + kExample);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // ../shared/data/instances/README.md: optimum 0.886439270.
  EXPECT_EQ(r.out.rfind("status        optimal\nobjective     0.88643927", 0), 0u) << r.out;
  const CliRun limited = run("solve --json --max-rounds 1 " + kExample);
  ASSERT_EQ(limited.exit_code, 0);
  EXPECT_EQ(json::parse(limited.out)["status"], "feasible");
}

// The program re-executes itself once to get huge pages (apps/bimdf/memory_setup.cpp), unless
// every file it is given is under 256 KiB: with the tunable unset, switched off, on, or beside
// another tunable, on the example (no re-exec) and on a copy padded with comments to 300 KiB
// (re-exec), it answers the same, and its arguments survive the re-exec (a usage error still
// exits 2).
TEST_F(CliSolve, HugePageReexecLeavesResultsUnchanged) {
  std::ifstream example(kExample);
  const std::string text((std::istreambuf_iterator<char>(example)), {});
  const std::string padded =
      write("padded.bimdf", std::string(300 << 10, ' ').replace(0, 1, "#") + "\n" + text);
  json first;
  for (const std::string& input : {kExample, padded})
    for (const std::string env :
         {"env -u GLIBC_TUNABLES", "env GLIBC_TUNABLES=glibc.malloc.hugetlb=0",
          "env GLIBC_TUNABLES=glibc.malloc.perturb=0",
          "env GLIBC_TUNABLES=glibc.malloc.hugetlb=1"}) {
      const CliRun r = run("solve --json " + input, env);
      ASSERT_EQ(r.exit_code, 0) << env << " " << input << ": " << r.err;
      const json j = json::parse(r.out);
      if (first.is_null()) first = j;
      EXPECT_EQ(j["status"], "optimal") << env << " " << input;
      EXPECT_EQ(j["flow"], first["flow"]) << env << " " << input;
      EXPECT_EQ(j["objective"], first["objective"]) << env << " " << input;
    }
  for (const std::string& input : {kExample, padded}) {
    const CliRun bad = run("solve --matching foo " + input, "env -u GLIBC_TUNABLES");
    EXPECT_EQ(bad.exit_code, 2) << input;
    EXPECT_NE(bad.err.find("--matching: foo not in {blossom,lemon,persistent}"), std::string::npos)
        << bad.err;
  }
}

// The program is linked statically where the build could (CMakeLists.txt: BIMDF_STATIC_CLI;
// a small solve's process then takes about half the time, docs/benchmarks.md), else
// dynamically: an ELF program header of type PT_INTERP names the dynamic loader.
TEST_F(CliSolve, ProgramIsLinkedAsConfigured) {
  std::ifstream program(BIMDF_CLI_PATH, std::ios::binary);
  Elf64_Ehdr header{};
  ASSERT_TRUE(program.read(reinterpret_cast<char*>(&header), sizeof header));
  ASSERT_EQ(std::string(reinterpret_cast<const char*>(header.e_ident), 4),
            "\x7f"
            "ELF");
  ASSERT_EQ(header.e_phentsize, sizeof(Elf64_Phdr));
  bool interpreter = false;
  for (int i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr segment{};
    program.seekg(static_cast<std::streamoff>(header.e_phoff + i * sizeof segment));
    ASSERT_TRUE(program.read(reinterpret_cast<char*>(&segment), sizeof segment));
    interpreter = interpreter || segment.p_type == PT_INTERP;
  }
  EXPECT_EQ(interpreter, !BIMDF_CLI_STATIC) << BIMDF_CLI_PATH;
}

TEST_F(CliSolve, WritesSolutionFileThatCheckAccepts) {
  const std::string out = path("bunny.solution.json");
  const CliRun r = run("solve --approx -o " + out + " " + kExample);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("status        feasible (approximation)\nobjective     ", 0), 0u) << r.out;
  const json j = json::parse(slurp(out));
  EXPECT_EQ(j["flow"].size(), 1796u);
  const CliRun check = run("check --json " + kExample + " " + out);
  ASSERT_EQ(check.exit_code, 0) << check.out;
  EXPECT_EQ(json::parse(check.out)["objective"], j["objective"]);
}

TEST_F(CliSolve, InfeasibleExitsOneWithReason) {
  // Demand 1 at a node whose only edge is a head–head loop.
  const std::string p = write("odd.bimdf", "# odd\n1\n1\n1\n0 0 1 1 0 inf A 0 1\n");
  const CliRun r = run("solve --approx " + p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("status        infeasible\nreason        parity: node 0 belongs"),
            std::string::npos)
      << r.out;
  const CliRun j = run("solve --approx --json " + p);
  EXPECT_EQ(j.exit_code, 1);
  const json s = json::parse(j.out);
  EXPECT_EQ(s["status"], "infeasible");
  EXPECT_TRUE(s["objective"].is_null());
  EXPECT_EQ(s["flow"], json::array());
}

TEST_F(CliSolve, UsageAndInputErrorsExitTwo) {
  const std::string p = write("small.bimdf", kSmall);
  EXPECT_EQ(run("solve --threads 0 " + p).exit_code, 2);
  EXPECT_EQ(run("solve --time-limit -1 " + p).exit_code, 2);
  EXPECT_EQ(run("solve --approx --max-deviation -1 " + p).exit_code, 2);
  EXPECT_EQ(run("solve --approx --parity bogus " + p).exit_code, 2);
  const std::string bad = write("bad.bimdf", "# t\n1\n0\n1\n0 0 1 0 0 1 A 0 1\n");
  const CliRun r = run("solve --approx " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + bad +
                       ":5: edge 0: head-tail loop at node 0 has no effect on conservation; "
                       "expected head-head or tail-tail\n");
  // Never over an input.
  EXPECT_EQ(run("solve --approx -o " + p + " " + p).exit_code, 2);
  EXPECT_EQ(slurp(p), kSmall);
}

TEST_F(CliSolve, EveryOptionCombinationGivesAVerifiedFlow) {
  for (const char* opts : {"--parity round-to-even", "--cover symmetric", "--max-deviation 0",
                           "--no-simplify", "-v"}) {
    const CliRun r = run(std::string("solve --approx --json ") + opts + " " + kExample);
    ASSERT_EQ(r.exit_code, 0) << opts << r.err;
    const std::string sol = write("s.json", r.out);
    EXPECT_EQ(run("check " + kExample + " " + sol).exit_code, 0) << opts;
  }
}

}  // namespace

namespace {

TEST_F(CliSolve, GenerateWritesDeterministicSolvableInstances) {
  const std::string a = path("a.bimdf"), b = path("b.json");
  ASSERT_EQ(run("generate quadwild --size 600 --seed 4 -o " + a).exit_code, 0);
  ASSERT_EQ(run("generate quadwild --size 600 --seed 4 -o " + b).exit_code, 0);
  // The same problem in both formats: converting one gives the other's text.
  EXPECT_EQ(run("convert --to json " + a).out, slurp(b));
  const CliRun solved = run("solve --json " + a);
  ASSERT_EQ(solved.exit_code, 0) << solved.err;
  EXPECT_EQ(json::parse(solved.out)["status"], "optimal");
  EXPECT_EQ(run("generate grid --size 10").exit_code, 2);
  EXPECT_EQ(run("generate random --size 0").exit_code, 2);
}

// --progress: on stderr, per component its approximation and then every refinement round, the
// last one proving optimality; the objectives add up to the result's, stdout is unchanged, and
// --approx (no rounds to report) excludes it.
TEST_F(CliSolve, ProgressLinesOnStderr) {
  const CliRun plain = run("solve --json " + kExample);
  const CliRun r = run("solve --json --progress " + kExample);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["flow"], json::parse(plain.out)["flow"]);
  const std::regex approximation(
      R"(progress [0-9]+\.[0-9]{3} s: component ([0-9]+) of 2: approximation, objective (\S+))");
  const std::regex round(
      R"(progress [0-9]+\.[0-9]{3} s: component ([0-9]+) of 2: round ([0-9]+), objective (\S+) )"
      R"(\((lowered|no improvement: optimal)\))");
  std::istringstream lines(r.err);
  std::string line;
  std::map<int, int64_t> rounds_of;
  std::map<int, double> last_objective;
  std::map<int, bool> proven;
  double approximate_sum = 0;
  int64_t rounds = 0;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, m, approximation)) {
      const int c = std::stoi(m[1]);
      EXPECT_EQ(rounds_of.count(c), 0u) << line;
      rounds_of[c] = 0;
      approximate_sum += std::stod(m[2]);
      last_objective[c] = std::stod(m[2]);
    } else if (std::regex_match(line, m, round)) {
      const int c = std::stoi(m[1]);
      ASSERT_EQ(rounds_of.count(c), 1u) << "a round before its approximation: " << line;
      EXPECT_FALSE(proven[c]) << "a round after the proof: " << line;
      EXPECT_EQ(std::stoll(m[2]), ++rounds_of[c]) << line;
      last_objective[c] = std::stod(m[3]);
      proven[c] = m[4] == "no improvement: optimal";
      ++rounds;
    } else {
      ADD_FAILURE() << "unexpected line on stderr: " << line;
    }
  }
  ASSERT_EQ(rounds_of.size(), 2u) << r.err;
  EXPECT_TRUE(proven[1] && proven[2]) << r.err;
  EXPECT_NEAR(approximate_sum, j["stats"]["approximate_objective"].get<double>(), 1e-9);
  EXPECT_NEAR(last_objective[1] + last_objective[2], j["objective"].get<double>(), 1e-9);
  EXPECT_EQ(rounds, j["stats"]["refinement_rounds"].get<int64_t>());

  const CliRun bad = run("solve --approx --progress " + kExample);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--approx excludes --progress"), std::string::npos) << bad.err;
}

}  // namespace
