// `molmesh surface`: atoms -> volume (SES distance field by default, or --surface
// sas|vdw|gaussian) -> marching cubes -> (processed) surface mesh.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

#include "command_registry.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "molmesh/pipeline/report_json.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "naming_input.hpp"
#include "option_checks.hpp"
#include "surface_options.hpp"

namespace molmesh::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct SurfaceArgs {
  std::string input;
  std::string output;
  std::string stats;
  std::string write_volume;
  SurfaceCliOptions options;
};

void run(const SurfaceArgs& args, const CliContext& ctx) {
  const Reporter reporter = ctx.reporter();
  if (!is_surface_mesh_path(args.output))
    throw molmesh::Error("cannot tell the output format from '" + args.output +
                         "': use .off, .ply, .obj or .stl");
  const auto total_start = Clock::now();
  StageTimings timings;

  if (!args.write_volume.empty() && !is_volume_path(args.write_volume))
    throw molmesh::Error("cannot tell the volume format from '" + args.write_volume +
                         "': use .dx, .mrc or .map");
  // A scalar volume (.dx, .mrc, .map) is contoured directly (GAMer Fig. 1's second input).
  const bool volume_input = is_volume_path(args.input);
  auto start = Clock::now();
  Atoms atoms;
  Grid volume;
  if (volume_input) {
    volume = read_volume(args.input);
  } else {
    atoms = read_atoms(args.input, args.options.atoms, reporter);
  }
  timings.emplace_back("read", seconds_since(start));

  SurfacePipelineOptions pipeline = args.options.pipeline;
  pipeline.keep_volume = !args.write_volume.empty() && !volume_input;
  pipeline.measure = !args.stats.empty();  // nobody sees the per-stage stats otherwise
  SurfacePipelineResult result = naming_input(args.input, [&] {
    return volume_input ? surface_from_grid(volume, pipeline, reporter)
                        : surface_from_atoms(atoms, pipeline, reporter);
  });
  if (!args.write_volume.empty()) {
    start = Clock::now();
    write_volume(args.write_volume, volume_input ? volume : result.volume);
    timings.emplace_back("write volume", seconds_since(start));
  }
  for (const StageRecord& stage : result.stages) timings.emplace_back(stage.name, stage.seconds);

  start = Clock::now();
  reporter.progress("write", 0.0);
  write_surface_mesh(args.output, result.surface);
  reporter.progress("write", 1.0);
  timings.emplace_back("write", seconds_since(start));

  if (!args.stats.empty()) {
    const SurfaceStats stats = compute_surface_stats(result.surface);
    timings.emplace_back("total", seconds_since(total_start));
    nlohmann::json input;
    input["path"] = args.input;
    input["atoms"] = atoms.size();
    input["grid_dims"] = volume_input ? volume.dims : result.grid_dims;
    input["raw_surface"] = to_json(compute_surface_stats(result.raw));
    input["output"] = args.output;
    // A volume input has no atom selection to record (as molmesh.surface(Volume) records).
    const SurfaceSource source{
        volume_input ? std::nullopt : std::optional<AtomReadOptions>(args.options.atoms),
        args.options.pipeline, volume_input};
    nlohmann::json document =
        stats_document(stats, timings, input, surface_parameters_json(source));
    document.update(surface_result_json(result));
    write_json_file(args.stats, document);
  }
}

const CommandRegistration registration{
    "surface", [](CLI::App& app, CliContext& ctx) {
      auto args = std::make_shared<SurfaceArgs>();
      auto* cmd = app.add_subcommand(
          "surface",
          "Molecular surface mesh from atoms: the solvent-excluded surface (or --surface "
          "sas|vdw|gaussian, the last GAMer's Eq. 1) sampled on a grid, marching cubes, then "
          "surface processing unless --raw. A scalar volume (.dx, .mrc, .map) is contoured "
          "at --isovalue instead of blurring atoms.");
      cmd->add_option(
             "INPUT", args->input,
             "Atoms: .pqr, .pdb/.ent, .cif/.mmcif (optionally .gz); or a scalar volume "
             ".dx/.mrc/.map whose level --isovalue is the surface (inside = larger values)")
          ->required()
          ->check(CLI::ExistingFile);
      cmd->add_option("-o,--output", args->output, "Output surface mesh (.off, .ply, .obj, .stl)")
          ->required()
          ->check(output_extension({".off", ".ply", ".obj", ".stl"}))
          ->type_name("OUT");
      cmd->add_option("--stats", args->stats,
                      "Write surface metrics, stage timings and parameters as JSON to this file")
          ->type_name("FILE.json");
      cmd->add_option("--write-volume", args->write_volume,
                      "Also write the blurred volume (or the input volume) to this .dx or .mrc "
                      "file, e.g. to contour it again or view it")
          ->type_name("FILE");
      add_surface_options(*cmd, args->options);
      cmd->callback([args, &ctx] { run(*args, ctx); });
    }};

}  // namespace
}  // namespace molmesh::cli
