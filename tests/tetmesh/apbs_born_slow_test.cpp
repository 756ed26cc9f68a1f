// End to end: molmesh makes a full (ion + solvent) mesh of a Born ion, Debian's APBS solves
// the Poisson-Boltzmann equation on it in finite-element mode (fe-manual, usemesh), and the
// solvation energy must be within 3 % of Born's analytic value.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
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

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ApbsBorn, FullMeshGivesBornEnergyWithin3Percent) {
  if (std::system("command -v apbs > /dev/null 2>&1") != 0) {
    FAIL() << "apbs is not installed (Debian package apbs)";
  }
  const fs::path dir =
      fs::temp_directory_path() / ("molmesh_apbs_born_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);

  // The ion surface: a 162-vertex icosphere of the Born radius, given to the CLI as a
  // surface file so the mesh follows the ion surface exactly (APBS's accuracy is set by
  // how well the dielectric boundary is resolved).
  write_surface_mesh(dir / "ion_surface.off", icosphere(Vec3::Zero(), 3.0, 2));
  {
    std::ofstream pqr(dir / "ion.pqr");
    pqr << "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00\n";
  }
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
  const std::string apbs_cmd = "cd '" + dir.string() + "' && apbs born.in > apbs.out 2> apbs.err";
  ASSERT_EQ(std::system(apbs_cmd.c_str()), 0) << slurp(dir / "apbs.err");
  const std::string out = slurp(dir / "apbs.out");
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
