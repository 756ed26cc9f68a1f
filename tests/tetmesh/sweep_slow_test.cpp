// The TetGen sweep of issue 18: `tetmesh` and `hierarchy` over blobbyness -0.3 ... -4 and
// spacing 0.3 ... 1.0 on every molecule in tests/data end with exit code 0 or a clear error
// (exit 1 and a "molmesh: error:" line), never a signal. Before tetgen_terminate.cpp and the
// untangling step, fas2 at B = -2 died with SIGSEGV.
//
// The grid is chosen to fit ~3 minutes on 2 cores: the full 4 x 3 grid on 1a1p (small:
// seconds per run), the extreme and middle values on fas2, and the two extreme blobbyness
// values at the coarsest spacing on mAChE (each mAChE run costs ~20 s). `hierarchy` runs
// the corners of the grid on 1a1p and the fas2 case that crashed. The whole grid (every
// molecule file, domain and command) is tests/tetmesh/tetgen_full_sweep.sh, run by hand
// (docs/testing.md, "TetGen sweep").
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

void expect_clean_end(const std::string& command) {
  const auto r = testing::run_cli("-q " + command);
  EXPECT_EQ(r.signal, 0) << command << "\n" << r.err;
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << command << ": exit " << r.exit_code << "\n"
                                                    << r.err;
  if (r.exit_code == 1) {
    EXPECT_NE(r.err.find("molmesh: error:"), std::string::npos) << r.err;
  }
}

struct Case {
  const char* molecule;
  std::vector<double> blobbyness;
  std::vector<double> spacing;
};

TEST(TetgenSweep, TetmeshNeverDiesOfASignal) {
  const auto dir = testing::test_dir();
  const Case cases[] = {
      {"1a1p", {-0.3, -1.0, -2.0, -4.0}, {0.3, 0.6, 1.0}},
      {"fas2", {-0.3, -2.0, -4.0}, {0.6, 1.0}},
      {"mache", {-0.3, -4.0}, {1.0}},
  };
  for (const auto& c : cases)
    for (double b : c.blobbyness)
      for (double h : c.spacing)
        expect_clean_end("tetmesh " + std::string(MOLMESH_TEST_DATA_DIR) + "/" + c.molecule +
                         ".pqr --surface gaussian --blobbyness " + std::to_string(b) +
                         " --spacing " + std::to_string(h) + " --domain full -o " +
                         (dir / "m.m").string());
  fs::remove_all(dir);
}

// Finding 2 named every domain: the fas2 case that crashed, at the default spacing, on the
// interior and exterior domains too (the full one is CliTetmesh.Fas2AtBlobbyness2IsNoCrash).
TEST(TetgenSweep, Fas2AtBlobbyness2MeshesInteriorAndExterior) {
  const auto dir = testing::test_dir();
  for (const char* domain : {"interior", "exterior"}) {
    const std::string command = "-q tetmesh " + std::string(MOLMESH_TEST_DATA_DIR) +
                                "/fas2.pqr --surface gaussian --blobbyness -2 --domain " + domain +
                                " -o " + (dir / "m.m").string();
    const auto r = testing::run_cli(command);
    EXPECT_EQ(r.signal, 0) << command << "\n" << r.err;
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.err;
    EXPECT_GT(fs::file_size(dir / "m.m"), 100000u) << command;
  }
  fs::remove_all(dir);
}

TEST(TetgenSweep, HierarchyNeverDiesOfASignal) {
  const auto dir = testing::test_dir();
  const Case cases[] = {
      {"1a1p", {-0.3, -4.0}, {0.3, 1.0}},
      {"fas2", {-2.0}, {0.5}},
  };
  for (const auto& c : cases)
    for (double b : c.blobbyness)
      for (double h : c.spacing)
        expect_clean_end("hierarchy " + std::string(MOLMESH_TEST_DATA_DIR) + "/" + c.molecule +
                         ".pqr --surface gaussian --blobbyness " + std::to_string(b) +
                         " --spacing " + std::to_string(h) + " --t0 0.2,0.4 -o " +
                         (dir / "h.h5").string());
  fs::remove_all(dir);
}

// The sweep's one hierarchy refusal that was a processing defect (session 27): mAChE at
// B = -2 on a 0.6 Å grid, whose level 1 (T0 = 0.4) crossed itself in 7 triangle pairs, so
// every domain exited 1. The last poor triangles' collapse (processing/poor_triangle_collapse)
// removes the crossing; the surface is the same for every domain, so the cheapest one runs.
TEST(TetgenSweep, MacheAtBlobbyness2OnA06Grid_HierarchyMeshesEveryLevel) {
  const auto dir = testing::test_dir();
  const std::string command =
      "-q hierarchy " + std::string(MOLMESH_TEST_DATA_DIR) +
      "/mache.pqr --surface gaussian --blobbyness -2 --spacing 0.6 --domain interior "
      "--t0 0.2,0.4 -o " +
      (dir / "h.h5").string();
  const auto r = testing::run_cli(command);
  EXPECT_EQ(r.signal, 0) << command << "\n" << r.err;
  EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.err;
  EXPECT_TRUE(fs::exists(dir / "h.h5")) << command;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
