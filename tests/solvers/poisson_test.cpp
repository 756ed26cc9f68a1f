// Born ion solvation energy through the reference-solve Poisson solver on a full mesh.
#include "solvers/physics/poisson.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "molmesh/core/error.hpp"
#include "shell_mesh.hpp"
#include "solvers/physics/units.hpp"

namespace molmesh::solvers {
namespace {

TEST(Poisson, BornIonSolvationEnergy) {
  const double radius = 3.0, sdie = 78.54;
  const auto h = test::make_shell_hierarchy({.inner_radius = radius,
                                             .outer_radius = 15.0,
                                             .subdivisions = 4,
                                             .radial_layers = 8,
                                             .ball_layers = 4},
                                            4);
  Atom ion;
  ion.charge = 1.0;
  ion.radius = radius;
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
