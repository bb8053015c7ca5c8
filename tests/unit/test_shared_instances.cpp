// Every real instance in ../shared/data/instances loads, with the sizes its README lists, and
// survives a libSatsuma-compatible write and re-read unchanged. The bundled example always runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bimdf/io.hpp"
#include "bimdf/summary.hpp"

namespace bimdf {
namespace {

namespace fs = std::filesystem;

struct Expected {
  std::string file;
  int nodes, edges;
};

std::vector<Expected> read_expected(const fs::path& tsv) {
  std::vector<Expected> rows;
  std::ifstream in(tsv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream s(line);
    Expected e;
    if (s >> e.file >> e.nodes >> e.edges) rows.push_back(e);
  }
  return rows;
}

void expect_round_trip(const Problem& p, const std::string& name) {
  BimdfWriteOptions compatible;
  compatible.libsatsuma_compatible = true;
  EXPECT_EQ(parse_bimdf(to_bimdf(p, compatible), name), p) << name;
  EXPECT_EQ(parse_json_problem(to_json_problem(p), name), p) << name;
}

TEST(SharedInstances, AllLoadWithTheirListedSizes) {
  const fs::path dir = fs::path(BIMDF_SHARED_DATA_DIR) / "instances";
  if (!fs::exists(dir / "expected.tsv"))
    GTEST_SKIP() << "shared data not found at " << dir << " (a clone without ../shared)";
  const std::vector<Expected> expected = read_expected(dir / "expected.tsv");
  ASSERT_GE(expected.size(), 60u);
  int bimdf_files = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    bimdf_files += entry.path().extension() == ".bimdf";
  EXPECT_EQ(static_cast<size_t>(bimdf_files), expected.size()) << "expected.tsv lists every file";
  for (const Expected& e : expected) {
    SCOPED_TRACE(e.file);
    const Problem p = read_problem_file((dir / e.file).string());
    EXPECT_EQ(p.num_nodes(), e.nodes);
    EXPECT_EQ(p.num_edges(), e.edges);
    const ProblemSummary s = summarize(p);
    EXPECT_EQ(s.parity_infeasible_components, 0);
    // The README: only cost kinds 0, A, Q occur.
    EXPECT_EQ(s.cost_kinds[static_cast<int>(CostKind::Zero)] +
                  s.cost_kinds[static_cast<int>(CostKind::AbsDeviation)] +
                  s.cost_kinds[static_cast<int>(CostKind::QuadDeviation)],
              e.edges);
    expect_round_trip(p, e.file);
  }
}

TEST(SharedInstances, BundledExampleLoads) {
  const fs::path file = fs::path(BIMDF_EXAMPLES_DIR) / "npm_bunny__flow_noalign_lemon_0.bimdf";
  const Problem p = read_problem_file(file.string());
  EXPECT_EQ(p.num_nodes(), 672);
  EXPECT_EQ(p.num_edges(), 1796);
  expect_round_trip(p, file.string());
}

}  // namespace
}  // namespace bimdf
