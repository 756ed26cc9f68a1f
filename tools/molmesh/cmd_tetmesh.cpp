// `molmesh tetmesh`: atoms (through the surface pipeline) or a surface mesh file ->
// TetGen tetrahedral mesh of the molecule, the solvent, or both (GAMer §2.4).
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "command_registry.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_mesh_io.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "naming_input.hpp"
#include "option_checks.hpp"
#include "surface_options.hpp"
#include "volume_options.hpp"

namespace molmesh::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct TetmeshArgs {
  std::string input;
  std::string output;
  std::string stats;
  std::string surface_output;
  VolumeCliOptions volume;
  SurfaceCliOptions surface;
};

void run(const TetmeshArgs& args, const CliContext& ctx) {
  const Reporter reporter = ctx.reporter();
  const auto total_start = Clock::now();
  StageTimings timings;
  const TetMeshOptions options =
      volume_options(args.volume, args.surface.pipeline.blur.max_memory_bytes);

  Atoms atoms;
  SurfaceMesh surface;
  nlohmann::json input;
  input["path"] = args.input;
  auto start = Clock::now();
  if (is_surface_mesh_path(args.input)) {
    surface = read_surface_mesh(args.input);
    timings.emplace_back("read", seconds_since(start));
    input["kind"] = "surface";
  } else {
    atoms = read_atoms(args.input, args.surface.atoms, reporter);
    timings.emplace_back("read", seconds_since(start));
    SurfacePipelineOptions pipeline = args.surface.pipeline;
    pipeline.measure = false;  // the tetmesh --stats report has no per-stage surface stats
    SurfacePipelineResult result =
        naming_input(args.input, [&] { return surface_from_atoms(atoms, pipeline, reporter); });
    for (const StageRecord& stage : result.stages) timings.emplace_back(stage.name, stage.seconds);
    surface = std::move(result.surface);
    input["kind"] = "atoms";
    input["atoms"] = atoms.size();
    input["grid_dims"] = result.grid_dims;
    if (!args.surface_output.empty()) write_surface_mesh(args.surface_output, surface);
  }
  input["surface_vertices"] = surface.points.size();
  input["surface_triangles"] = surface.triangles.size();

  TetMeshReport report;
  start = Clock::now();
  const TetMesh mesh = naming_input(
      args.input, [&] { return tetrahedralize(surface, atoms, options, reporter, &report); });
  timings.emplace_back("tetrahedralize", seconds_since(start));

  start = Clock::now();
  reporter.progress("write", 0.0);
  write_volume_mesh(args.output, mesh);
  reporter.progress("write", 1.0);
  timings.emplace_back("write", seconds_since(start));

  if (!args.stats.empty()) {
    timings.emplace_back("total", seconds_since(total_start));
    nlohmann::json doc = to_json(compute_tet_stats(mesh));
    doc["tetgen"] = to_json(report);
    doc["domain"] = args.volume.domain;
    doc["timings_s"] = nlohmann::json::object();
    for (const auto& [name, seconds] : timings) doc["timings_s"][name] = seconds;
    input["output"] = args.output;
    doc["input"] = input;
    std::optional<SurfaceSource> source;  // surface-file input: the tetmesh options only
    if (!atoms.empty()) source = SurfaceSource{args.surface.atoms, args.surface.pipeline};
    doc["parameters"] = tetmesh_parameters_json(options, source);
    write_json_file(args.stats, doc);
  }
}

const CommandRegistration registration{
    "tetmesh", [](CLI::App& app, CliContext& ctx) {
      auto args = std::make_shared<TetmeshArgs>();
      auto* cmd = app.add_subcommand(
          "tetmesh",
          "Tetrahedral mesh (TetGen) of the molecule (interior, every atom centre a node), the "
          "solvent up to an outer sphere (exterior), or both in one conforming mesh (full)");
      cmd->add_option("INPUT", args->input,
                      "Atoms (.pqr, .pdb/.ent, .cif/.mmcif; the surface pipeline runs first with "
                      "the options below) or a closed surface mesh (.off, .ply, .obj, .stl) used "
                      "as given")
          ->required()
          ->check(CLI::ExistingFile);
      cmd->add_option("-o,--output", args->output,
                      "Output volume mesh: .m/.mcsf (FETK MCSF, for APBS/SMOL), .vtu (VTK), "
                      ".msh (Gmsh 2.2), .msh4 (Gmsh 4.1 written under that name)")
          ->required()
          ->check(output_extension({".m", ".mcsf", ".vtu", ".msh", ".msh4"}))
          ->type_name("OUT");
      cmd->add_option("--stats", args->stats,
                      "Write tetrahedron quality (counts per region and marker, dihedral angles, "
                      "radius-edge ratios, volumes), TetGen report, timings as JSON")
          ->type_name("FILE.json");
      add_volume_options(*cmd, args->volume, "");
      add_tetgen_switches_option(*cmd, args->volume.tet.tetgen_switches);
      cmd->add_option("--surface-output", args->surface_output,
                      "Also write the molecular surface that was meshed (atom input only)")
          ->type_name("FILE");
      add_surface_options(*cmd, args->surface);
      cmd->callback([args, &ctx] { run(*args, ctx); });
    }};

}  // namespace
}  // namespace molmesh::cli
