// P1 assembly on meshes with known geometry: algebraic properties, and nodal convergence
// O(h^2) for the shell Laplace problem u = a + b/r.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "shell_mesh.hpp"
#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/fem/point_locator.hpp"
#include "solvers/multigrid/linear_solver.hpp"

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

TEST(PointLocator, FindsContainingCellsAndInterpolatesLinearsExactly) {
  const auto shell = test::make_shell_mesh({.inner_radius = 2.0,
                                            .outer_radius = 6.0,
                                            .subdivisions = 2,
                                            .radial_layers = 3,
                                            .ball_layers = 2});
  const PointLocator locator(shell.mesh);
  const Vec3 probes[] = {Vec3(0, 0, 0), Vec3(0.3, -1.1, 0.7), Vec3(3.0, 2.0, -1.0),
                         Vec3(-4.5, 0.1, 1.2)};
  for (const Vec3& p : probes) {
    const auto at = locator.locate(p);
    ASSERT_TRUE(at.has_value());
    Vec3 back = Vec3::Zero();
    for (std::size_t a = 0; a < 4; ++a) {
      EXPECT_GE(at->barycentric[a], -1e-9);
      back += at->barycentric[a] *
              shell.mesh.points[static_cast<std::size_t>(
                  shell.mesh.tetrahedra[static_cast<std::size_t>(at->tetrahedron)][a])];
    }
    EXPECT_LT((back - p).norm(), 1e-9);
  }
  EXPECT_FALSE(locator.locate(Vec3(7.0, 0, 0)).has_value());
}

// Charges sit on mesh vertices (atom centres), shared by many cells: every vertex of a
// strongly graded mesh (geometric layers, cells 40x larger outside than inside) is found,
// with weight 1 on itself.
TEST(PointLocator, FindsEveryVertexOfAGradedMesh) {
  const auto shell = test::make_shell_mesh({.inner_radius = 1.0,
                                            .outer_radius = 40.0,
                                            .subdivisions = 2,
                                            .radial_layers = 12,
                                            .ball_layers = 2});
  const PointLocator locator(shell.mesh);
  for (std::size_t v = 0; v < shell.mesh.points.size(); ++v) {
    const auto at = locator.locate(shell.mesh.points[v]);
    ASSERT_TRUE(at.has_value()) << "vertex " << v;
    const Tetrahedron& tet = shell.mesh.tetrahedra[static_cast<std::size_t>(at->tetrahedron)];
    double own = 0.0;
    for (std::size_t a = 0; a < 4; ++a) {
      if (static_cast<std::size_t>(tet[a]) == v) own = at->barycentric[a];
    }
    EXPECT_NEAR(own, 1.0, 1e-9) << "vertex " << v;
  }
}

// Dirichlet on both spheres with the exact values of u = 1 + 10/r. Returns the root mean
// square nodal error (the maximum goes to max_error); h is the longest edge.
double shell_laplace_error(int refinement, double& h, double& max_error) {
  const auto hierarchy = test::make_shell_hierarchy({.inner_radius = 10.0,
                                                     .outer_radius = 20.0,
                                                     .subdivisions = 1 + refinement,
                                                     .radial_layers = 2 << refinement,
                                                     .geometric = false},
                                                    refinement + 1);
  const TetMesh& m = hierarchy.meshes[0].mesh;
  const std::vector<double> ones(m.tetrahedra.size(), 1.0);
  const SparseMatrix k = assemble_stiffness(m, ones);
  const auto n = static_cast<Eigen::Index>(m.points.size());
  const auto bits = boundary_vertex_marker_bits(m);
  std::vector<char> dirichlet(m.points.size());
  Eigen::VectorXd exact(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    exact[i] = 1.0 + 10.0 / m.points[static_cast<std::size_t>(i)].norm();
    dirichlet[static_cast<std::size_t>(i)] = bits[static_cast<std::size_t>(i)] != 0;
  }
  const ReducedSystem system = reduce_dirichlet(k, Eigen::VectorXd::Zero(n), dirichlet, exact);
  Eigen::VectorXd x;
  LinearSolverOptions options;
  options.cg.tolerance = 1e-12;
  const SolveReport report = solve_reduced(system, hierarchy.prolongations, options, x);
  EXPECT_TRUE(report.converged);
  const Eigen::VectorXd u = expand_solution(system, x, dirichlet, exact);
  h = 0.0;
  for (const Tetrahedron& t : m.tetrahedra) {
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        h = std::max(h, (m.points[static_cast<std::size_t>(t[static_cast<std::size_t>(a)])] -
                         m.points[static_cast<std::size_t>(t[static_cast<std::size_t>(b)])])
                            .norm());
  }
  max_error = (u - exact).cwiseAbs().maxCoeff();
  return std::sqrt((u - exact).squaredNorm() / static_cast<double>(n));
}

// Least-squares slope of log(error) against log(h) over refinements first..last.
double convergence_order(int first, int last) {
  std::vector<double> hs, errors;
  for (int level = first; level <= last; ++level) {
    double h = 0.0, max_error = 0.0;
    errors.push_back(shell_laplace_error(level, h, max_error));
    hs.push_back(h);
    std::printf("h = %.4f  rms nodal error = %.3e  max nodal error = %.3e\n", h, errors.back(),
                max_error);
  }
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    mx += std::log(hs[i]) / static_cast<double>(hs.size());
    my += std::log(errors[i]) / static_cast<double>(hs.size());
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    sxy += (std::log(hs[i]) - mx) * (std::log(errors[i]) - my);
    sxx += (std::log(hs[i]) - mx) * (std::log(hs[i]) - mx);
  }
  std::printf("fitted order = %.3f\n", sxy / sxx);
  return sxy / sxx;
}

TEST(P1Convergence, ShellLaplaceNodalErrorFallsAsHSquared) {
  EXPECT_GE(convergence_order(1, 3), 1.8);
}

}  // namespace
}  // namespace molmesh::solvers
