#pragma once
// Stage 2.1 as the CLI runs it: atoms (or a volume) -> Gaussian blur -> marching cubes ->
// optional removal of small cavities -> surface processing (unless raw). Each stage is timed
// and, for surfaces, measured.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/processing/dislocation.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/fast_blur.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

struct SurfacePipelineOptions {
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
  std::array<int, 3> grid_dims{0, 0, 0};  // the blurred volume's size (0 for volume input)
  Grid volume;  // the blurred volume, only with options.keep_volume (atoms input)
};

SurfacePipelineResult surface_from_atoms(const Atoms& atoms, const SurfacePipelineOptions& options,
                                         const Reporter& reporter = {});
SurfacePipelineResult surface_from_grid(const Grid& grid, const SurfacePipelineOptions& options,
                                        const Reporter& reporter = {});

}  // namespace molmesh
