// Nodal convergence of P1 elements, O(h^2), for the shell Laplace problem u = a + b/r with
// Dirichlet values on both spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/multigrid/linear_solver.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

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
