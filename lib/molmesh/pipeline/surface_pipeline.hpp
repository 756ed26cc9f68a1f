#pragma once
// Stage 2.1 as the CLI runs it: atoms (or a volume) -> Gaussian blur or distance field
// (docs/surface.md) -> marching cubes ->
// optional removal of small cavities -> surface processing (unless raw). Each stage is timed
// and, for surfaces, measured.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/processing/dislocation.hpp"
#include "molmesh/processing/level_set_distance.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/fast_blur.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "molmesh/volume/grid.hpp"
#include "molmesh/volume/surface_kind.hpp"

namespace molmesh {

// What a surface is contoured from: atoms (surface_from_atoms) or a scalar volume
// (surface_from_grid), whose level may be any finite number (a potential map's can be
// negative).
enum class SurfaceInput { kAtoms, kVolume };

struct SurfacePipelineOptions {
  // Which surface of the atoms: the solvent-excluded surface (the default: the dielectric and
  // reactive boundary PB and Smoluchowski users expect), the vdW or solvent-accessible one
  // (distance fields sampled every blur.spacing and contoured at 0), or the paper's Gaussian
  // (blur, isovalue below). The Gaussian-only options (blur.blobbyness, blur.truncation,
  // isovalue, blur_method) must keep their defaults for the others: validate() refuses them,
  // rather than ignore what a user asked for. docs/surface.md "Which surface".
  SurfaceKind surface = SurfaceKind::kSes;
  double probe_radius = 1.4;  // Å, solvent probe of the sas and ses surfaces (water)
  // Project vertices back onto the surface after every processing move
  // (ProcessingOptions::project): onto the distance field's trilinear level set for vdw/sas/ses,
  // onto F = isovalue of Eq. 1 evaluated exactly (volume/gaussian_field.hpp) for the Gaussian
  // of atoms. Unset: on for the Gaussian (it puts vertices on Eq. 1 to ~1e-4 Å and improves
  // the angles), off for the distance fields (pulled back onto creases and cusps they lose
  // angle quality); docs/surface.md, docs/processing.md "Distance to the level set". Volume
  // inputs (surface_from_grid) project onto their trilinear level set only when it is true.
  // keeps_on_surface() below resolves it.
  std::optional<bool> keep_on_surface;
  BlurOptions blur;  // blur.isovalue is overwritten with `isovalue` below
  // Eq. 1 summed exactly, or Eq. 2 by splatting + recursive filtering (volume/fast_blur.hpp,
  // measurements in docs/inputs.md).
  BlurMethod blur_method = BlurMethod::kExact;
  double isovalue = 1.0;
  double min_cavity_volume = 0.0;  // Å³; cavities enclosing less are dropped; 0 keeps all
  bool raw = false;                // stop after marching cubes (and cavity removal)
  bool keep_volume = false;        // return the blurred volume in SurfacePipelineResult::volume
  // Per-stage SurfaceStats and the dislocation (what `--stats` reports). Off skips both,
  // which saves ~10 % of the pipeline: the surface itself is the same either way.
  bool measure = true;
  // Quality improvement, coarsening (one round per T0), smoothing: processing/process_surface.hpp.
  ProcessingOptions processing;
  // Sphere list (docs/formats.md) added to processing.keep_spheres; empty for none.
  std::string keep_spheres_file;

  // Throws molmesh::Error naming the member (core/error.hpp) for a value outside the range of
  // its entry in pipeline/surface_option_specs.hpp (the front ends' ranges), NaN or inf
  // included, then checks `processing` (ProcessingOptions::validate()). The isovalue's range is
  // for atoms; a volume's isovalue need only be finite. surface_from_atoms() and
  // surface_from_grid() call it first.
  void validate(SurfaceInput input) const;
};

struct StageRecord {
  std::string name;  // "blur", "marching cubes", "cavities", ...
  double seconds = 0.0;
  std::optional<SurfaceStats> stats;  // of the surface this stage produced (if measured)
};

struct SurfacePipelineResult {
  SurfaceMesh raw;      // marching cubes output (after cavity removal)
  SurfaceMesh surface;  // final surface (== raw when options.raw)
  std::vector<StageRecord> stages;
  // Distance of the final surface's vertices to the raw one (zero when raw or not measured).
  Dislocation dislocation;
  // Distance of the final surface to the level set of Eq. 1 evaluated exactly from the atoms
  // (volume/gaussian_field.hpp; for the fast blur, the Eq. 1 that Eq. 2 stands for). Only
  // for the Gaussian surface of atoms, and only when measured.
  std::optional<LevelSetDistance> level_set_distance;
  std::array<int, 3> grid_dims{0, 0, 0};  // the blurred volume's size (0 for volume input)
  Grid volume;         // the blurred volume, only with options.keep_volume (atoms input)
  double level = 1.0;  // the level marching cubes contoured (isovalue, or 0 for distances)
  // Moves a point onto the surface (processing uses it when options.keep_on_surface;
  // `hierarchy` passes it on to every level's processing). Set for the distance-field
  // surfaces always, for the Gaussian of atoms with options.keep_on_surface.
  std::function<Vec3(const Vec3&)> projection;
};

// The volume whose level `level_of(options)` is the chosen surface: Eq. 1 (or Eq. 2) for
// kGaussian, a distance field (volume/ball_union.hpp, volume/ses_field.hpp) otherwise.
Grid surface_volume(const Atoms& atoms, const SurfacePipelineOptions& options,
                    const Reporter& reporter = {});
// options.keep_on_surface, or the kind's default when it is unset.
bool keeps_on_surface(const SurfacePipelineOptions& options);
// Throws OptionError naming the option when a Gaussian-only option (blur.blobbyness, isovalue,
// blur.truncation, blur_method) differs from its default while `surface` is not kGaussian.
// validate(SurfaceInput::kAtoms) calls it, after the ranges.
void require_gaussian_options_apply(const SurfacePipelineOptions& options);
// Whether processing settles the vertices onto the surface once at the end instead
// (ProcessingOptions::settle): for the distance-field surfaces of atoms when keep_on_surface is
// unset, so the mesh is not left inside the surface by smoothing.
bool settles_on_surface(const SurfacePipelineOptions& options);
// The same for a volume input (surface_from_grid): only when options.keep_on_surface is true.
bool volume_keeps_on_surface(const SurfacePipelineOptions& options);

double level_of(const SurfacePipelineOptions& options);

// The spheres coarsening must keep dense: options.processing.keep_spheres, then those of
// options.keep_spheres_file (read here; InputError when it cannot be). For the stages that
// process the surface themselves (the hierarchy's levels).
std::vector<Sphere> all_keep_spheres(const SurfacePipelineOptions& options);

SurfacePipelineResult surface_from_atoms(const Atoms& atoms, const SurfacePipelineOptions& options,
                                         const Reporter& reporter = {});
SurfacePipelineResult surface_from_grid(const Grid& grid, const SurfacePipelineOptions& options,
                                        const Reporter& reporter = {});

}  // namespace molmesh
