#pragma once
// `smoluchowski` and `poisson` under a `solve` command: shared by `molmesh solve` (the
// built-in CG) and `molmesh-petsc` (PETSc's KSP under MPI), so both take the same options
// and write the same output.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli_context.hpp"
#include "solvers/multigrid/linear_solver.hpp"

namespace molmesh::cli {

struct SolveEngine {
  std::string name = "built-in";
  solvers::LinearEngine linear_engine;  // empty: the built-in CG
  // Only one MPI rank prints, writes JSON and stores fields.
  bool writes_output = true;
};

// Adds the two subcommands to `cmd` (which requires one of them).
void add_solve_subcommands(CLI::App* cmd, CliContext& ctx,
                           std::shared_ptr<const SolveEngine> engine);

}  // namespace molmesh::cli
