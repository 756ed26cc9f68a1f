// End to end: molmesh makes a full (ion + solvent) mesh of a Born ion, Debian's APBS solves
// the Poisson-Boltzmann equation on it in finite-element mode (fe-manual, usemesh), and the
// solvation energy must be within 3 % of Born's analytic value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>

#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

std::string elec_block(const char* name, double sdie) {
  std::ostringstream s;
  s << "elec name " << name << "\n"
    << "  fe-manual\n  domainLength 40 40 40\n  etol 0.1\n  ekey glob\n  akeyPRE geom\n"
    << "  akeySOLVE resi\n  targetNum 10\n  targetRes 0.0\n  maxsolve 1\n  maxvert 1000000\n"
    << "  usemesh 1\n  mol 1\n  lpbe\n  bcfl mdh\n  pdie 1.0\n  sdie " << sdie << "\n"
    << "  srfm mol\n  srad 1.4\n  swin 0.3\n  sdens 10.0\n  temp 298.15\n"
    << "  calcenergy total\n  calcforce no\nend\n";
  return s.str();
}

TEST(ApbsBorn, FullMeshGivesBornEnergyWithin3Percent) {
  if (testing::run_command("command -v apbs").exit_code != 0) {
    FAIL() << "apbs is not installed (Debian package apbs)";
  }
  const fs::path dir = testing::test_dir();

  // The ion surface: a 162-vertex icosphere of the Born radius, given to the CLI as a
  // surface file so the mesh follows the ion surface exactly (APBS's accuracy is set by
  // how well the dielectric boundary is resolved).
  write_surface_mesh(dir / "ion_surface.off", icosphere(Vec3::Zero(), 3.0, 2));
  testing::write_file(dir / "ion.pqr",
                      "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00\n");
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

  {
    std::ofstream in(dir / "born.in");
    in << "read\n  mol pqr ion.pqr\n  mesh mcsf mesh.m\nend\n"
       << elec_block("born", 78.54) << elec_block("born_ref", 1.0)
       << "print elecEnergy born - born_ref end\nquit\n";
  }
  const testing::CommandRun apbs =
      testing::run_command("cd " + testing::shell_quoted(dir.string()) + " && apbs born.in");
  ASSERT_EQ(apbs.exit_code, 0) << apbs.err;
  const std::string& out = apbs.out;
  // e.g. "  Global net ELEC energy = -2.286071850994E+02 kJ/mol"
  const std::regex energy(R"(Global net ELEC energy\s*=\s*([-+0-9.eE]+)\s*kJ/mol)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(out, match, energy))
      << out.substr(out.size() > 3000 ? out.size() - 3000 : 0);
  const double dg = std::stod(match[1].str());
  const double analytic = -(1389.35458 / 6.0) * (1.0 - 1.0 / 78.54);  // -228.61 kJ/mol
  RecordProperty("born_energy_kj_mol", std::to_string(dg));
  std::cout << "APBS Born ion: " << mesh.points.size() << " vertices, " << mesh.tetrahedra.size()
            << " tets; dG = " << dg << " kJ/mol (analytic " << analytic << ")\n";
  EXPECT_NEAR(dg, analytic, 0.03 * std::abs(analytic)) << "APBS gave " << dg << " kJ/mol";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
