// The shared QuadWild layouts (../shared/data/layouts) and their reference results, for the
// quantizer's and the remesher's tests. A clone without ../shared skips those tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace bimdf::testing {

inline const std::filesystem::path kLayouts =
    std::filesystem::path(BIMDF_SHARED_DATA_DIR) / "layouts";

// One row of ../shared/data/layouts/README.md's reference table (optima with the digits of
// expected.tsv).
struct Reference {
  std::string mesh;
  int patches = 0;
  double noalign_opt = 0, noalign_iso = 0, noalign_reg = 0;
  double align_opt = 0, align_iso = 0, align_reg = 0, align_energy = 0;
  int aligned = 0, pairs = 0;
  int noalign_quads = 0, align_quads = 0;  // faces of the quad mesh the reference wrote
};

std::vector<Reference> references();

inline std::string layout_path(const std::string& mesh) {
  return (kLayouts / mesh / (mesh + ".obj")).string();
}

}  // namespace bimdf::testing

#define REQUIRE_SHARED_LAYOUTS()                                             \
  if (!std::filesystem::exists(bimdf::testing::kLayouts / "expected.tsv"))   \
  GTEST_SKIP() << "shared layouts not found at " << bimdf::testing::kLayouts \
               << " (a clone without ../shared)"
