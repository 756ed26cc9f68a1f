// `molmesh improve` end to end on a real molecular surface handed over the way other tools
// write meshes: an STL triangle soup, an MSMS pair, and an open mesh that must be refused.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "molmesh/io/msms.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;

CliRun molmesh(const std::string& args) { return testing::run_cli("--quiet " + args); }

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

const SurfaceMesh& raw_1a1p() {
  static const SurfaceMesh m =
      marching_cubes(blur_atoms(read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr"), BlurOptions{}), 1.0);
  return m;
}

TEST(ImproveCli, StlSoupComesOutClosedManifoldAndBetter) {
  const fs::path in = testing::test_dir() / "1a1p.stl";
  const fs::path out = testing::test_dir() / "1a1p_improved.ply";
  const fs::path stats = testing::test_dir() / "1a1p_improved.json";
  write_surface_mesh(in, raw_1a1p());
  const CliRun r =
      molmesh("improve " + in.string() + " -o " + out.string() + " --stats " + stats.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = read_json(stats);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_TRUE(j["manifold"].get<bool>());
  const auto raw = compute_surface_stats(raw_1a1p());
  EXPECT_EQ(j["input"]["input_surface"]["vertices"].get<std::size_t>(), raw.vertices);
  EXPECT_LT(j["vertices"].get<std::size_t>(), raw.vertices);
  EXPECT_GT(j["min_angle_deg"].get<double>(), raw.min_angle_deg);
  EXPECT_LT(j["max_angle_deg"].get<double>(), raw.max_angle_deg);
  EXPECT_GT(j["fraction_angles_40_80"].get<double>(), raw.fraction_angles_40_80);
  EXPECT_LT(j["dislocation_mean"].get<double>(), 0.1);
  // The file on disk is what the stats describe.
  const SurfaceStats written = compute_surface_stats(read_surface_mesh(out));
  EXPECT_EQ(written.vertices, j["vertices"].get<std::size_t>());
  EXPECT_GT(written.volume, 0.0);
}

TEST(ImproveCli, MsmsPairInvertedInputIsTurnedOutward) {
  SurfaceMesh inverted = raw_1a1p();
  for (Triangle& t : inverted.triangles) std::swap(t[1], t[2]);
  const fs::path stem = testing::test_dir() / "1a1p_msms";
  write_msms(stem, inverted);
  const fs::path out = testing::test_dir() / "1a1p_msms_improved.off";
  const fs::path stats = testing::test_dir() / "1a1p_msms_improved.json";
  const CliRun r = molmesh("improve " + stem.string() + ".vert -o " + out.string() +
                           " --no-coarsen --stats " + stats.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("components turned outward"), std::string::npos) << r.err;
  const nlohmann::json j = read_json(stats);
  EXPECT_EQ(j["input"]["repair"]["reoriented_components"].get<int>(), 1);
  EXPECT_EQ(j["vertices"].get<std::size_t>(), compute_surface_stats(raw_1a1p()).vertices);
  EXPECT_GT(j["volume"].get<double>(), 0.0);
}

TEST(ImproveCli, OpenMeshIsRefusedWithCountsAndLocations) {
  SurfaceMesh open = raw_1a1p();
  open.triangles.erase(open.triangles.begin() + 100);
  open.triangles.erase(open.triangles.begin() + static_cast<long>(open.triangles.size() / 2));
  const fs::path in = testing::test_dir() / "open.off";
  write_surface_mesh(in, open);
  const fs::path out = testing::test_dir() / "open_improved.off";
  fs::remove(out);
  const CliRun r = molmesh("improve " + in.string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("2 holes (6 edges used by only one triangle), e.g. at ("), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(ImproveCli, UnknownFormatIsAnInputError) {
  const fs::path in = testing::test_dir() / "mesh.xyz";
  std::ofstream(in) << "1 2 3\n";
  const CliRun r =
      molmesh("improve " + in.string() + " -o " + (testing::test_dir() / "x.off").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
}

}  // namespace
}  // namespace molmesh
