#pragma once
// One entry point for the physics solvers: solve a Dirichlet-reduced system with CG,
// preconditioned by multigrid over the hierarchy's prolongations or by incomplete Cholesky.
#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "solvers/fem/dirichlet.hpp"
#include "solvers/multigrid/multigrid.hpp"
#include "solvers/multigrid/pcg.hpp"

namespace molmesh::solvers {

enum class Preconditioning { kMultigrid, kIncompleteCholesky };

struct LinearSolverOptions;

// Another implementation of solve_reduced for the same system, e.g. PETSc's KSP on MPI
// ranks (solvers/petsc/petsc_engine.hpp); the physics solvers stay the same.
using LinearEngine = std::function<SolveReport(
    const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
    const LinearSolverOptions& options, Eigen::VectorXd& x,
    std::vector<MeshOperator> mesh_operators)>;

struct LinearSolverOptions {
  Preconditioning preconditioning = Preconditioning::kMultigrid;
  SolveOptions cg;
  MultigridOptions multigrid;
  LinearEngine engine;  // empty: the built-in CG below
};

// Solves system.matrix * x = system.rhs (x holds the free unknowns on return). With
// kMultigrid and no prolongations the V-cycle is algebraic multigrid (a direct solve for
// small systems).
// mesh_operators (optional): coarse operators discretised on the coarse meshes
// (multigrid.hpp). With options.engine set, that engine solves instead.
SolveReport solve_reduced(const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                          const LinearSolverOptions& options, Eigen::VectorXd& x,
                          std::vector<MeshOperator> mesh_operators = {});

}  // namespace molmesh::solvers
