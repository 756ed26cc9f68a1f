// End to end through the CLI: `molmesh hierarchy` on a Born ion (full domain), `molmesh
// export` of its finest and coarsest levels to MCSF, and Debian's APBS (fe-manual, usemesh)
// on each: an exported level is a mesh APBS solves on, and level 0 is accurate enough for a
// solvation energy (docs/validation.md, "APBS on an exported level").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/mcsf.hpp"
#include "support/apbs.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

// ctest runs each test in its own process, so each builds its own hierarchy (1-2 s) in its
// own folder.
class ExportApbsBorn : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = testing::test_dir();
    testing::write_file(dir_ / "ion.pqr", testing::kBornIonPqr);
    // --size-factor 2.5: at the defaults level 0 has ~17,700 vertices, which APBS's ~64x
    // refinement on load makes a ~1M-vertex solve, too slow for a test.
    hierarchy_ = testing::run_cli_in(dir_.string(),
                                     "-q hierarchy ion.pqr --domain full --outer-radius 20 "
                                     "--sphere-subdivisions 2 --size-factor 2.5 -o ion.h5");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // Exports `level` (-1: the coarsest) and returns APBS's solvation energy on it, or nullopt
  // after a failed assertion. Prints and records the mesh size and the energy.
  std::optional<double> apbs_energy_on_level(int level) {
    EXPECT_EQ(hierarchy_.exit_code, 0) << hierarchy_.err;
    if (hierarchy_.exit_code != 0) return std::nullopt;
    const int levels = static_cast<int>(read_hierarchy(dir_ / "ion.h5").levels.size());
    EXPECT_GE(levels, 2) << "a hierarchy of one level has no coarsest level to test apart";
    if (level < 0) level = levels - 1;
    const std::string L = std::to_string(level);
    const testing::CliRun run = testing::run_cli_in(
        dir_.string(), "-q export ion.h5 --level " + L + " --no-prolongations -o ion");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const std::string mesh_file = "ion_L" + L + "_volume.m";
    if (run.exit_code != 0 || !fs::exists(dir_ / mesh_file)) {
      ADD_FAILURE() << mesh_file << " was not written: " << run.output();
      return std::nullopt;
    }
    const TetMesh mesh = read_mcsf(dir_ / mesh_file);

    const std::string input = "born_L" + L + ".in";
    testing::write_file(dir_ / input, testing::apbs_solvation_input("ion.pqr", mesh_file));
    const testing::CommandRun apbs = testing::run_apbs_in(dir_, input);
    EXPECT_EQ(apbs.exit_code, 0) << apbs.err << testing::apbs_output_tail(apbs);
    const std::optional<double> dg = testing::apbs_global_elec_energy(apbs.out);
    EXPECT_TRUE(dg) << "no energy in APBS's output: " << testing::apbs_output_tail(apbs);
    if (apbs.exit_code != 0 || !dg) return std::nullopt;

    RecordProperty("level", level);
    RecordProperty("vertices", std::to_string(mesh.points.size()));
    RecordProperty("tetrahedra", std::to_string(mesh.tetrahedra.size()));
    RecordProperty("born_energy_kj_mol", std::to_string(*dg));
    std::cout << "APBS on exported level " << level << " of " << levels << ": "
              << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
              << " tets; dG = " << *dg << " kJ/mol (analytic "
              << testing::born_solvation_energy_kj_mol(3.0) << ")\n";
    return dg;
  }

  static inline fs::path dir_;
  static inline testing::CliRun hierarchy_;
};

// Measured -230.16 kJ/mol (+0.68 %); APBS takes ~2 min on it.
TEST_F(ExportApbsBorn, Level0GivesBornEnergyWithin1Percent) {
  if (!testing::apbs_installed()) FAIL() << "apbs is not installed (Debian package apbs)";
  const std::optional<double> dg = apbs_energy_on_level(0);
  ASSERT_TRUE(dg);
  const double analytic = testing::born_solvation_energy_kj_mol(3.0);  // -228.61 kJ/mol
  EXPECT_NEAR(*dg, analytic, 0.01 * std::abs(analytic)) << "APBS gave " << *dg << " kJ/mol";
}

// Measured -202.03 kJ/mol (-11.6 %): its 54-vertex ion surface encloses 90 % of the ion's
// volume. The floor is that APBS solves on it and gives a finite, roughly right energy.
TEST_F(ExportApbsBorn, CoarsestLevelGivesFiniteEnergyWithin15Percent) {
  if (!testing::apbs_installed()) FAIL() << "apbs is not installed (Debian package apbs)";
  const std::optional<double> dg = apbs_energy_on_level(-1);
  ASSERT_TRUE(dg);
  ASSERT_TRUE(std::isfinite(*dg)) << *dg;
  const double analytic = testing::born_solvation_energy_kj_mol(3.0);
  EXPECT_NEAR(*dg, analytic, 0.15 * std::abs(analytic)) << "APBS gave " << *dg << " kJ/mol";
}

}  // namespace
}  // namespace molmesh
