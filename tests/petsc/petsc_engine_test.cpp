// molmesh-petsc against the built-in solver through the commands a user runs: the same
// rate constant and solvation energy (1e-6 relative) on 1 and 2 MPI ranks, iteration
// counts flat across 2-5 levels, and PETSc's MatLoad reading `molmesh export`'s
// prolongations.
#include <gtest/gtest.h>
#include <petscmat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "molmesh/io/hierarchy_hdf5.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

class PetscEngine : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = testing::test_dir();
    testing::write_file(dir_ / "sphere.pqr",
                        "ATOM      1  NA  ION     1       0.000   0.000   0.000  1.0000 10.0\n");
    testing::write_file(dir_ / "born.pqr",
                        "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00\n");
    // Five levels, so 2..5 of them can be used.
    sphere_status_ = cli("hierarchy " + path("sphere.pqr") + " -o " + path("sphere.h5") +
                         " --domain exterior --outer-radius 50 --t0 0.1,0.3,0.5,0.7,0.9");
    born_status_ = cli("hierarchy " + path("born.pqr") + " -o " + path("born.h5") +
                       " --domain full --outer-radius 20");
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static int cli(const std::string& args) { return testing::run_cli("-q " + args).exit_code; }
  // Runs `command` writing JSON to `name`; returns the parsed JSON (empty on failure).
  static nlohmann::json run_json(const std::string& command, const std::string& name) {
    const std::string full = command + " --no-fields --json " + path(name);
    const testing::CommandRun run = testing::run_command(full);
    if (run.exit_code != 0) {
      ADD_FAILURE() << full << "\n" << run.output();
      return {};
    }
    std::ifstream in(path(name));
    return nlohmann::json::parse(in);
  }
  // CI runs as root on 2 cores: mpirun needs both flags there.
  static std::string petsc(int ranks) {
    std::string command = MOLMESH_MPIEXEC;
    command += " --oversubscribe --allow-run-as-root -n ";
    command += std::to_string(ranks);
    command += " ";
    command += MOLMESH_PETSC_PATH;
    command += " -q ";
    return command;
  }
  static inline fs::path dir_;
  static inline int sphere_status_ = -1, born_status_ = -1;
};

TEST_F(PetscEngine, SameRateAsTheBuiltInSolverOnOneAndTwoRanks) {
  ASSERT_EQ(sphere_status_, 0);
  const std::string args = "smoluchowski " + path("sphere.h5");
  const auto builtin = run_json(std::string(MOLMESH_CLI_PATH) + " -q solve " + args, "b.json");
  ASSERT_FALSE(builtin.is_null());
  const double k = builtin["rate_constant_M-1s-1"].get<double>();
  for (int ranks : {1, 2}) {
    const auto j = run_json(petsc(ranks) + args, "p" + std::to_string(ranks) + ".json");
    ASSERT_FALSE(j.is_null());
    std::printf("%d rank(s): k %.9e vs built-in %.9e; %d vs %d iterations; %s\n", ranks,
                j["rate_constant_M-1s-1"].get<double>(), k, j["iterations"].get<int>(),
                builtin["iterations"].get<int>(), j["preconditioner"].get<std::string>().c_str());
    EXPECT_TRUE(j["converged"].get<bool>());
    EXPECT_NEAR(j["rate_constant_M-1s-1"].get<double>() / k, 1.0, 1e-6);
    EXPECT_EQ(j["level_unknowns"], builtin["level_unknowns"]);
    EXPECT_LE(j["iterations"].get<int>(), 30);
  }
}

TEST_F(PetscEngine, SameBornEnergyAsTheBuiltInSolverOnOneAndTwoRanks) {
  ASSERT_EQ(born_status_, 0);
  const std::string args = "poisson " + path("born.h5") + " --pqr " + path("born.pqr");
  const auto builtin = run_json(std::string(MOLMESH_CLI_PATH) + " -q solve " + args, "bb.json");
  ASSERT_FALSE(builtin.is_null());
  const double dg = builtin["solvation_energy_kJ_per_mol"].get<double>();
  for (int ranks : {1, 2}) {
    const auto j = run_json(petsc(ranks) + args, "pb" + std::to_string(ranks) + ".json");
    ASSERT_FALSE(j.is_null());
    std::printf("%d rank(s): dG %.9f vs built-in %.9f kJ/mol\n", ranks,
                j["solvation_energy_kJ_per_mol"].get<double>(), dg);
    EXPECT_NEAR(j["solvation_energy_kJ_per_mol"].get<double>() / dg, 1.0, 1e-6);
  }
}

TEST_F(PetscEngine, IterationsFlatAcrossTwoToFiveLevels) {
  ASSERT_EQ(sphere_status_, 0);
  int fewest = 1 << 30, most = 0;
  for (int levels = 2; levels <= 5; ++levels) {
    const auto j = run_json(
        petsc(2) + "smoluchowski " + path("sphere.h5") + " --levels " + std::to_string(levels),
        "l" + std::to_string(levels) + ".json");
    ASSERT_FALSE(j.is_null());
    const int iterations = j["iterations"].get<int>();
    std::printf("%d levels: %d iterations, level sizes %s\n", levels, iterations,
                j["level_unknowns"].dump().c_str());
    EXPECT_TRUE(j["converged"].get<bool>());
    fewest = std::min(fewest, iterations);
    most = std::max(most, iterations);
  }
  EXPECT_LE(most, fewest + 6);
}

TEST_F(PetscEngine, MatLoadReadsExportedProlongations) {
  ASSERT_EQ(born_status_, 0);
  ASSERT_EQ(cli("export " + path("born.h5") + " -o " + path("born")), 0);
  const Hierarchy h = read_hierarchy(path("born.h5"));
  ASSERT_FALSE(h.transfers.empty());
  ASSERT_EQ(PetscInitializeNoArguments(), 0);
  for (const LevelTransfer& t : h.transfers) {
    const std::string file = path("born_P" + std::to_string(t.coarse_level) + "_to_" +
                                  std::to_string(t.fine_level) + "_volume.petsc");
    PetscViewer viewer = nullptr;
    Mat m = nullptr;
    ASSERT_EQ(PetscViewerBinaryOpen(PETSC_COMM_SELF, file.c_str(), FILE_MODE_READ, &viewer), 0);
    ASSERT_EQ(MatCreate(PETSC_COMM_SELF, &m), 0);
    ASSERT_EQ(MatSetType(m, MATSEQAIJ), 0);
    ASSERT_EQ(MatLoad(m, viewer), 0) << file;
    PetscInt rows = 0, cols = 0;
    MatGetSize(m, &rows, &cols);
    EXPECT_EQ(rows, t.volume.rows());
    EXPECT_EQ(cols, t.volume.cols());
    double worst = 0.0;
    for (PetscInt r = 0; r < rows; ++r) {
      PetscInt n = 0;
      const PetscInt* c = nullptr;
      const PetscScalar* v = nullptr;
      MatGetRow(m, r, &n, &c, &v);
      for (PetscInt k = 0; k < n; ++k)
        worst = std::max(worst, std::abs(v[k] - t.volume.coeff(r, c[k])));
      EXPECT_EQ(n, t.volume.row(r).nonZeros());
      MatRestoreRow(m, r, &n, &c, &v);
    }
    EXPECT_EQ(worst, 0.0) << file;
    MatDestroy(&m);
    PetscViewerDestroy(&viewer);
  }
  PetscFinalize();
}

}  // namespace
}  // namespace molmesh
