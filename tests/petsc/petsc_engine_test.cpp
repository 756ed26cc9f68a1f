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
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "molmesh/io/hierarchy_hdf5.hpp"
#include "support/files.hpp"
#include "support/process.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

// Under AddressSanitizer the test executable runs with ASAN_OPTIONS
// fast_unwind_on_malloc=0 (tests/CMakeLists.txt): Open MPI's leaks at exit (PETSc's MatLoad
// here, molmesh-petsc's ranks) are only named for tools/sanitizers/lsan.supp by full stacks.
// Unwinding every allocation that way is slow (session 26: a 5-level hierarchy 7 -> 11 s),
// so the molmesh CLI, which has no MPI, runs with the fast unwinder, and of the ranks only
// the 1- and 2-rank runs of each equation keep the leak check; the level-count sweep runs
// them without it (the same code path as the rate test, ASan and UBSan still on).
// Outside ASan the prefixes are inert.
class PetscEngine : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { dir_ = testing::test_dir(); }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static std::string with_asan_options(const std::string& options) {
    return "ASAN_OPTIONS=\"${ASAN_OPTIONS}:" + options + "\" ";
  }
  static std::string molmesh_cli() {
    return with_asan_options("fast_unwind_on_malloc=1") + MOLMESH_CLI_PATH + " -q ";
  }
  static int cli(const std::string& args) {
    return testing::run_command(molmesh_cli() + args).exit_code;
  }
  // NAME.h5, the hierarchy of one ion (a PQR line) built with `options`: each test process
  // builds only the one it uses, once; "" (and a failure) if the CLI failed.
  static std::string hierarchy_h5(const std::string& name, const std::string& ion,
                                  const std::string& options) {
    static std::map<std::string, int> status;
    if (!status.contains(name)) {
      testing::write_file(dir_ / (name + ".pqr"), ion + "\n");
      status[name] =
          cli("hierarchy " + path(name + ".pqr") + " -o " + path(name + ".h5") + " " + options);
    }
    EXPECT_EQ(status[name], 0) << name;
    return status[name] == 0 ? path(name + ".h5") : "";
  }
  // Five levels, so 2..5 of them can be used.
  static std::string sphere_h5() {
    return hierarchy_h5("sphere",
                        "ATOM      1  NA  ION     1       0.000   0.000   0.000  1.0000 10.0",
                        "--domain exterior --outer-radius 50 --t0 0.1,0.3,0.5,0.7,0.9");
  }
  static std::string born_h5() {
    return hierarchy_h5("born",
                        "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00",
                        "--domain full --outer-radius 20");
  }
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
  enum class LeakCheck { on, off };
  // CI runs as root on 2 cores: mpirun needs both flags there.
  static std::string petsc(int ranks, LeakCheck leaks = LeakCheck::on) {
    std::string command = leaks == LeakCheck::off ? with_asan_options("detect_leaks=0") : "";
    command += MOLMESH_MPIEXEC;
    command += " --oversubscribe --allow-run-as-root -n ";
    command += std::to_string(ranks);
    command += " ";
    command += MOLMESH_PETSC_PATH;
    command += " -q ";
    return command;
  }
  static inline fs::path dir_;
};

TEST_F(PetscEngine, SameRateAsTheBuiltInSolverOnOneAndTwoRanks) {
  const std::string sphere = sphere_h5();
  ASSERT_FALSE(sphere.empty());
  const std::string args = "smoluchowski " + sphere;
  const auto builtin = run_json(molmesh_cli() + "solve " + args, "b.json");
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
  const std::string born = born_h5();
  ASSERT_FALSE(born.empty());
  const std::string args = "poisson " + born + " --pqr " + path("born.pqr");
  const auto builtin = run_json(molmesh_cli() + "solve " + args, "bb.json");
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
  const std::string sphere = sphere_h5();
  ASSERT_FALSE(sphere.empty());
  int fewest = 1 << 30, most = 0;
  for (int levels = 2; levels <= 5; ++levels) {
    const auto j = run_json(
        petsc(2, LeakCheck::off) + "smoluchowski " + sphere + " --levels " + std::to_string(levels),
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
  const std::string born = born_h5();
  ASSERT_FALSE(born.empty());
  ASSERT_EQ(cli("export " + born + " -o " + path("born")), 0);
  const Hierarchy h = read_hierarchy(born);
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
