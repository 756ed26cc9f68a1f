// molmesh-petsc: `molmesh solve` on PETSc under MPI (solvers/petsc/petsc_engine.hpp).
//   mpirun -n 2 molmesh-petsc smoluchowski HIER.h5 [molmesh solve options] [-- PETSc options]
// A separate program keeps MPI and PETSc out of the main CLI (docs/solvers-petsc.md).
// Everything after `--` goes to PETSc's options database (-ksp_monitor, -pc_type gamg,
// -mg_levels_ksp_type chebyshev, -log_view, ...); rank 0 prints and writes the output.
#include <petscsys.h>
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cli_context.hpp"
#include "help_formatter.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/version.hpp"
#include "option_spelling.hpp"
#include "solve_command.hpp"
#include "solvers/petsc/petsc_engine.hpp"

int main(int argc, char** argv) {
  using namespace molmesh::cli;
  // molmesh's options before `--`, PETSc's after it (each parser sees only its own).
  std::vector<char*> ours{argv[0]}, petsc{argv[0]};
  bool after = false;
  for (int i = 1; i < argc; ++i) {
    if (!after && std::strcmp(argv[i], "--") == 0) {
      after = true;
      continue;
    }
    (after ? petsc : ours).push_back(argv[i]);
  }
  int petsc_argc = static_cast<int>(petsc.size());
  petsc.push_back(nullptr);
  char** petsc_argv = petsc.data();
  if (PetscInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr) != 0) {
    std::fprintf(stderr, "molmesh-petsc: error: PetscInitialize failed\n");
    return kFailure;
  }
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  // Every rank reads the hierarchy and runs molmesh's threaded stages (assembly, the coarse
  // levels, the multigrid setup); with TBB's default each rank would use every core of the
  // node, so N ranks on a node would run N times as many threads as cores. Each rank gets
  // its share of the node's cores instead (results do not depend on it: docs/testing.md).
  MPI_Comm node = MPI_COMM_NULL;
  int ranks_on_node = 1;
  if (MPI_Comm_split_type(PETSC_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node) ==
      MPI_SUCCESS) {
    MPI_Comm_size(node, &ranks_on_node);
    MPI_Comm_free(&node);
  }
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const tbb::global_control threads_per_rank(
      tbb::global_control::max_allowed_parallelism,
      std::max<std::size_t>(1, cores / static_cast<unsigned>(std::max(1, ranks_on_node))));

  CLI::App app{
      "molmesh-petsc: molmesh's solvers on PETSc (KSPCG + PCMG on the hierarchy's levels) under "
      "MPI; PETSc options after --"};
  use_help_formatter(app);
  app.set_version_flag("--version", std::string("molmesh-petsc ") + molmesh::version());
  app.fallthrough();
  app.require_subcommand(1);
  CliContext ctx;
  app.add_flag("-q,--quiet", ctx.quiet, "Do not show progress")->configurable(false);
  std::string preconditioner = "mg";
  app.add_option("--pc", preconditioner,
                 "mg (PCMG on molmesh's levels), gamg (PCGAMG), hypre (BoomerAMG), icc, or "
                 "options (only -pc_type from the PETSc options)")
      ->check(CLI::IsMember({"mg", "gamg", "hypre", "icc", "options"}))
      ->capture_default_str();
  auto engine = std::make_shared<SolveEngine>();
  engine->writes_output = rank == 0;
  if (rank != 0) ctx.quiet = true;
  add_solve_subcommands(&app, ctx, engine);
  app.parse_complete_callback([&] {
    engine->name = "petsc (" + preconditioner + ", " + std::to_string(size) + " rank" +
                   (size == 1 ? "" : "s") + ")";
    engine->linear_engine = molmesh::solvers::petsc_engine(
        {.preconditioner = molmesh::solvers::parse_petsc_preconditioner(preconditioner),
         .options_prefix = {}});
  });

  int status = kSuccess;
  try {
    app.parse(static_cast<int>(ours.size()), ours.data());
  } catch (const CLI::ParseError& e) {
    status = rank == 0 ? (app.exit(e) == 0 ? kSuccess : kUsage)
                       : (e.get_exit_code() == 0 ? kSuccess : kUsage);
  } catch (const molmesh::OptionError& e) {
    std::fprintf(stderr, "molmesh-petsc: error: %s\n",
                 molmesh::cli::with_cli_flags(e.what()).c_str());
    status = kUsage;
  } catch (const molmesh::InputError& e) {
    std::fprintf(stderr, "molmesh-petsc: error: %s\n",
                 molmesh::cli::with_cli_flags(e.what()).c_str());
    status = kInputError;
  } catch (const molmesh::OutputError& e) {
    std::fprintf(stderr, "molmesh-petsc: error: %s\n",
                 molmesh::cli::with_cli_flags(e.what()).c_str());
    status = kOutputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "molmesh-petsc: error: %s\n",
                 molmesh::cli::with_cli_flags(e.what()).c_str());
    status = kFailure;
  }
  PetscFinalize();
  return status;
}
