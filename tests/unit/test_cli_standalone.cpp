// `bimdf remesh` on a bare triangle mesh (issue 51): the whole pipeline through the program,
// --info, --layout-out, and the refusals with their messages.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_fixture.hpp"
#include "surface_fixtures.hpp"

namespace bimdf {
namespace {

using testing::CliFixture;
namespace fs = std::filesystem;

std::string obj_text(const TriangleMesh& m) {
  std::ostringstream s;
  s.precision(17);
  for (const auto& v : m.vertices) s << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  for (const auto& f : m.faces) s << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  return s.str();
}

class StandaloneCli : public CliFixture {};

TEST_F(StandaloneCli, CubeBecomesSixRegularGridsWithItsEightCorners) {
  const std::string cube = write("cube.obj", obj_text(test::cube(6)));
  const auto r = run("remesh " + cube + " -o " + path("out.obj") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["input"]["triangles"], 6 * 6 * 6 * 2);
  EXPECT_EQ(j["input"]["sharp_edges"], 12 * 6);
  EXPECT_EQ(j["input"]["feature_corners"], 8);
  EXPECT_EQ(j["layout"]["patches"], 6);
  EXPECT_EQ(j["layout"]["traced_along"], "parametrization");  // exact on flat faces: no fold
  EXPECT_EQ(j["layout"]["folded_faces"], 0);
  // One layout per default pairing radius, 1 and 1.25, and one with fewer lines at radius 1.
  EXPECT_EQ(j["layout"]["candidates"], 3);
  EXPECT_EQ(j["field"]["singularities"], 8);
  const auto& m = j["metrics"];
  EXPECT_EQ(m["manifold"], true);
  EXPECT_EQ(m["boundary_edges"], 0);
  EXPECT_EQ(m["euler_characteristic"], 2);
  EXPECT_EQ(m["inverted"], 0);
  EXPECT_EQ(m["singular_vertices"], 8);
  EXPECT_EQ(m["interior_singularities"]["3"], 8);
  EXPECT_GT(m["scaled_jacobian"]["min"].get<double>(), 0.99);  // six flat grids
  for (const char* stage :
       {"read_s", "field_s", "parametrization_s", "trace_s", "cut_s", "patches_s", "total_s"})
    EXPECT_TRUE(j["time"].contains(stage)) << stage;
}

TEST_F(StandaloneCli, OnePairingRadiusAndNoSpareOneMakeOneLayout) {
  const std::string cube = write("cube.obj", obj_text(test::cube(6)));
  const auto r =
      run("remesh " + cube + " -o " + path("out.obj") + " --json --pairing-radii 0.5 --no-spare");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["layout"]["candidates"], 1);
  EXPECT_EQ(j["layout"]["pairing_radius"], 0.5);
  EXPECT_EQ(j["layout"]["spare"], false);
  EXPECT_EQ(j["metrics"]["singular_vertices"], 8);
  const auto spare = run("remesh " + cube + " -o " + path("spare.obj") +
                         " --json --pairing-radii 0.5 --spare-radii 1,2");
  ASSERT_EQ(spare.exit_code, 0) << spare.err;
  EXPECT_EQ(nlohmann::json::parse(spare.out)["layout"]["candidates"], 3);
  const auto both =
      run("remesh " + cube + " -o " + path("both.obj") + " --no-spare --spare-radii 1");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(both.err,
            "error: --spare-radii excludes --no-spare\n"
            "Run 'bimdf remesh --help' for the options.\n");
  const auto bad_spare = run("remesh " + cube + " -o " + path("bad.obj") + " --spare-radii x");
  EXPECT_EQ(bad_spare.exit_code, 2);
  EXPECT_EQ(bad_spare.err,
            "error: --spare-radii: expected a number from 0 to 100, got x\n"
            "Run 'bimdf remesh --help' for the options.\n");
  const auto bad = run("remesh " + cube + " -o " + path("bad.obj") + " --pairing-radii 1,-2");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err,
            "error: --pairing-radii: expected a number from 0 to 100, got -2\n"
            "Run 'bimdf remesh --help' for the options.\n");
  EXPECT_FALSE(fs::exists(path("bad.obj")));
}

TEST_F(StandaloneCli, InfoDescribesTheInputAndWritesNothing) {
  const std::string square = write("sq.obj", obj_text(test::square(1, 4)));
  const auto r = run("remesh " + square + " --info");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
            "input         " + square +
                ": 32 triangles, 25 vertices; 1 component (1 of genus 0), 1 border loop; 0 sharp "
                "edges, 4 feature corners");
  EXPECT_NE(r.out.find("cross field   0 singularities inside; index sum 1 = Euler characteristic"),
            std::string::npos)
      << r.out;
}

TEST_F(StandaloneCli, LayoutOutWritesQuadwildFilesTheReaderTakes) {
  const std::string cube = write("cube.obj", obj_text(test::cube(3)));
  const auto r =
      run("remesh " + cube + " -o " + path("out.obj") + " --layout-out " + path("lay.obj"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto q = run("quantize " + path("lay.obj") + " --json");
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_EQ(nlohmann::json::parse(q.out)["charts"], 6);
}

TEST_F(StandaloneCli, BadMeshesAreRefusedAndNothingIsWritten) {
  const std::string fin = write("fin.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
  auto r = run("remesh " + fin + " -o " + path("out.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: " + fin +
                       ": the mesh edge between vertices 0 and 1 has 3 faces, expected at most 2 "
                       "(non-manifold)\n");
  EXPECT_FALSE(fs::exists(path("out.obj")));
  const std::string empty = write("empty.off", "OFF\n0 0 0\n");
  r = run("remesh " + empty + " -o " + path("out.obj"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "error: " + empty + ": the mesh has no faces, expected a triangle or polygon mesh\n");
  r = run("remesh " + fin);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "error: --output is required\nRun 'bimdf remesh --help' for the options.\n");
}

}  // namespace
}  // namespace bimdf
