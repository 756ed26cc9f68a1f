// The block Gauss-Seidel smoother: the shortcuts it takes (sweep from zero, residual from
// half the matrix, sweeps with their products folded in) against the plain definitions, symmetry of
// the smoothing pair, and independence of the thread count.
#include "solvers/multigrid/gauss_seidel.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

#include "molmesh/core/error.hpp"
#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

// The P1 Laplacian of a shell with the outer sphere held fixed: a real SPD mesh operator.
SparseMatrix shell_operator() {
  const auto shell = test::make_shell_mesh(
      {.inner_radius = 10.0, .outer_radius = 40.0, .subdivisions = 3, .radial_layers = 8});
  const std::vector<double> ones(shell.mesh.tetrahedra.size(), 1.0);
  const SparseMatrix k = assemble_stiffness(shell.mesh, ones);
  std::vector<char> fixed(shell.mesh.points.size(), 0);
  for (std::size_t v = 0; v < fixed.size(); ++v) fixed[v] = shell.mesh.points[v].norm() > 39.9;
  const auto n = static_cast<Eigen::Index>(fixed.size());
  return reduce_dirichlet(k, Eigen::VectorXd::Zero(n), fixed, Eigen::VectorXd::Zero(n)).matrix;
}

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (auto& x : v) x = value(rng);
  return v;
}

// Symmetric smoothing from zero: forward, then backward.
Eigen::VectorXd symmetric_smoothing(const GaussSeidelSmoother& s, const Eigen::VectorXd& b) {
  Eigen::VectorXd x;
  forward_sweep_from_zero(s, b, x);
  backward_sweep(s, b, x);
  return x;
}

TEST(GaussSeidel, OneBlockIsTheClassicForwardSubstitution) {
  const SparseMatrix a = shell_operator();
  const GaussSeidelSmoother s = make_gauss_seidel(a, 1);
  ASSERT_EQ(s.block.size(), 2u);
  const Eigen::VectorXd b = random_vector(a.rows(), 1);
  Eigen::VectorXd x;
  forward_sweep_from_zero(s, b, x);
  // (D + L) x = b
  const Eigen::SparseMatrix<double> lower =
      Eigen::SparseMatrix<double>(a).triangularView<Eigen::Lower>();
  EXPECT_LT((lower * x - b).norm(), 1e-12 * b.norm());
}

TEST(GaussSeidel, ShortcutsMatchTheirDefinitions) {
  const SparseMatrix a = shell_operator();
  for (int blocks : {1, 3, 8}) {
    const GaussSeidelSmoother s = make_gauss_seidel(a, blocks, 100);
    EXPECT_EQ(s.block.size(), static_cast<std::size_t>(blocks) + 1);
    const Eigen::VectorXd b = random_vector(a.rows(), 2);
    Eigen::VectorXd from_zero;
    forward_sweep_from_zero(s, b, from_zero);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(a.rows());
    forward_sweep(s, b, full);
    EXPECT_LT((from_zero - full).norm(), 1e-13 * full.norm()) << blocks << " blocks";

    Eigen::VectorXd residual;
    residual_after_forward_sweep(s, nullptr, from_zero, residual);
    const Eigen::VectorXd direct = b - a * from_zero;
    EXPECT_LT((residual - direct).norm(), 1e-11 * b.norm()) << blocks << " blocks";

    const Eigen::VectorXd before = full;
    forward_sweep(s, b, full);
    residual_after_forward_sweep(s, &before, full, residual);
    EXPECT_LT((residual - (b - a * full)).norm(), 1e-11 * b.norm()) << blocks << " blocks";
    // A sweep is a contraction in the energy norm: the residual fell.
    EXPECT_LT(residual.norm(), direct.norm());
  }
}

TEST(GaussSeidel, FusedSweepsMatchTheSweepsAndProductsTheyReplace) {
  const SparseMatrix a = shell_operator();
  for (int blocks : {1, 3, 8}) {
    const GaussSeidelSmoother s = make_gauss_seidel(a, blocks, 100);
    if (blocks > 1) {
      EXPECT_FALSE(s.cross_block_rows.empty());
    }
    const Eigen::VectorXd b = random_vector(a.rows(), 6);
    Eigen::VectorXd x, residual;
    forward_sweep_from_zero_with_residual(s, b, x, residual);
    Eigen::VectorXd plain;
    forward_sweep_from_zero(s, b, plain);
    EXPECT_LT((x - plain).norm(), 1e-13 * plain.norm()) << blocks << " blocks";
    EXPECT_LT((residual - (b - a * x)).norm(), 1e-11 * b.norm()) << blocks << " blocks";

    // A correction arrives, then the backward sweep also gives A x.
    x += random_vector(a.rows(), 7);
    Eigen::VectorXd plain_after = x;
    Eigen::VectorXd scratch, ax;
    backward_sweep_with_product(s, b, x, scratch, ax);
    backward_sweep(s, b, plain_after);
    EXPECT_EQ((x - plain_after).cwiseAbs().maxCoeff(), 0.0) << blocks << " blocks";
    const Eigen::VectorXd direct = a * x;
    EXPECT_LT((ax - direct).norm(), 1e-11 * direct.norm()) << blocks << " blocks";
  }
}

TEST(GaussSeidel, ForwardThenBackwardIsSymmetric) {
  const SparseMatrix a = shell_operator();
  for (int blocks : {1, 4}) {
    const GaussSeidelSmoother s = make_gauss_seidel(a, blocks, 100);
    const Eigen::VectorXd u = random_vector(a.rows(), 3);
    const Eigen::VectorXd v = random_vector(a.rows(), 4);
    const double uv = u.dot(symmetric_smoothing(s, v));
    const double vu = v.dot(symmetric_smoothing(s, u));
    EXPECT_NEAR(uv, vu, 1e-12 * std::abs(uv)) << blocks << " blocks";
    EXPECT_GT(u.dot(symmetric_smoothing(s, u)), 0.0);
  }
}

TEST(GaussSeidel, ResultDoesNotDependOnTheThreadCount) {
  const SparseMatrix a = shell_operator();
  const GaussSeidelSmoother s = make_gauss_seidel(a, 4, 100);
  const Eigen::VectorXd b = random_vector(a.rows(), 5);
  Eigen::VectorXd one_thread;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one_thread = symmetric_smoothing(s, b);
  }
  const Eigen::VectorXd any_threads = symmetric_smoothing(s, b);
  EXPECT_EQ((one_thread - any_threads).cwiseAbs().maxCoeff(), 0.0);
}

TEST(GaussSeidel, RejectsOperatorsWithoutPositiveDiagonal) {
  SparseMatrix a(3, 3);
  a.insert(0, 0) = 1.0;
  a.insert(1, 2) = 1.0;
  a.insert(2, 1) = 1.0;
  a.insert(2, 2) = 1.0;
  a.makeCompressed();
  EXPECT_THROW(make_gauss_seidel(a, 1), Error);
}

}  // namespace
}  // namespace molmesh::solvers
