// `molmesh improve`: a user's surface mesh (OFF/PLY/OBJ/STL or an MSMS .vert/.face pair)
// -> repair -> the same quality improvement, coarsening and smoothing as `molmesh surface`
// (GAMer §4.2, Fig. 10).
#include <chrono>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/msms.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/pipeline/improve_option_specs.hpp"
#include "molmesh/pipeline/improve_pipeline.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "molmesh/pipeline/report_json.hpp"
#include "molmesh/processing/dislocation.hpp"
#include "molmesh/processing/mesh_repair.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/processing/processing_option_specs.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "option_checks.hpp"
#include "spec_option.hpp"

namespace molmesh::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct ImproveArgs {
  std::string input;
  std::string output;
  std::string stats;
  bool no_coarsen = false;
  ImprovePipelineOptions options;
};

SurfaceMesh read_input(const std::filesystem::path& path) {
  if (is_msms_path(path)) return read_msms(path);
  if (is_surface_mesh_path(path)) return read_surface_mesh(path);
  throw InputError(path.string(),
                   "cannot tell the mesh format from the extension: use .off, .ply, .obj, .stl "
                   "or an MSMS .vert/.face pair");
}

void write_output(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  if (is_msms_path(path)) {
    write_msms(path, mesh);
  } else {
    write_surface_mesh(path, mesh);
  }
}

void run(const ImproveArgs& args, const CliContext& ctx) {
  const Reporter reporter = ctx.reporter();
  const std::filesystem::path out_path(args.output);
  if (!is_surface_mesh_path(out_path) && !is_msms_path(out_path)) {
    throw Error("cannot tell the output format from '" + args.output +
                "': use .off, .ply, .obj, .stl, or .vert/.face for MSMS");
  }
  const auto total_start = Clock::now();
  StageTimings timings;

  auto start = Clock::now();
  reporter.progress("read", 0.0);
  const SurfaceMesh input = read_input(args.input);
  reporter.progress("read", 1.0);
  timings.emplace_back("read", seconds_since(start));

  ImprovePipelineOptions options = args.options;
  if (args.no_coarsen) options.processing.t0.clear();
  ImprovePipelineResult improved = improve_surface(input, args.input, options, reporter);
  timings.emplace_back("repair", improved.repair_seconds);
  for (const ProcessingStage& s : improved.stages) timings.emplace_back(s.name, s.seconds);
  const SurfaceMesh& repaired = improved.repaired;
  const SurfaceMesh& result = improved.surface;
  const MeshRepairReport& report = improved.repair;

  start = Clock::now();
  reporter.progress("write", 0.0);
  write_output(out_path, result);
  reporter.progress("write", 1.0);
  timings.emplace_back("write", seconds_since(start));

  if (!args.stats.empty()) {
    const SurfaceStats stats = compute_surface_stats(result);
    start = Clock::now();
    const Dislocation d = measure_dislocation(result, repaired);
    timings.emplace_back("dislocation", seconds_since(start));
    timings.emplace_back("total", seconds_since(total_start));
    nlohmann::json in;
    in["path"] = args.input;
    in["input_surface"] = to_json(compute_surface_stats(repaired));
    in["repair"] = to_json(report);
    in["output"] = args.output;
    nlohmann::json doc = stats_document(stats, timings, in, improve_parameters_json(options));
    add_dislocation(doc, d);
    write_json_file(args.stats, doc);
  }
}

const CommandRegistration registration{
    "improve", [](CLI::App& app, CliContext& ctx) {
      auto args = std::make_shared<ImproveArgs>();
      auto* cmd = app.add_subcommand(
          "improve",
          "Repair and improve a user's surface mesh (GAMer §4.2): merge duplicate vertices, drop "
          "degenerate and duplicate triangles, orient consistently and outward, then quality "
          "improvement, coarsening and smoothing as in `molmesh surface`. Meshes with holes or "
          "non-manifold edges are refused with counts and example locations.");
      cmd->add_option("MESH", args->input,
                      "Input surface: .off, .ply, .obj, .stl, or an MSMS pair (NAME.vert or "
                      "NAME.face; both must exist)")
          ->required();
      cmd->add_option("-o,--output", args->output,
                      "Output surface (.off, .ply, .obj, .stl, or .vert/.face for an MSMS pair)")
          ->required()
          ->type_name("OUT");
      cmd->add_option("--stats", args->stats,
                      "Write metrics of the result (angles, counts, closed, manifold), the input's "
                      "metrics, the repairs made, the dislocation from the (repaired) input in Å "
                      "and stage timings as JSON to this file")
          ->type_name("FILE.json");
      const ProcessingOptionSpecs& processing = kProcessingOptionSpecs;
      const ImproveOptionSpecs& specs = kImproveOptionSpecs;
      ProcessingOptions& p = args->options.processing;
      add_spec_option(*cmd, specs.t0, p.t0)
          ->delimiter(',')
          ->capture_default_str()
          ->type_name("T0[,T0...]");
      cmd->add_flag("--no-coarsen", args->no_coarsen,
                    "Quality improvement and smoothing only: keep every vertex");
      add_spec_flag(*cmd, specs.repair_only, args->options.repair_only);
      add_spec_option(*cmd, processing.rings, p.rings)->capture_default_str()->type_name("K");
      add_spec_option(*cmd, processing.sweeps, p.improve.sweeps)
          ->capture_default_str()
          ->type_name("N");
      add_spec_option(*cmd, processing.feature_weight, p.improve.feature_weight)
          ->capture_default_str()
          ->type_name("W");
      add_spec_option(*cmd, processing.smooth_iterations, p.smoothing.normal_iterations)
          ->capture_default_str()
          ->type_name("N");
      add_spec_flag(*cmd, processing.flips, p.flips);
      add_spec_option(*cmd, processing.cleanup_rounds, p.cleanup_rounds)
          ->capture_default_str()
          ->type_name("N");
      add_spec_option(*cmd, specs.merge_tolerance, args->options.repair.merge_tolerance)
          ->capture_default_str()
          ->type_name("D");
      cmd->callback([args, &ctx] { run(*args, ctx); });
    }};

}  // namespace
}  // namespace molmesh::cli
