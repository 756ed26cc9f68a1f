#pragma once
// Preconditioned conjugate gradients with a residual history, and the two preconditioners
// the solvers offer: a multigrid V-cycle over a mesh hierarchy (multigrid.hpp) and
// incomplete Cholesky (the baseline it is measured against).
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh::solvers {

struct SolveOptions {
  double tolerance = 1e-8;  // on ||b - A x|| / ||b||
  int max_iterations = 2000;
};

struct SolveReport {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0.0;        // recomputed from b - A x at the end
  std::vector<double> residual_history;  // ||r_k|| / ||b||, k = 0..iterations
  double setup_time_s = 0.0;             // building the preconditioner
  double solve_time_s = 0.0;             // the iterations
  std::string preconditioner;
  std::vector<int> level_sizes;      // unknowns per multigrid level (empty for IC)
  std::vector<long> level_nonzeros;  // nonzeros of each level's operator
  int mesh_levels = 0;               // leading level_sizes from meshes; the rest algebraic
};

// z = M^-1 r for a symmetric positive definite M.
using Preconditioner = std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)>;

// y = A x, rows in parallel (each row is summed in a fixed order, so results do not depend
// on the thread count).
void parallel_multiply(const SparseMatrix& a, const Eigen::VectorXd& x, Eigen::VectorXd& y);

// Solves A x = b for symmetric positive definite A starting from x (resized and zeroed
// when its size is wrong). Does not throw when the tolerance is not reached: the report
// says so and the caller decides.
SolveReport preconditioned_cg(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              const Preconditioner& preconditioner, const SolveOptions& options);

// z = M^-1 r and, from the same work, az = A z (multigrid's last smoothing sweep gives it
// from the pass over A it makes anyway; multigrid.hpp).
using PreconditionerWithProduct =
    std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z, Eigen::VectorXd& az)>;

// The same CG with that preconditioner: one pass over A per iteration fewer (A p is
// updated from A z); the same iterates up to rounding.
SolveReport preconditioned_cg_with_product(const SparseMatrix& a, const Eigen::VectorXd& b,
                                           Eigen::VectorXd& x,
                                           const PreconditionerWithProduct& preconditioner,
                                           const SolveOptions& options);

// Eigen's IncompleteCholesky (AMD ordering, diagonal scaling) wrapped as a Preconditioner.
// Owns its factor; throws molmesh::Error when the factorisation fails.
Preconditioner make_incomplete_cholesky(const SparseMatrix& a);

}  // namespace molmesh::solvers
