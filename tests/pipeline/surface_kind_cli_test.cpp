// --surface and --probe-radius as a user runs them: the Gaussian kind reproduces the paper's
// pipeline byte for byte, the distance-field kinds nest (vdW inside SES inside SAS), stats
// and hierarchy files say which surface they hold, and `hierarchy` takes the shared atom
// and surface options (with its documented --t0).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = testing::test_dir();
  ~TempDir() { fs::remove_all(path); }
};

const std::string k1a1p = std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr";

TEST(SurfaceKindCli, GaussianReproducesThePaperPipelineByteForByte) {
  TempDir dir;
  const fs::path cli = dir.path / "cli.off", lib = dir.path / "lib.off";
  // Without the projection onto Eq. 1 (which a grid input has no atoms for), the Gaussian kind
  // is the paper's path.
  ASSERT_EQ(testing::run_cli(
                "-q surface " + k1a1p +
                " --surface gaussian --blobbyness -0.5 --isovalue 1 --no-keep-on-surface -o " +
                cli.string())
                .exit_code,
            0);
  // The paper's path written out without the surface-kind dispatch: Eq. 1 on the grid, then
  // contouring and processing at the library's processing defaults.
  const Atoms atoms = read_atoms(k1a1p);
  BlurOptions blur;
  blur.blobbyness = -0.5;
  blur.isovalue = 1.0;
  SurfacePipelineOptions options;
  options.isovalue = 1.0;
  write_surface_mesh(lib, surface_from_grid(blur_atoms(atoms, blur), options).surface);
  const std::string a = testing::slurp(cli), b = testing::slurp(lib);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the gaussian surface differs from Eq. 1 contoured directly";
}

TEST(SurfaceKindCli, DistanceSurfacesNestAndStatsSayWhichSurface) {
  TempDir dir;
  double volume[3];
  const char* kinds[3] = {"vdw", "ses", "sas"};
  for (int k = 0; k < 3; ++k) {
    const fs::path json = dir.path / (std::string(kinds[k]) + ".json");
    const testing::CliRun surface = testing::run_cli(
        "-q surface " + k1a1p + " --surface " + kinds[k] + " --probe-radius 1.4 -o " +
        (dir.path / "s.off").string() + " --stats " + json.string());
    ASSERT_EQ(surface.exit_code, 0) << surface.output();
    std::ifstream in(json);
    const nlohmann::json doc = nlohmann::json::parse(in);
    EXPECT_EQ(doc["parameters"]["surface"], kinds[k]);
    EXPECT_EQ(doc["parameters"]["probe_radius"], 1.4);
    EXPECT_TRUE(doc["closed"].get<bool>() && doc["manifold"].get<bool>());
    EXPECT_GT(doc["area"].get<double>(), 0.0);
    volume[k] = doc["volume"].get<double>();
  }
  EXPECT_LT(volume[0], volume[1]);
  EXPECT_LT(volume[1], volume[2]);
  const testing::CliRun bogus = testing::run_cli("-q surface " + k1a1p + " --surface bogus -o " +
                                                 (dir.path / "x.off").string());
  EXPECT_EQ(bogus.exit_code, 2) << bogus.output();
  const testing::CliRun negative = testing::run_cli(
      "-q surface " + k1a1p + " --probe-radius -1 -o " + (dir.path / "x.off").string());
  EXPECT_EQ(negative.exit_code, 2) << negative.output();
}

TEST(SurfaceKindCli, HierarchyTakesTheSharedOptionsAndInfoNamesTheSurface) {
  TempDir dir;
  const fs::path h5 = dir.path / "h.h5";
  const fs::path radii = dir.path / "radii.txt";
  testing::write_file(radii, "* 1.60\n");
  const testing::CliRun hierarchy =
      testing::run_cli("-q hierarchy " + k1a1p + " --surface vdw --coarsen 0.3 --domain interior " +
                       "--no-hetatm --radii " + radii.string() + " -o " + h5.string());
  ASSERT_EQ(hierarchy.exit_code, 0) << hierarchy.output();
  const testing::CliRun info = testing::run_cli("info " + h5.string());
  const std::string out = info.output();
  ASSERT_EQ(info.exit_code, 0) << out;
  EXPECT_NE(out.find("surface: vdw"), std::string::npos) << out;
  EXPECT_NE(out.find("hetatm                     no"), std::string::npos) << out;
  EXPECT_NE(out.find("t0                         0.3"), std::string::npos) << out;
  const testing::CliRun raw =
      testing::run_cli("-q hierarchy " + k1a1p + " --raw -o " + h5.string());
  EXPECT_EQ(raw.exit_code, 2) << raw.output();
}

}  // namespace
}  // namespace molmesh
