// The multigrid setup's parallel sparse product against Eigen's.
#include "solvers/multigrid/sparse_product.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "solvers/multigrid/aggregation.hpp"

namespace molmesh::solvers {
namespace {

SparseMatrix random_sparse(int rows, int cols, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> column(0, cols - 1);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < per_row; ++k) t.emplace_back(i, column(rng), value(rng));
  SparseMatrix m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

TEST(SparseProduct, MatchesEigenAndKeepsColumnsSorted) {
  const SparseMatrix a = random_sparse(3000, 2000, 9, 1);
  const SparseMatrix b = random_sparse(2000, 700, 5, 2);
  const SparseMatrix ours = multiply(a, b);
  const SparseMatrix eigen = (a * b).pruned(0.0, 0.0);
  ASSERT_EQ(ours.rows(), 3000);
  ASSERT_EQ(ours.cols(), 700);
  EXPECT_LT((Eigen::MatrixXd(ours) - Eigen::MatrixXd(eigen)).cwiseAbs().maxCoeff(), 1e-13);
  for (Eigen::Index i = 0; i < ours.rows(); ++i) {
    int previous = -1;
    for (SparseMatrix::InnerIterator it(ours, i); it; ++it) {
      EXPECT_GT(it.col(), previous);
      previous = static_cast<int>(it.col());
    }
  }
  EXPECT_THROW(multiply(b, b), std::exception);
}

TEST(SmoothedAggregation, CoarsensALaplacianAndKeepsItDefinite) {
  // 1D Laplacian, n = 400: aggregates of about three, rows of the tentative part sum to 1.
  const int n = 400;
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  const SparseMatrix p = smoothed_aggregation_prolongation(a);
  EXPECT_GT(p.cols(), n / 4);
  EXPECT_LT(p.cols(), n / 2);
  // Away from the Dirichlet ends, smoothing keeps constants: P 1 = 1 in the interior.
  const Eigen::VectorXd ones = p * Eigen::VectorXd::Ones(p.cols());
  for (int i = 5; i < n - 5; ++i) EXPECT_NEAR(ones[i], 1.0, 1e-12) << i;
  const SparseMatrix coarse = galerkin_product(SparseMatrix(p.transpose()), a, p);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(coarse)};
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

}  // namespace
}  // namespace molmesh::solvers
