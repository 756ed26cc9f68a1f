#pragma once
// PETSc as the linear engine of the physics solvers (LinearSolverOptions::engine): KSPCG
// preconditioned by PCMG whose levels are molmesh's own (the operators and prolongations
// the built-in V-cycle selects: mesh levels discretised on the coarse meshes or Galerkin,
// then smoothed-aggregation levels below them; MultigridPreconditioner::level_*), or by
// any PETSc preconditioner (PCGAMG, hypre BoomerAMG, ICC) for comparison.
//
// Every rank holds the whole mesh and assembles the same system (assembly is cheap next to
// the solve); the matrices and vectors are distributed by rows in PETSc's default
// ownership ranges (PetscSplitOwnership), each rank inserting only the rows it owns, so
// the solve runs on all ranks. The solution is gathered on every rank.
//
// PETSc's options database is read last (KSPSetFromOptions), so `-ksp_*`, `-pc_*`,
// `-mg_levels_*`, `-mg_coarse_*` given on the command line override these defaults.
// PetscInitialize must have been called.
#include <string>

#include "solvers/multigrid/linear_solver.hpp"

namespace molmesh::solvers {

enum class PetscPreconditioner {
  kMolmeshMultigrid,  // PCMG on molmesh's levels
  kGamg,              // PCGAMG (smoothed aggregation on the fine matrix alone)
  kBoomerAmg,         // -pc_type hypre -pc_hypre_type boomeramg
  kIcc,               // ICC(0) (block Jacobi + ICC on 2+ ranks)
  kOptions,           // nothing set: whatever -pc_type says
};

struct PetscEngineOptions {
  PetscPreconditioner preconditioner = PetscPreconditioner::kMolmeshMultigrid;
  // Prefix for this solver's options (e.g. "reference_" gives -reference_ksp_type).
  std::string options_prefix;
};

LinearEngine petsc_engine(const PetscEngineOptions& options = {});

// Parses "mg", "gamg", "hypre", "icc", "options"; throws molmesh::Error otherwise.
PetscPreconditioner parse_petsc_preconditioner(const std::string& name);

}  // namespace molmesh::solvers
