// Multigrid-preconditioned CG: iteration counts independent of the number of levels and of
// the mesh size, unlike CG with incomplete Cholesky.
#include <gtest/gtest.h>

#include "molmesh/core/error.hpp"
#include "solvers/physics/smoluchowski.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

SmoluchowskiResult solve(const test::ShellHierarchy& h, Preconditioning p) {
  SmoluchowskiOptions options;
  options.solver.preconditioning = p;
  options.solver.cg.tolerance = 1e-8;
  return solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options);
}

TEST(Multigrid, IterationsStayLowForTwoToFiveLevels) {
  const test::ShellSpec finest{
      .inner_radius = 10.0, .outer_radius = 100.0, .subdivisions = 4, .radial_layers = 16};
  for (int levels = 2; levels <= 5; ++levels) {
    const auto h = test::make_shell_hierarchy(finest, levels);
    const auto result = solve(h, Preconditioning::kMultigrid);
    std::printf("levels %d: sizes", levels);
    for (int s : result.solve.level_sizes) std::printf(" %d", s);
    std::printf("; %d iterations, relative residual %.2e, %.3f s setup + %.3f s solve\n",
                result.solve.iterations, result.solve.relative_residual, result.solve.setup_time_s,
                result.solve.solve_time_s);
    // Every mesh level is used; aggregation may add algebraic levels below the coarsest.
    EXPECT_EQ(result.solve.mesh_levels, levels);
    EXPECT_LE(result.solve.level_sizes.back(), 1500);
    EXPECT_TRUE(result.solve.converged);
    EXPECT_LE(result.solve.relative_residual, 1e-8 * 1.0001);
    EXPECT_LE(result.solve.iterations, 25);
    // The residual history is recorded and decreasing overall.
    EXPECT_EQ(result.solve.residual_history.size(),
              static_cast<std::size_t>(result.solve.iterations + 1));
  }
}

TEST(Multigrid, AggregationAloneWhenTheHierarchyHasOneLevel) {
  const auto h = test::make_shell_hierarchy(
      {.inner_radius = 10.0, .outer_radius = 100.0, .subdivisions = 4, .radial_layers = 16}, 1);
  const auto mg = solve(h, Preconditioning::kMultigrid);
  const auto ic = solve(h, Preconditioning::kIncompleteCholesky);
  std::printf("algebraic only: sizes");
  for (int s : mg.solve.level_sizes) std::printf(" %d", s);
  std::printf("; %d iterations (IC %d)\n", mg.solve.iterations, ic.solve.iterations);
  EXPECT_EQ(mg.solve.mesh_levels, 1);
  EXPECT_GE(mg.solve.level_sizes.size(), 3u);
  EXPECT_LE(mg.solve.level_sizes.back(), 1500);
  EXPECT_TRUE(mg.solve.converged);
  EXPECT_LE(mg.solve.iterations, 25);
  EXPECT_LT(mg.solve.iterations, ic.solve.iterations);
  EXPECT_NEAR(mg.rate_constant_A3_per_s / ic.rate_constant_A3_per_s, 1.0, 1e-6);
}

TEST(Multigrid, CoarseOperatorsDiscretisedOnTheCoarseMeshes) {
  const auto h = test::make_shell_hierarchy(
      {.inner_radius = 10.0, .outer_radius = 100.0, .subdivisions = 4, .radial_layers = 16}, 4);
  std::vector<CoarseLevel> coarse;
  for (std::size_t l = 1; l < h.meshes.size(); ++l) coarse.push_back({&h.meshes[l].mesh, {}});
  SmoluchowskiOptions options;
  const auto galerkin = solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options);
  const auto mesh = solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options, {}, coarse);
  std::printf("coarse operators: Galerkin %d iterations, mesh %d iterations; nonzeros",
              galerkin.solve.iterations, mesh.solve.iterations);
  for (std::size_t l = 0; l < mesh.solve.level_nonzeros.size(); ++l)
    std::printf(" %ld/%ld", galerkin.solve.level_nonzeros[l], mesh.solve.level_nonzeros[l]);
  std::printf("\n");
  EXPECT_TRUE(mesh.solve.converged);
  EXPECT_EQ(mesh.solve.mesh_levels, 4);
  EXPECT_LE(mesh.solve.iterations, 25);
  EXPECT_NE(mesh.solve.preconditioner.find("re-discretised"), std::string::npos);
  // Re-discretised operators keep the mesh stencil: never denser than Galerkin's.
  for (std::size_t l = 1; l < mesh.solve.level_nonzeros.size(); ++l)
    EXPECT_LE(mesh.solve.level_nonzeros[l], galerkin.solve.level_nonzeros[l]);
  EXPECT_NEAR(mesh.rate_constant_A3_per_s / galerkin.rate_constant_A3_per_s, 1.0, 1e-6);
}

// A coarse vertex that samples the potential grid inside the molecule (hundreds of kT/e)
// must not break the preconditioner: coarse beta*W is clamped to the fine level's range.
// A fine vertex with such a value is the user's error, reported as such.
TEST(Multigrid, ExtremeCoarsePotentialIsClampedAndExtremeFinePotentialIsAnError) {
  const auto h = test::make_shell_hierarchy(
      {.inner_radius = 10.0, .outer_radius = 100.0, .subdivisions = 3, .radial_layers = 8}, 3);
  const std::vector<double> fine_beta_w(h.meshes[0].mesh.points.size(), 0.0);
  std::vector<std::vector<double>> coarse_beta_w;
  std::vector<CoarseLevel> coarse;
  coarse_beta_w.reserve(h.meshes.size());
  for (std::size_t l = 1; l < h.meshes.size(); ++l) {
    coarse_beta_w.emplace_back(h.meshes[l].mesh.points.size(), 0.0);
    coarse_beta_w.back()[3] = -900.0;  // exp(900) overflows
    coarse_beta_w.back()[5] = 900.0;   // exp(-900) underflows
    coarse.push_back({&h.meshes[l].mesh, coarse_beta_w.back()});
  }
  SmoluchowskiOptions options;
  const auto plain = solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options);
  const auto clamped =
      solve_smoluchowski(h.meshes[0].mesh, fine_beta_w, h.prolongations, options, {}, coarse);
  EXPECT_TRUE(clamped.solve.converged);
  EXPECT_NEAR(clamped.rate_constant_A3_per_s / plain.rate_constant_A3_per_s, 1.0, 1e-6);

  std::vector<double> bad_fine = fine_beta_w;
  bad_fine[7] = -900.0;
  EXPECT_THROW(solve_smoluchowski(h.meshes[0].mesh, bad_fine, h.prolongations, options), Error);
}

TEST(Multigrid, IncompleteCholeskyNeedsMoreIterationsOnFinerMeshes) {
  int previous_ic = 0;
  for (int refinement = 2; refinement <= 4; ++refinement) {
    const auto h = test::make_shell_hierarchy({.inner_radius = 10.0,
                                               .outer_radius = 100.0,
                                               .subdivisions = refinement,
                                               .radial_layers = 1 << refinement},
                                              refinement + 1);
    const auto mg = solve(h, Preconditioning::kMultigrid);
    const auto ic = solve(h, Preconditioning::kIncompleteCholesky);
    std::printf("%d unknowns: MG-PCG %d iterations (%.3f s), IC-PCG %d iterations (%.3f s)\n",
                mg.unknowns, mg.solve.iterations, mg.solve.setup_time_s + mg.solve.solve_time_s,
                ic.solve.iterations, ic.solve.setup_time_s + ic.solve.solve_time_s);
    EXPECT_TRUE(mg.solve.converged);
    EXPECT_TRUE(ic.solve.converged);
    EXPECT_LE(mg.solve.iterations, 25);
    EXPECT_GT(ic.solve.iterations, previous_ic);
    EXPECT_GT(ic.solve.iterations, mg.solve.iterations);
    // Same answer either way.
    EXPECT_NEAR(mg.rate_constant_A3_per_s / ic.rate_constant_A3_per_s, 1.0, 1e-6);
    previous_ic = ic.solve.iterations;
  }
}

}  // namespace
}  // namespace molmesh::solvers
