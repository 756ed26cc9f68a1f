#include "molmesh/pipeline/surface_pipeline.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/pipeline/surface_option_specs.hpp"
#include "molmesh/surface/components.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/ball_union.hpp"
#include "molmesh/volume/gaussian_field.hpp"
#include "molmesh/volume/level_set_projection.hpp"
#include "molmesh/volume/ses_field.hpp"

namespace molmesh {
namespace {

using Clock = std::chrono::steady_clock;

// The centre of the local frame atoms are blurred and meshed in: their mean, rounded to a
// multiple of the grid spacing so that moving a molecule by whole cells moves nothing but
// this centre (the results are then the same wherever the molecule sits, issue 18).
// Molecules centred farther than this from the origin (Å) are blurred in a local frame.
constexpr double kLocalFrameDistance = 1e3;

// The Newton projection onto Eq. 1's level set (keep_on_surface): steps of at most
// this many Å, until a step is shorter than the tolerance (Å).
constexpr double kLevelSetMaxStep = 0.5;
constexpr double kLevelSetTolerance = 1e-4;

// A processed surface with an angle outside these bounds (degrees) is not one processing
// could improve: features finer than the grid (tight Gaussians, van der Waals creases) or
// tiny marching-cubes fragments. It is still returned, with a warning, because whether it
// is usable is the caller's call; TetGen often refuses such surfaces later.
constexpr double kPoorMinAngle = 5.0;
constexpr double kPoorMaxAngle = 160.0;

void warn_about_poor_angles(const SurfaceMesh& mesh, double spacing, const Reporter& reporter) {
  const SurfaceStats stats = compute_surface_stats(mesh);
  if (stats.min_angle_deg >= kPoorMinAngle && stats.max_angle_deg <= kPoorMaxAngle) return;
  char line[320];
  std::snprintf(line, sizeof line,
                "the processed surface has angles from %.2f to %.1f degrees (%d components): "
                "features finer than the %.3g A grid; expect TetGen to refuse it or a poor "
                "solve. A finer grid spacing or a smoother surface (a Gaussian with "
                "blobbyness closer to 0, or the SES) gives a usable mesh",
                stats.min_angle_deg, stats.max_angle_deg, stats.components, spacing);
  reporter.warn(line);
}

Vec3 frame_centre(const Atoms& atoms, double spacing) {
  Vec3 sum = Vec3::Zero();
  std::size_t n = 0;
  for (const auto& a : atoms) {
    if (!a.center.allFinite()) return Vec3::Zero();  // the blur refuses it with a message
    sum += a.center;
    ++n;
  }
  if (n == 0 || !(spacing > 0.0) || !std::isfinite(spacing)) return Vec3::Zero();
  const Vec3 mean = sum / static_cast<double>(n);
  // Near the origin the input frame keeps every digit the blur needs; staying in it keeps the
  // atom path bit-identical to contouring the same Eq. 1 volume directly (surface_from_grid).
  if (mean.norm() < kLocalFrameDistance) return Vec3::Zero();
  return Vec3(std::round(mean.x() / spacing) * spacing, std::round(mean.y() / spacing) * spacing,
              std::round(mean.z() / spacing) * spacing);
}

// Marching cubes, cavity removal, then processing (unless raw). `centre` is the local
// frame's origin in input coordinates (keep spheres are given in input coordinates).
void extract_and_process(const Grid& grid, double level, const SurfacePipelineOptions& options,
                         const std::function<Vec3(const Vec3&)>& projection,
                         const Reporter& reporter, SurfacePipelineResult& result,
                         const Vec3& centre = Vec3::Zero()) {
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
  if (keeps_on_surface(options) && projection && !processing.project)
    processing.project = projection;
  processing.record_stages = processing.record_stages && options.measure;
  if (!options.keep_spheres_file.empty()) {
    for (Sphere s : read_spheres(options.keep_spheres_file)) {
      s.center -= centre;
      processing.keep_spheres.push_back(s);
    }
  }
  ProcessingResult processed = process_surface(result.raw, processing, reporter);
  for (ProcessingStage& stage : processed.stages)
    result.stages.push_back({std::move(stage.name), stage.seconds,
                             processing.record_stages ? std::optional(stage.stats) : std::nullopt});
  if (options.measure) {
    start = Clock::now();
    result.dislocation = measure_dislocation(processed.mesh, result.raw);
    result.stages.push_back({"dislocation", seconds_since(start), std::nullopt});
  }
  result.surface = std::move(processed.mesh);
  warn_about_poor_angles(result.surface, grid.spacing.maxCoeff(), reporter);
}

// Eq. 1 as the blur evaluates it, exactly: with the fast blur's one decay rate, the Eq. 1 that
// its Eq. 2 equals.
GaussianField exact_field(const Atoms& atoms, const SurfacePipelineOptions& options) {
  BlurOptions blur = options.blur;
  blur.isovalue = options.isovalue;
  if (options.blur_method == BlurMethod::kFast)
    return GaussianField(with_constant_decay(atoms, constant_decay_rate(atoms, blur.blobbyness)),
                         blur);
  return GaussianField(atoms, blur);
}

}  // namespace

void SurfacePipelineOptions::validate(SurfaceInput input) const {
  const SurfaceOptionSpecs& specs = kSurfaceOptionSpecs;
  check_range(specs.probe_radius, probe_radius);
  check_range(specs.spacing, blur.spacing);
  check_range(specs.blobbyness, blur.blobbyness);
  if (input == SurfaceInput::kAtoms) {
    check_range(specs.isovalue, isovalue);
  } else if (!std::isfinite(isovalue)) {
    throw OptionError("`isovalue` must be a finite number (got " + std::to_string(isovalue) + ")");
  }
  check_range(specs.min_cavity_volume, min_cavity_volume);
  if (input == SurfaceInput::kAtoms) require_gaussian_options_apply(*this);
  processing.validate();
}

void require_gaussian_options_apply(const SurfacePipelineOptions& options) {
  if (options.surface == SurfaceKind::kGaussian) return;
  // Changed from the defaults means asked for: a Gaussian parameter given with another surface
  // would be silently ignored, and the user would mesh a surface they did not mean (the
  // default became ses, so `--blobbyness -2` alone used to mean a Gaussian surface).
  const SurfacePipelineOptions defaults;
  const SurfaceOptionSpecs& specs = kSurfaceOptionSpecs;
  const auto refuse = [&](std::string_view member) {
    throw OptionError(
        "`" + std::string(member) + "` applies only to the Gaussian surface, not to " +
        std::string(surface_kind_name(options.surface)) +
        ": set `surface` to gaussian to mesh the paper's blurred density, or leave `" +
        std::string(member) + "` out for the " + std::string(surface_kind_name(options.surface)) +
        " (docs/surface.md)");
  };
  if (options.blur.blobbyness != defaults.blur.blobbyness) refuse(specs.blobbyness.member);
  if (options.isovalue != defaults.isovalue) refuse(specs.isovalue.member);
  if (options.blur.truncation != defaults.blur.truncation) refuse(specs.truncation.member);
  if (options.blur_method != defaults.blur_method) refuse(specs.blur.member);
}

bool keeps_on_surface(const SurfacePipelineOptions& options) {
  return options.keep_on_surface.value_or(options.surface == SurfaceKind::kGaussian);
}

bool settles_on_surface(const SurfacePipelineOptions& options) {
  return !options.keep_on_surface.has_value() && options.surface != SurfaceKind::kGaussian;
}

bool volume_keeps_on_surface(const SurfacePipelineOptions& options) {
  return options.keep_on_surface.value_or(false);
}

double level_of(const SurfacePipelineOptions& options) {
  return options.surface == SurfaceKind::kGaussian ? options.isovalue : 0.0;
}

std::vector<Sphere> all_keep_spheres(const SurfacePipelineOptions& options) {
  std::vector<Sphere> spheres = options.processing.keep_spheres;
  if (!options.keep_spheres_file.empty()) {
    for (const Sphere& s : read_spheres(options.keep_spheres_file)) spheres.push_back(s);
  }
  return spheres;
}

Grid surface_volume(const Atoms& atoms, const SurfacePipelineOptions& options,
                    const Reporter& reporter) {
  switch (options.surface) {
    case SurfaceKind::kVdw:
      return ball_union_field(atoms, 0.0, options.blur.spacing, reporter,
                              options.blur.max_memory_bytes);
    case SurfaceKind::kSas:
      return ball_union_field(atoms, options.probe_radius, options.blur.spacing, reporter,
                              options.blur.max_memory_bytes);
    case SurfaceKind::kSes:
      return ses_field(atoms, options.probe_radius, options.blur.spacing, reporter,
                       options.blur.max_memory_bytes);
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
  options.validate(SurfaceInput::kAtoms);
  SurfacePipelineResult result;
  // Local frame: far from the origin (1e6 Å and more) coordinates lose the digits the
  // processing needs; shifted to the molecule's centre they keep them.
  const Vec3 centre = frame_centre(atoms, options.blur.spacing);
  SurfacePipelineOptions local_options = options;
  for (Sphere& s : local_options.processing.keep_spheres) s.center -= centre;
  Atoms local_atoms = atoms;
  for (Atom& a : local_atoms) a.center -= centre;
  const auto start = Clock::now();
  auto grid = std::make_shared<Grid>(surface_volume(local_atoms, options, reporter));
  result.stages.push_back({options.surface == SurfaceKind::kGaussian ? "blur" : "distance field",
                           seconds_since(start), std::nullopt});
  result.grid_dims = grid->dims;
  // Distance-field surfaces are exact level sets of the grid; the Gaussian's is Eq. 1's, built
  // once for the projection and the measurement.
  std::shared_ptr<const GaussianField> field;
  if (options.surface == SurfaceKind::kGaussian && (keeps_on_surface(options) || options.measure))
    field = std::make_shared<const GaussianField>(exact_field(local_atoms, options));
  std::function<Vec3(const Vec3&)> local_projection;
  if (options.surface != SurfaceKind::kGaussian) {
    local_projection = level_set_projection(grid, level_of(options));
  } else if (keeps_on_surface(options)) {
    const double level = options.isovalue;
    local_projection = [field, level](const Vec3& p) {
      return newton_to_level([&field](const Vec3& x, Vec3* g) { return field->value(x, g); }, level,
                             p, kLevelSetMaxStep, kLevelSetTolerance);
    };
  }
  if (settles_on_surface(options)) local_options.processing.settle = local_projection;
  extract_and_process(*grid, level_of(options), local_options, local_projection, reporter, result,
                      centre);
  if (options.measure && field) {
    const auto measure_start = Clock::now();
    result.level_set_distance = measure_level_set_distance(
        result.surface, [&field](const Vec3& p, Vec3* g) { return field->value(p, g); },
        options.isovalue);
    result.stages.push_back({"level-set distance", seconds_since(measure_start), std::nullopt});
  }
  for (auto* mesh : {&result.raw, &result.surface})
    for (Vec3& p : mesh->points) p += centre;
  // Callers (the hierarchy) project meshes in input coordinates.
  if (local_projection)
    result.projection = [local_projection, centre](const Vec3& p) {
      return Vec3(local_projection(p - centre) + centre);
    };
  if (options.keep_volume) {
    result.volume = *grid;
    result.volume.origin += centre;
  }
  return result;
}

SurfacePipelineResult surface_from_grid(const Grid& grid, const SurfacePipelineOptions& options,
                                        const Reporter& reporter) {
  options.validate(SurfaceInput::kVolume);
  SurfacePipelineResult result;
  // A volume's surface is its trilinear level set; projecting onto it is asked for explicitly
  // (maps are noisy at the voxel scale, and an unset keep_on_surface means the Gaussian's
  // default, which is for atoms).
  std::function<Vec3(const Vec3&)> projection;
  if (volume_keeps_on_surface(options))
    projection = level_set_projection(std::make_shared<const Grid>(grid), options.isovalue);
  extract_and_process(grid, options.isovalue, options, projection, reporter, result);
  result.projection = std::move(projection);
  return result;
}

}  // namespace molmesh
