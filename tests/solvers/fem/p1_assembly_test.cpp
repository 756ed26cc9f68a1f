// P1 assembly on meshes with known geometry: symmetry, constants in the kernel, the exact
// energy of linear functions, and the row-gather assembly against a cell-by-cell scatter.
#include "solvers/fem/p1_assembly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "solvers/fem/dirichlet.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

// A ball of radius 3 inside a shell to 9: both regions, a few thousand cells.
test::ShellMesh small_ball_and_shell() {
  return test::make_shell_mesh({.inner_radius = 3.0,
                                .outer_radius = 9.0,
                                .subdivisions = 2,
                                .radial_layers = 3,
                                .ball_layers = 2});
}

TEST(P1Assembly, StiffnessIsSymmetricAnnihilatesConstantsAndGivesExactEnergyOfLinears) {
  const auto shell = small_ball_and_shell();
  const TetMesh& m = shell.mesh;
  double volume = 0.0;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    const double v = tet_geometry(m, t).volume;
    ASSERT_GT(v, 0.0) << "tet " << t;
    volume += v;
  }
  const std::vector<double> ones(m.tetrahedra.size(), 1.0);
  const SparseMatrix k = assemble_stiffness(m, ones);
  EXPECT_LT((SparseMatrix(k.transpose()) - k).norm(), 1e-12 * k.norm());
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(k.rows());
  EXPECT_LT((k * one).cwiseAbs().maxCoeff(), 1e-10 * k.diagonal().maxCoeff());
  // u = 2x - y + 3z: u^T K u = |grad u|^2 * volume exactly.
  Eigen::VectorXd u(k.rows());
  for (Eigen::Index i = 0; i < k.rows(); ++i) {
    const Vec3& p = m.points[static_cast<std::size_t>(i)];
    u[i] = 2 * p.x() - p.y() + 3 * p.z();
  }
  EXPECT_NEAR(u.dot(k * u), 14.0 * volume, 1e-9 * 14.0 * volume);
}

// The row-wise gather must give exactly the matrix of the textbook cell-by-cell scatter.
TEST(P1Assembly, RowGatherEqualsCellByCellScatter) {
  const auto shell = small_ball_and_shell();
  const TetMesh& m = shell.mesh;
  std::vector<double> coefficient(m.tetrahedra.size());
  for (std::size_t t = 0; t < coefficient.size(); ++t) coefficient[t] = 1.0 + 0.1 * double(t % 7);
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    const TetGeometry g = tet_geometry(m, t);
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = 0; b < 4; ++b)
        triplets.emplace_back(m.tetrahedra[t][a], m.tetrahedra[t][b],
                              coefficient[t] * g.volume * g.gradients[a].dot(g.gradients[b]));
  }
  SparseMatrix reference(static_cast<Eigen::Index>(m.points.size()),
                         static_cast<Eigen::Index>(m.points.size()));
  reference.setFromTriplets(triplets.begin(), triplets.end());
  const SparseMatrix k = assemble_stiffness(m, coefficient);
  ASSERT_EQ(k.nonZeros(), reference.nonZeros());  // same pattern, every vertex pair once
  EXPECT_LT((k - reference).norm(), 1e-13 * reference.norm());
  for (Eigen::Index i = 0; i < k.rows(); ++i) {
    int previous = -1;
    for (SparseMatrix::InnerIterator it(k, i); it; ++it) {
      EXPECT_GT(it.col(), previous);
      previous = static_cast<int>(it.col());
    }
  }
}

// The coarse levels assemble only the free-free block: it must be reduce_dirichlet's block of
// the whole matrix, pattern and values, with every third vertex and the boundary left out.
TEST(P1Assembly, KeptBlockEqualsTheReducedWholeMatrix) {
  const auto shell = small_ball_and_shell();
  const TetMesh& m = shell.mesh;
  std::vector<double> coefficient(m.tetrahedra.size());
  for (std::size_t t = 0; t < coefficient.size(); ++t) coefficient[t] = 1.0 + 0.1 * double(t % 5);
  std::vector<char> dirichlet(m.points.size(), 0);
  for (std::size_t v = 0; v < dirichlet.size(); v += 3) dirichlet[v] = 1;
  for (const auto& face : m.boundary_faces)
    for (int v : face) dirichlet[static_cast<std::size_t>(v)] = 1;
  const auto n = static_cast<Eigen::Index>(m.points.size());
  const ReducedSystem reduced =
      reduce_dirichlet(assemble_stiffness(m, coefficient), Eigen::VectorXd::Zero(n), dirichlet,
                       Eigen::VectorXd::Zero(n));
  const ReducedSystem numbering = number_free_vertices(dirichlet);
  ASSERT_EQ(numbering.free_to_full, reduced.free_to_full);
  const SparseMatrix block = assemble_stiffness(m, coefficient, numbering.full_to_free);
  ASSERT_EQ(block.rows(), reduced.matrix.rows());
  ASSERT_EQ(block.nonZeros(), reduced.matrix.nonZeros());
  for (Eigen::Index i = 0; i < block.rows(); ++i) {
    SparseMatrix::InnerIterator want(reduced.matrix, i);
    for (SparseMatrix::InnerIterator got(block, i); got; ++got, ++want) {
      ASSERT_TRUE(want) << "row " << i;
      EXPECT_EQ(got.col(), want.col()) << "row " << i;
      EXPECT_NEAR(got.value(), want.value(), 1e-13 * std::abs(want.value()) + 1e-300);
    }
    EXPECT_FALSE(want) << "row " << i;
  }
  // A numbering out of vertex order would leave columns unsorted: refused.
  std::vector<int> shuffled = numbering.full_to_free;
  std::swap(shuffled[numbering.free_to_full[0]], shuffled[numbering.free_to_full[1]]);
  EXPECT_THROW(assemble_stiffness(m, coefficient, shuffled), Error);
}

TEST(P1Assembly, RejectsCellsWithVerticesOutsideTheMesh) {
  auto shell = test::make_shell_mesh({.subdivisions = 0, .radial_layers = 1});
  shell.mesh.tetrahedra[3][2] = static_cast<int>(shell.mesh.points.size());
  const std::vector<double> ones(shell.mesh.tetrahedra.size(), 1.0);
  EXPECT_THROW(assemble_stiffness(shell.mesh, ones), Error);
}

TEST(P1Assembly, RejectsInvertedTetrahedra) {
  auto shell = test::make_shell_mesh({.subdivisions = 0, .radial_layers = 1});
  std::swap(shell.mesh.tetrahedra[0][0], shell.mesh.tetrahedra[0][1]);
  const std::vector<double> ones(shell.mesh.tetrahedra.size(), 1.0);
  EXPECT_THROW(assemble_stiffness(shell.mesh, ones), Error);
}

}  // namespace
}  // namespace molmesh::solvers
