#include "molmesh/pipeline/surface_pipeline.hpp"

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/surface/components.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/ball_union.hpp"
#include "molmesh/volume/level_set_projection.hpp"
#include "molmesh/volume/ses_field.hpp"

namespace molmesh {
namespace {

using Clock = std::chrono::steady_clock;

// Marching cubes, cavity removal, then processing (unless raw).
void extract_and_process(const Grid& grid, double level, const SurfacePipelineOptions& options,
                         const std::function<Vec3(const Vec3&)>& projection,
                         const Reporter& reporter, SurfacePipelineResult& result) {
  auto start = Clock::now();
  result.level = level;
  SurfaceMesh raw = marching_cubes(grid, level, reporter);
  const double mc_seconds = seconds_since(start);
  if (raw.triangles.empty())
    throw Error("the isosurface at isovalue " + std::to_string(level) +
                " is empty; lower the isovalue or check the input");
  const auto stats_of = [&](const SurfaceMesh& mesh) -> std::optional<SurfaceStats> {
    if (!options.measure) return std::nullopt;
    return compute_surface_stats(mesh);
  };
  result.stages.push_back({"marching cubes", mc_seconds, stats_of(raw)});

  if (options.min_cavity_volume > 0.0) {
    start = Clock::now();
    std::size_t removed = 0;
    raw = drop_small_cavities(raw, options.min_cavity_volume, &removed);
    if (raw.triangles.empty())
      throw Error("removing cavities left no surface (is the surface inside out?)");
    result.stages.push_back({"cavities", seconds_since(start),
                             removed > 0 ? stats_of(raw) : result.stages.back().stats});
  }

  result.raw = std::move(raw);
  if (options.raw) {
    result.surface = result.raw;
    return;
  }
  ProcessingOptions processing = options.processing;
  if (options.keep_on_surface && projection && !processing.project) processing.project = projection;
  processing.record_stages = processing.record_stages && options.measure;
  if (!options.keep_spheres_file.empty()) {
    for (const Sphere& s : read_spheres(options.keep_spheres_file))
      processing.keep_spheres.push_back(s);
  }
  ProcessingResult processed = process_surface(result.raw, processing, reporter);
  for (ProcessingStage& stage : processed.stages)
    result.stages.push_back({std::move(stage.name), stage.seconds, stage.stats});
  if (options.measure) {
    start = Clock::now();
    result.dislocation = measure_dislocation(processed.mesh, result.raw);
    result.stages.push_back({"dislocation", seconds_since(start), std::nullopt});
  }
  result.surface = std::move(processed.mesh);
}

}  // namespace

double level_of(const SurfacePipelineOptions& options) {
  return options.surface == SurfaceKind::kGaussian ? options.isovalue : 0.0;
}

Grid surface_volume(const Atoms& atoms, const SurfacePipelineOptions& options,
                    const Reporter& reporter) {
  switch (options.surface) {
    case SurfaceKind::kVdw:
      return ball_union_field(atoms, 0.0, options.blur.spacing, reporter);
    case SurfaceKind::kSas:
      return ball_union_field(atoms, options.probe_radius, options.blur.spacing, reporter);
    case SurfaceKind::kSes:
      return ses_field(atoms, options.probe_radius, options.blur.spacing, reporter);
    case SurfaceKind::kGaussian:
      break;
  }
  BlurOptions blur = options.blur;
  blur.isovalue = options.isovalue;
  return options.blur_method == BlurMethod::kFast
             ? fast_blur(atoms, blur, SplatMethod::kTrilinear, reporter)
             : blur_atoms(atoms, blur, reporter);
}

SurfacePipelineResult surface_from_atoms(const Atoms& atoms, const SurfacePipelineOptions& options,
                                         const Reporter& reporter) {
  SurfacePipelineResult result;
  const auto start = Clock::now();
  auto grid = std::make_shared<Grid>(surface_volume(atoms, options, reporter));
  result.stages.push_back({options.surface == SurfaceKind::kGaussian ? "blur" : "distance field",
                           seconds_since(start), std::nullopt});
  result.grid_dims = grid->dims;
  // Distance-field surfaces are exact level sets: processing keeps its vertices on them.
  if (options.surface != SurfaceKind::kGaussian)
    result.projection = level_set_projection(grid, level_of(options));
  extract_and_process(*grid, level_of(options), options, result.projection, reporter, result);
  if (options.keep_volume) result.volume = *grid;
  return result;
}

SurfacePipelineResult surface_from_grid(const Grid& grid, const SurfacePipelineOptions& options,
                                        const Reporter& reporter) {
  SurfacePipelineResult result;
  extract_and_process(grid, options.isovalue, options, {}, reporter, result);
  return result;
}

}  // namespace molmesh
