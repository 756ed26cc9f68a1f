// Option values are range-checked (issue 18, finding 11) and resource limits enforced: NaN,
// inf and absurd magnitudes are exit code 2 naming the option; requests whose grid or mesh
// would exceed --max-memory stop at once (exit 1) saying how much they would need.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path path = testing::test_dir();
  ~Scratch() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

const std::string kData = MOLMESH_TEST_DATA_DIR;

TEST(OptionRanges, NonFiniteAndAbsurdValuesAreUsageErrorsNamingTheOption) {
  const Scratch dir;
  write_surface_mesh(dir / "ion.off", icosphere(Vec3::Zero(), 3.0, 2));
  const std::string ion = dir / "ion.off";
  const std::string fas2 = kData + "/fas2.pqr";
  const std::pair<std::string, std::string> cases[] = {
      {"tetmesh " + ion + " --outer-radius 1e300 -o " + (dir / "t.m"), "--outer-radius"},
      {"tetmesh " + ion + " --outer-radius nan -o " + (dir / "t.m"), "--outer-radius"},
      {"tetmesh " + ion + " --min-dihedral nan -o " + (dir / "t.m"), "--min-dihedral"},
      {"tetmesh " + ion + " --size-factor inf -o " + (dir / "t.m"), "--size-factor"},
      {"surface " + fas2 + " --min-cavity-volume nan -o " + (dir / "s.off"), "--min-cavity-volume"},
      {"surface " + fas2 + " --spacing nan -o " + (dir / "s.off"), "--spacing"},
      {"surface " + fas2 + " --isovalue -inf -o " + (dir / "s.off"), "--isovalue"},
      // In the CLI's range (a volume's level may be negative) but not for atoms: the library
      // refuses it once the input is known, and that is a bad option value too.
      {"surface " + fas2 + " --isovalue -1 -o " + (dir / "s.off"), "--isovalue"},
      {"tetmesh " + fas2 + " --isovalue 0 -o " + (dir / "t.m"), "--isovalue"},
      {"surface " + fas2 + " --max-memory nan -o " + (dir / "s.off"), "--max-memory"},
      {"surface " + fas2 + " -o " + (dir / "s.xyz"), "--output"},
      {"tetmesh " + ion + " -o " + (dir / "t.xyz"), "--output"},
      {"hierarchy " + fas2 + " -o " + (dir / "h.xyz"), "--output"},
      {"hierarchy " + fas2 + " --outer-radius nan -o " + (dir / "h.h5"), "--outer-radius"},
      {"hierarchy " + fas2 + " --spacing nan -o " + (dir / "h.h5"), "--spacing"},
      {"hierarchy " + fas2 + " --t0 0.1,nan -o " + (dir / "h.h5"), "--t0"},
  };
  for (const auto& [command, option] : cases) {
    const auto r = testing::run_cli("-q " + command);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << command << "\n" << r.err;
  }
  for (const char* name : {"t.m", "s.off", "s.xyz", "t.xyz", "h.xyz", "h.h5"})
    EXPECT_FALSE(fs::exists(dir.path / name)) << name;
}

TEST(OptionRanges, OversizedGridsAndMeshesStopAtOnceWithTheMemoryTheyNeed) {
  const Scratch dir;
  write_surface_mesh(dir / "ion.off", icosphere(Vec3::Zero(), 3.0, 2));
  {
    std::ofstream far(dir / "far.pqr");
    far << "ATOM      1  C   ALA     1       0.000   0.000   0.000  0.00 1.70\n"
        << "ATOM      2  C   ALA     1  100000.000 100000.000 100000.000  0.00 1.70\n";
  }
  const std::pair<std::string, std::string> cases[] = {
      // --size-factor 1e-3 ran for more than a minute on this surface.
      {"tetmesh " + (dir / "ion.off") + " --domain interior --size-factor 1e-3 -o " + (dir / "t.m"),
       "--size-factor"},
      {"tetmesh " + (dir / "ion.off") + " --domain interior --max-volume 1e-9 -o " + (dir / "t.m"),
       "--max-volume"},
      {"surface " + (dir / "far.pqr") + " --raw -o " + (dir / "s.off"), "--spacing"},
      {"surface " + kData + "/fas2.pqr --spacing 0.01 --raw -o " + (dir / "s.off"), "--spacing"},
      {"surface " + kData + "/fas2.pqr --max-memory 0.001 --raw -o " + (dir / "s.off"),
       "--max-memory"},
      // The distance fields are held to the same limit (they ignored it: a 22 GB grid was
      // allocated for two atoms 700 Å apart).
      {"surface " + (dir / "far.pqr") + " --surface ses --raw -o " + (dir / "s.off"), "--spacing"},
      {"surface " + (dir / "far.pqr") + " --surface vdw --raw -o " + (dir / "s.off"), "--spacing"},
      {"surface " + kData + "/fas2.pqr --surface sas --max-memory 0.001 --raw -o " +
           (dir / "s.off"),
       "--max-memory"},
  };
  for (const auto& [command, hint] : cases) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = testing::run_cli("-q " + command);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 1) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("would need"), std::string::npos) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(hint), std::string::npos) << command << "\n" << r.err;
    // ... and which input it was about (issue 18, finding 12).
    const std::string input = command.substr(
        command.find(' ') + 1, command.find(' ', command.find(' ') + 1) - command.find(' ') - 1);
    EXPECT_NE(r.err.find(input + ": "), std::string::npos) << command << "\n" << r.err;
    EXPECT_LT(seconds, 30.0) << command;
  }
}

}  // namespace
}  // namespace molmesh
