// Born ion solvation energy through the reference-solve Poisson solver on a full mesh.
#include "solvers/physics/poisson.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "molmesh/core/error.hpp"
#include "solvers/physics/units.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

// A ball of radius 3 Å (the ion) in a shell to 15 Å, four nested levels, and the ion.
test::ShellHierarchy born_hierarchy() {
  return test::make_shell_hierarchy({.inner_radius = 3.0,
                                     .outer_radius = 15.0,
                                     .subdivisions = 4,
                                     .radial_layers = 8,
                                     .ball_layers = 4},
                                    4);
}

Atom born_ion() {
  Atom ion;
  ion.charge = 1.0;
  ion.radius = 3.0;
  return ion;
}

TEST(Poisson, BornIonSolvationEnergy) {
  const double radius = 3.0, sdie = 78.54;
  const auto h = born_hierarchy();
  const Atom ion = born_ion();
  PoissonOptions options;
  options.pdie = 1.0;
  options.sdie = sdie;
  const auto result = solve_solvation_energy(h.meshes[0].mesh, {ion}, h.prolongations, options);
  const double expected = -units::kCoulombKjAngstromPerMol / (2.0 * radius) * (1.0 - 1.0 / sdie);
  EXPECT_NEAR(expected, -228.61, 0.01);
  std::printf("Born dG = %.3f kJ/mol (analytic %.3f, error %+.3f %%); CG iterations %d + %d\n",
              result.solvation_energy_kj_per_mol, expected,
              100.0 * (result.solvation_energy_kj_per_mol / expected - 1.0),
              result.solvated.iterations, result.reference.iterations);
  EXPECT_TRUE(result.solvated.converged);
  EXPECT_TRUE(result.reference.converged);
  EXPECT_EQ(result.charges, 1);
  EXPECT_LT(result.max_charge_offset, 1e-12);
  EXPECT_NEAR(result.solvation_energy_kj_per_mol / expected, 1.0, 0.02);
  // Outside the ion the reaction field of a Born ion is q C (1/sdie - 1) / r... inside it
  // is the constant C q (1/sdie - 1)/R; check the constant at the centre.
  EXPECT_NEAR(result.reaction_potential[0],
              units::kCoulombKjAngstromPerMol * (1.0 / sdie - 1.0) / radius,
              0.02 * units::kCoulombKjAngstromPerMol / radius);
}

// Coarse operators discretised on the coarse meshes (their own regions and outer sphere)
// precondition the same fine system: the same energy, a mesh-stencil hierarchy.
TEST(Poisson, CoarseOperatorsFromTheCoarseMeshesGiveTheSameEnergy) {
  const auto h = born_hierarchy();
  const Atom ion = born_ion();
  const auto galerkin = solve_solvation_energy(h.meshes[0].mesh, {ion}, h.prolongations, {});
  std::vector<CoarseLevel> coarse;
  for (std::size_t l = 1; l < h.meshes.size(); ++l) coarse.push_back({&h.meshes[l].mesh, {}});
  const auto mesh =
      solve_solvation_energy(h.meshes[0].mesh, {ion}, h.prolongations, {}, {}, coarse);
  std::printf("Born with mesh coarse operators: %d + %d iterations (Galerkin %d + %d)\n",
              mesh.solvated.iterations, mesh.reference.iterations, galerkin.solvated.iterations,
              galerkin.reference.iterations);
  EXPECT_TRUE(mesh.solvated.converged);
  EXPECT_TRUE(mesh.reference.converged);
  // As strong a preconditioner as the Galerkin one on this nested hierarchy.
  EXPECT_LE(mesh.solvated.iterations, galerkin.solvated.iterations + 5);
  EXPECT_EQ(mesh.solvated.mesh_levels, 4);
  EXPECT_NE(mesh.solvated.preconditioner.find("re-discretised"), std::string::npos);
  EXPECT_NEAR(mesh.solvation_energy_kj_per_mol / galerkin.solvation_energy_kj_per_mol, 1.0, 1e-6);
  for (std::size_t l = 1; l < mesh.solvated.level_nonzeros.size() &&
                          l < static_cast<std::size_t>(mesh.solvated.mesh_levels);
       ++l)
    EXPECT_LE(mesh.solvated.level_nonzeros[l], galerkin.solvated.level_nonzeros[l]);
}

TEST(Poisson, ChargeOutsideTheMeshIsAnError) {
  const auto shell = test::make_shell_mesh({.inner_radius = 3.0,
                                            .outer_radius = 10.0,
                                            .subdivisions = 1,
                                            .radial_layers = 2,
                                            .ball_layers = 1});
  Atom far;
  far.charge = 1.0;
  far.center = Vec3(20, 0, 0);
  EXPECT_THROW(solve_solvation_energy(shell.mesh, {far}, {}, {}), Error);
}

}  // namespace
}  // namespace molmesh::solvers
