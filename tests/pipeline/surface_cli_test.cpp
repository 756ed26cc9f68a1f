// The `surface` and `stats` commands, run as a user would.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = molmesh::testing::test_dir();
  ~TempDir() { fs::remove_all(path); }
};

TEST(SurfaceCli, WritesMeshAndStatsJson) {
  TempDir dir;
  const fs::path off = dir.path / "fas2.off";
  const fs::path json = dir.path / "fas2.json";
  ASSERT_EQ(molmesh::testing::run_cli("-q surface " + std::string(MOLMESH_TEST_DATA_DIR) +
                                      "/fas2.pqr --surface gaussian -o " + off.string() +
                                      " --raw --stats " + json.string())
                .exit_code,
            0);
  ASSERT_TRUE(fs::exists(off));
  std::ifstream in(json);
  const nlohmann::json doc = nlohmann::json::parse(in);
  const std::set<std::string> required = {"vertices",
                                          "triangles",
                                          "min_angle_deg",
                                          "max_angle_deg",
                                          "angle_histogram_percent",
                                          "fraction_angles_40_80",
                                          "area",
                                          "volume",
                                          "components",
                                          "euler_characteristic",
                                          "closed",
                                          "manifold",
                                          "timings_s",
                                          "input",
                                          "parameters",
                                          "levelset_distance_mean",
                                          "levelset_distance_max",
                                          "centroid_distance_mean",
                                          "centroid_distance_max"};
  // The keys must all be there; processing adds dislocation and per-stage stats.
  for (const auto& key : required) EXPECT_TRUE(doc.contains(key)) << key;
  EXPECT_TRUE(doc["closed"].get<bool>());
  EXPECT_TRUE(doc["manifold"].get<bool>());
  EXPECT_GT(doc["volume"].get<double>(), 0.0);
  EXPECT_EQ(doc["angle_histogram_percent"].size(), 18u);
  // Marching cubes puts the vertices on the grid's linear interpolant of Eq. 1 along the
  // edges: a small fraction of the 0.5 Å spacing from the exact level set.
  for (const char* key : {"levelset_distance_mean", "levelset_distance_max",
                          "centroid_distance_mean", "centroid_distance_max"}) {
    ASSERT_TRUE(doc[key].is_number()) << key;
    EXPECT_TRUE(std::isfinite(doc[key].get<double>())) << key;
    EXPECT_GE(doc[key].get<double>(), 0.0) << key;
  }
  EXPECT_LT(doc["levelset_distance_mean"].get<double>(), 0.02);
  EXPECT_LT(doc["levelset_distance_max"].get<double>(), 0.1);
  EXPECT_LE(doc["levelset_distance_mean"].get<double>(),
            doc["levelset_distance_max"].get<double>());
  double percent = 0.0;
  for (const auto& v : doc["angle_histogram_percent"]) percent += v.get<double>();
  EXPECT_NEAR(percent, 100.0, 1e-6);
  for (const char* stage : {"read", "blur", "marching cubes", "write", "total"})
    EXPECT_TRUE(doc["timings_s"].contains(stage)) << stage;
  EXPECT_EQ(doc["parameters"]["spacing"].get<double>(), 0.5);

  // `stats --json` on the written mesh agrees with the --stats file.
  const auto stats_json = molmesh::testing::run_cli("stats --json " + off.string());
  ASSERT_EQ(stats_json.exit_code, 0);
  const nlohmann::json again = nlohmann::json::parse(stats_json.out);
  EXPECT_EQ(again["vertices"], doc["vertices"]);
  EXPECT_EQ(again["triangles"], doc["triangles"]);
  EXPECT_EQ(again["euler_characteristic"], doc["euler_characteristic"]);
  EXPECT_NEAR(again["area"].get<double>(), doc["area"].get<double>(),
              1e-6 * doc["area"].get<double>());
  const auto stats = molmesh::testing::run_cli("stats " + off.string());
  ASSERT_EQ(stats.exit_code, 0);
  EXPECT_NE(stats.out.find("manifold"), std::string::npos);
}

TEST(SurfaceCli, ExitCodes) {
  TempDir dir;
  const std::string data = MOLMESH_TEST_DATA_DIR;
  EXPECT_EQ(molmesh::testing::run_cli("surface " + data + "/missing.pqr -o " +
                                      (dir.path / "x.off").string())
                .exit_code,
            2);
  EXPECT_EQ(molmesh::testing::run_cli("surface " + data + "/fas2.pqr -o " +
                                      (dir.path / "x.off").string() + " --blobbyness 0.5")
                .exit_code,
            2);
  const fs::path bad = dir.path / "bad.pqr";
  std::ofstream(bad) << "ATOM      1  N   ALA     1      nonsense\n";
  EXPECT_EQ(
      molmesh::testing::run_cli("surface " + bad.string() + " -o " + (dir.path / "x.off").string())
          .exit_code,
      3);
  EXPECT_EQ(molmesh::testing::run_cli("surface " + data + "/1a1p.pqr -o " +
                                      (dir.path / "x.unknown").string())
                .exit_code,
            2);
  EXPECT_EQ(molmesh::testing::run_cli("surface " + data + "/1a1p.pqr --raw -o " +
                                      (dir.path / "no_such_dir" / "x.off").string())
                .exit_code,
            4);
  EXPECT_FALSE(fs::exists(dir.path / "x.off"));
}

// A processed surface whose angles processing could not bring into a usable range is still
// written, but with a warning that says so and what to change; a good one gets none.
TEST(SurfaceCli, WarnsWhenTheProcessedSurfaceHasDegenerateAngles) {
  TempDir dir;
  const std::string fas2 = std::string(MOLMESH_TEST_DATA_DIR) + "/fas2.pqr";
  const fs::path json = dir.path / "poor.json";
  // B = -4 on a 1 A grid: features finer than the grid (0.21 to 171.5 degrees).
  const auto poor = molmesh::testing::run_cli(
      "-q surface " + fas2 + " --surface gaussian --blobbyness -4 --spacing 1.0 -o " +
      (dir.path / "poor.off").string() + " --stats " + json.string());
  ASSERT_EQ(poor.exit_code, 0) << poor.err;
  EXPECT_NE(poor.err.find("warning: the processed surface has angles from"), std::string::npos)
      << poor.err;
  EXPECT_NE(poor.err.find("finer grid spacing"), std::string::npos) << poor.err;
  std::ifstream in(json);
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_LT(doc["min_angle_deg"].get<double>(), 5.0);

  const auto good =
      molmesh::testing::run_cli("-q surface " + fas2 + " --surface gaussian --spacing 1.0 -o " +
                                (dir.path / "good.off").string());
  ASSERT_EQ(good.exit_code, 0) << good.err;
  EXPECT_EQ(good.err.find("warning"), std::string::npos) << good.err;
}

}  // namespace
