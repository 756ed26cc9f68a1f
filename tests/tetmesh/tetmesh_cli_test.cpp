// `molmesh tetmesh` end to end on a surface file: outputs in every format, --stats JSON,
// a bad output name rejected with exit code 2 before any work, and fas2 at B = -2 (where
// TetGen once crashed) meshed or refused cleanly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

TEST(CliTetmesh, SurfaceFileToEveryFormatWithStats) {
  const fs::path dir = testing::test_dir();
  const std::string surf = (dir / "ion.off").string();
  write_surface_mesh(surf, icosphere(Vec3(1, 1, 1), 3.0, 2));
  { std::ofstream(dir / "site.txt") << "1 1 4 1.6\n"; }
  for (const char* ext : {".m", ".vtu", ".msh", ".msh4"}) {
    const std::string out = (dir / (std::string("ion") + ext)).string();
    ASSERT_EQ(testing::run_cli("-q tetmesh " + surf +
                               " --domain exterior --outer-radius 15 --active-site " +
                               (dir / "site.txt").string() + " -o " + out + " --stats " +
                               (dir / "stats.json").string())
                  .exit_code,
              0)
        << ext;
    EXPECT_GT(fs::file_size(out), 1000u);
  }
  std::ifstream in(dir / "stats.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["domain"], "exterior");
  EXPECT_GT(j["tetrahedra"].get<int>(), 100);
  EXPECT_GT(j["min_volume"].get<double>(), 0.0);
  EXPECT_EQ(j["tetgen"]["surface_steiner_points"], 0);
  EXPECT_EQ(j["tetgen"]["outer_radius"], 15.0);
  EXPECT_GT(j["faces_per_marker"]["3"].get<int>(), 0);
  EXPECT_EQ(j["tetrahedra_per_region"].size(), 1u);
  const TetMesh back = read_mcsf(dir / "ion.m");
  EXPECT_EQ(back.tetrahedra.size(), j["tetrahedra"].get<std::size_t>());

  EXPECT_EQ(
      testing::run_cli("-q tetmesh " + surf + " --outer-radius 15 -o " + (dir / "x.xyz").string())
          .exit_code,
      2);
  EXPECT_FALSE(fs::exists(dir / "x.xyz"));
  EXPECT_EQ(testing::run_cli("-q tetmesh " + surf + " --domain inside -o " + (dir / "x.m").string())
                .exit_code,
            2);
  // A single surface with no atoms but ratio sizing works; an enclosed-too-small sphere fails.
  EXPECT_EQ(
      testing::run_cli("-q tetmesh " + surf + " --outer-radius 2 -o " + (dir / "y.m").string())
          .exit_code,
      1);
  fs::remove_all(dir);
}

TEST(CliTetmesh, Fas2AtBlobbyness2IsNoCrash) {
  // Issue 18's reproducer: TetGen died with SIGSEGV (double free in its cleanup).
  const auto dir = testing::test_dir();
  const auto r = testing::run_cli("-q " + std::string("tetmesh ") + MOLMESH_TEST_DATA_DIR +
                                  "/fas2.pqr --surface gaussian --blobbyness -2 --domain full -o " +
                                  (dir / "f.m").string());
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.exit_code << " " << r.err;
  if (r.exit_code != 0) {
    EXPECT_NE(r.err.find("molmesh: error:"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "f.m"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
