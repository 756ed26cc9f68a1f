// `molmesh export HIER.h5 -o PREFIX`: every level of a hierarchy (or one, --level) as
// MCSF / VTU / Gmsh meshes and the prolongations as PETSc binary and Matrix Market files,
// for solvers that do not read HDF5 (io/hierarchy_export.hpp lists the files).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "command_registry.hpp"
#include "molmesh/io/hierarchy_export.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"

namespace molmesh::cli {
namespace {

struct ExportArgs {
  std::string hierarchy;
  std::string prefix;
  int level = -1;
  bool all_levels = false;
  bool no_prolongations = false;
};

void run(const ExportArgs& args, const CliContext& ctx) {
  const Reporter reporter = ctx.reporter();
  reporter.progress("export: read", 0.0);
  const Hierarchy h = read_hierarchy(args.hierarchy);
  reporter.progress("export: write", 0.0);
  ExportOptions options;
  options.level = args.level;
  options.prolongations = !args.no_prolongations;
  const auto files = export_hierarchy(h, args.prefix, options);
  reporter.progress("export: write", 1.0);
  for (const auto& f : files) std::printf("%s\n", f.string().c_str());
}

const CommandRegistration registration{
    "export", [](CLI::App& app, CliContext& ctx) {
      auto args = std::make_shared<ExportArgs>();
      auto* cmd = app.add_subcommand(
          "export",
          "Write hierarchy levels as MCSF (.m, FETK/APBS), VTU and Gmsh meshes (volume; surface as "
          "VTU and OFF) and the prolongations as PETSc binary (.petsc) and Matrix Market (.mtx); "
          "prints the files written (see docs/formats.md)");
      cmd->add_option("hierarchy", args->hierarchy,
                      "Mesh hierarchy (HDF5 from `molmesh hierarchy`)")
          ->required()
          ->check(CLI::ExistingFile);
      cmd->add_option("-o,--output", args->prefix,
                      "Output prefix: PREFIX_L<L>_volume.m, PREFIX_P<c>_to_<f>_volume.petsc, ...")
          ->required();
      auto* level =
          cmd->add_option("--level", args->level,
                          "Export only this level (0 = finest) and the prolongation into it")
              ->check(CLI::NonNegativeNumber);
      cmd->add_flag("--all-levels", args->all_levels, "Export every level (the default)")
          ->excludes(level);
      cmd->add_flag("--no-prolongations", args->no_prolongations, "Write the meshes only");
      cmd->callback([args, &ctx] { run(*args, ctx); });
    }};

}  // namespace
}  // namespace molmesh::cli
