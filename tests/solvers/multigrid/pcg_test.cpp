// CG with the product taken from the preconditioner (preconditioned_cg_with_product) against
// plain preconditioned CG: the same iterates up to rounding, on a real mesh hierarchy.
#include "solvers/multigrid/pcg.hpp"

#include <gtest/gtest.h>

#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/multigrid/multigrid.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

TEST(Pcg, ProductFromTheMultigridCycleGivesTheSameIterates) {
  const auto h = test::make_shell_hierarchy(
      {.inner_radius = 10.0, .outer_radius = 100.0, .subdivisions = 4, .radial_layers = 16}, 3);
  const TetMesh& mesh = h.meshes[0].mesh;
  const std::vector<double> ones(mesh.tetrahedra.size(), 1.0);
  const SparseMatrix k = assemble_stiffness(mesh, ones);
  const auto n = static_cast<Eigen::Index>(mesh.points.size());
  std::vector<char> fixed(mesh.points.size(), 0);
  Eigen::VectorXd values = Eigen::VectorXd::Zero(n);
  for (std::size_t v = 0; v < fixed.size(); ++v) {
    const double r = mesh.points[v].norm();
    fixed[v] = r < 10.1 || r > 99.9;
    if (r < 10.1) values[static_cast<Eigen::Index>(v)] = 1.0;  // absorbing-like inner sphere
  }
  const ReducedSystem system = reduce_dirichlet(k, Eigen::VectorXd::Zero(n), fixed, values);
  const MultigridPreconditioner mg(system.matrix, system.free_to_full, h.prolongations);
  ASSERT_GE(mg.level_sizes().size(), 3u);

  // One application: the same z, and A z from the cycle's last sweep.
  Eigen::VectorXd z, z_with, az;
  mg.apply(system.rhs, z);
  mg.apply_with_product(system.rhs, z_with, az);
  EXPECT_EQ((z - z_with).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd direct = system.matrix * z;
  EXPECT_LT((az - direct).norm(), 1e-12 * direct.norm());

  const SolveOptions options{.tolerance = 1e-10, .max_iterations = 200};
  Eigen::VectorXd x_plain, x_with;
  const SolveReport plain = preconditioned_cg(
      system.matrix, system.rhs, x_plain,
      [&](const Eigen::VectorXd& r, Eigen::VectorXd& out) { mg.apply(r, out); }, options);
  const SolveReport with = preconditioned_cg_with_product(
      system.matrix, system.rhs, x_with,
      [&](const Eigen::VectorXd& r, Eigen::VectorXd& out, Eigen::VectorXd& a_out) {
        mg.apply_with_product(r, out, a_out);
      },
      options);
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(with.converged);
  EXPECT_EQ(with.iterations, plain.iterations);
  for (std::size_t i = 0; i < plain.residual_history.size(); ++i)
    EXPECT_NEAR(with.residual_history[i] / plain.residual_history[i], 1.0, 1e-6) << i;
  EXPECT_LT((x_with - x_plain).norm(), 1e-9 * x_plain.norm());
}

}  // namespace
}  // namespace molmesh::solvers
