// End to end: molmesh makes a full (ion + solvent) mesh of a Born ion, Debian's APBS solves
// the Poisson-Boltzmann equation on it in finite-element mode (fe-manual, usemesh), and the
// solvation energy must be within 3 % of Born's analytic value.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "support/apbs.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

TEST(ApbsBorn, FullMeshGivesBornEnergyWithin3Percent) {
  if (!testing::apbs_installed()) {
    FAIL() << "apbs is not installed (Debian package apbs)";
  }
  const fs::path dir = testing::test_dir();

  // The ion surface: a 162-vertex icosphere of the Born radius, given to the CLI as a
  // surface file so the mesh follows the ion surface exactly (APBS's accuracy is set by
  // how well the dielectric boundary is resolved).
  write_surface_mesh(dir / "ion_surface.off", icosphere(Vec3::Zero(), 3.0, 2));
  testing::write_file(dir / "ion.pqr", testing::kBornIonPqr);
  const testing::CliRun run =
      testing::run_cli_in(dir.string(),
                          "-q tetmesh ion_surface.off --domain full --outer-radius 20 "
                          "--sphere-subdivisions 2 --size-factor 2.5 -o mesh.m --stats "
                          "mesh.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const TetMesh mesh = read_mcsf(dir / "mesh.m");
  EXPECT_GT(mesh.points.size(), 300u);
  // APBS refines ~64x on load. The size field (tetmesh/size_field.hpp) grades a 3 A ion's
  // solvent at h/r = 0.09: 16,597 vertices at the default size factor, 1,464 at 2.5.
  EXPECT_LT(mesh.points.size(), 2500u);

  testing::write_file(dir / "born.in", testing::apbs_solvation_input("ion.pqr", "mesh.m"));
  const testing::CommandRun apbs = testing::run_apbs_in(dir, "born.in");
  ASSERT_EQ(apbs.exit_code, 0) << apbs.err;
  const std::optional<double> energy = testing::apbs_global_elec_energy(apbs.out);
  ASSERT_TRUE(energy) << testing::apbs_output_tail(apbs);
  const double dg = *energy;
  const double analytic = testing::born_solvation_energy_kj_mol(3.0);  // -228.61 kJ/mol
  RecordProperty("born_energy_kj_mol", std::to_string(dg));
  std::cout << "APBS Born ion: " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
            << " tets; dG = " << dg << " kJ/mol (analytic " << analytic << ")\n";
  EXPECT_NEAR(dg, analytic, 0.03 * std::abs(analytic)) << "APBS gave " << dg << " kJ/mol";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
