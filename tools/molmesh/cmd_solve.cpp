// `molmesh solve`: the built-in P1 finite-element solvers on a level of a mesh hierarchy,
// with multigrid-preconditioned CG over the coarser levels (GAMer §4.4).
//   molmesh solve smoluchowski HIER.h5   diffusion-limited rate constant (M^-1 s^-1)
//   molmesh solve poisson HIER.h5 --pqr  electrostatic solvation energy (kJ/mol)
// The subcommands live in solve_command.cpp (shared with molmesh-petsc).
#include <CLI/CLI.hpp>
#include <memory>

#include "command_registry.hpp"
#include "solve_command.hpp"

namespace molmesh::cli {
namespace {

const CommandRegistration registration{
    "solve", [](CLI::App& app, CliContext& ctx) {
      auto* cmd = app.add_subcommand(
          "solve",
          "Built-in P1 finite-element solvers on a hierarchy level, CG preconditioned by multigrid "
          "over the coarser levels; results to stdout/JSON, fields into the HDF5 (see XDMF)");
      cmd->require_subcommand(1);
      add_solve_subcommands(cmd, ctx, std::make_shared<SolveEngine>());
    }};

}  // namespace
}  // namespace molmesh::cli
