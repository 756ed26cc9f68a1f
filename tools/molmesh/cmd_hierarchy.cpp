// `molmesh hierarchy`: atoms -> surface -> multilevel surface and volume meshes (GAMer
// §4.3) with transfer operators, in one HDF5 file plus XDMF sidecars.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "command_registry.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/hierarchy/hierarchy_option_specs.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/sha256.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/pipeline/hierarchy_parameters.hpp"
#include "molmesh/pipeline/hierarchy_surface.hpp"
#include "molmesh/pipeline/report_json.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "naming_input.hpp"
#include "option_checks.hpp"
#include "spec_option.hpp"
#include "surface_options.hpp"
#include "volume_options.hpp"

namespace molmesh::cli {
namespace {

struct HierarchyArgs {
  std::string input;
  std::string output;
  std::string stats;
  // Atoms, surface and processing: the shared layer (surface_options.hpp). Its coarsening
  // thresholds are the levels' T0 here (HierarchyOptions::t0 by default).
  SurfaceCliOptions surface;
  VolumeCliOptions volume;  // the shared layer (volume_options.hpp), the same on every level
  double size_growth = HierarchyOptions{}.size_growth;
  bool renumber = HierarchyOptions{}.renumber;
};

void run(const HierarchyArgs& args, const CliContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const Reporter reporter = ctx.reporter();
  const Atoms atoms = read_atoms(args.input, args.surface.atoms, reporter);
  const SurfacePipelineOptions& pipeline = args.surface.pipeline;

  const auto surface = naming_input(args.input, [&] {
    return surface_from_atoms(atoms, hierarchy_surface_options(pipeline), reporter);
  });

  HierarchyOptions options;
  // The shared layer's coarsening thresholds are the levels' (--t0).
  options.t0 = pipeline.processing.t0;
  options.processing = pipeline.processing;  // its t0 is replaced by one T0 per level
  options.tetmesh = volume_options(args.volume, pipeline.blur.max_memory_bytes);
  process_levels_as(options, pipeline, surface.projection);
  options.size_growth = args.size_growth;
  options.renumber = args.renumber;

  HierarchyReport report;
  Hierarchy hierarchy = naming_input(args.input, [&] {
    return build_hierarchy(surface.surface, atoms, options, reporter, &report);
  });
  hierarchy.input_name = std::filesystem::path(args.input).filename().string();
  hierarchy.input_checksum = sha256_file(args.input);
  hierarchy.parameters = hierarchy_parameters(options, report, args.volume.active_site,
                                              SurfaceSource{args.surface.atoms, pipeline});
  write_hierarchy(args.output, hierarchy);
  if (!args.stats.empty()) {
    nlohmann::json document = to_json(report);
    document["input"] = {{"path", args.input}, {"atoms", atoms.size()}, {"output", args.output}};
    document["parameters"] = hierarchy.parameters;
    write_json_file(args.stats, document);
  }

  const double seconds = seconds_since(start);
  if (!ctx.quiet) {
    std::fprintf(stderr, "level  T0     surface verts  volume verts     tets  bandwidth\n");
    for (std::size_t l = 0; l < hierarchy.levels.size(); ++l) {
      const auto& level = hierarchy.levels[l];
      std::fprintf(stderr, "%5zu  %.3f  %13zu  %12zu  %7zu  %d -> %d\n", l, level.t0,
                   level.surface.points.size(), level.volume.points.size(),
                   level.volume.tetrahedra.size(), report.levels[l].bandwidth_before,
                   report.levels[l].bandwidth_after);
    }
    std::fprintf(stderr, "wrote %s (%.1f s)\n", args.output.c_str(), seconds);
  }
}

const CommandRegistration registration{
    "hierarchy", [](CLI::App& app, CliContext& ctx) {
      auto args = std::make_shared<HierarchyArgs>();
      auto* cmd = app.add_subcommand(
          "hierarchy",
          "Multilevel surface and volume meshes for multigrid (GAMer 4.3): level 0 finest, each "
          "coarser level coarsened and improved once more with the next T0; one HDF5 file with "
          "prolongation operators (restriction = transpose) and XDMF sidecars for ParaView");
      cmd->add_option("input", args->input,
                      "Molecule: .pqr, .pdb/.ent or .cif/.mmcif (optionally .gz)")
          ->required()
          ->check(CLI::ExistingFile);
      cmd->add_option(
             "-o,--output", args->output,
             "Output HDF5 file (OUT.h5); XDMF sidecars OUT.xdmf and OUT_L<L>_{volume,surface}.xdmf "
             "are written beside it")
          ->required()
          ->check(output_extension({".h5"}));
      cmd->add_option("--stats", args->stats,
                      "Write what each level took (seconds, bandwidths, TetGen), the outer "
                      "radius and the parameters as JSON to this file")
          ->type_name("FILE.json");
      args->surface.pipeline.processing.t0 = HierarchyOptions{}.t0;
      add_surface_options(*cmd, args->surface);
      // Every level is processed by the hierarchy itself, so there is no raw surface to
      // stop at, and the coarsening thresholds are the levels (--t0, as documented;
      // --coarsen is the shared layer's name for the same values).
      cmd->remove_option(cmd->get_option("--raw"));
      cmd->remove_option(cmd->get_option("--coarsen"));
      const HierarchyOptionSpecs& specs = kHierarchyOptionSpecs;
      add_spec_option(*cmd, specs.t0, args->surface.pipeline.processing.t0)
          ->delimiter(',')
          ->capture_default_str()
          ->type_name("T0[,T0...]");
      add_volume_options(*cmd, args->volume,
                         "; no vertex inside is removed by coarsening on any level");
      add_spec_option(*cmd, specs.size_growth, args->size_growth)->capture_default_str();
      add_spec_flag(*cmd, specs.renumber, args->renumber);
      cmd->callback([args, &ctx] { run(*args, ctx); });
    }};

}  // namespace
}  // namespace molmesh::cli
