#pragma once
// One entry point for the physics solvers: solve a Dirichlet-reduced system with CG,
// preconditioned by multigrid over the hierarchy's prolongations or by incomplete Cholesky.
#include <Eigen/Core>
#include <span>

#include "solvers/fem/dirichlet.hpp"
#include "solvers/multigrid/multigrid.hpp"
#include "solvers/multigrid/pcg.hpp"

namespace molmesh::solvers {

enum class Preconditioning { kMultigrid, kIncompleteCholesky };

struct LinearSolverOptions {
  Preconditioning preconditioning = Preconditioning::kMultigrid;
  SolveOptions cg;
  MultigridOptions multigrid;
};

// Solves system.matrix * x = system.rhs (x holds the free unknowns on return). With
// kMultigrid and no prolongations the V-cycle is algebraic multigrid (a direct solve for
// small systems).
// mesh_operators (optional): coarse operators discretised on the coarse meshes
// (multigrid.hpp).
SolveReport solve_reduced(const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                          const LinearSolverOptions& options, Eigen::VectorXd& x,
                          std::vector<MeshOperator> mesh_operators = {});

}  // namespace molmesh::solvers
