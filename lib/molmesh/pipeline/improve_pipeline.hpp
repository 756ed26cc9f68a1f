#pragma once
// A user's surface mesh (MSMS, EDTSurf, any OFF/PLY/OBJ/STL) as `molmesh improve` treats it:
// repair (merge duplicates, drop degenerate faces, orient outward) -> the same quality
// improvement, coarsening and smoothing as the surface pipeline (GAMer §4.2, Fig. 10), with
// processing defaults tuned for such meshes. Shared by the CLI and the Python module.
#include <string_view>
#include <vector>

#include "molmesh/core/reporter.hpp"
#include "molmesh/processing/mesh_repair.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// External meshes (EDTSurf, MSMS) are far denser and more regular than marching-cubes
// output; holding feature vertices less firmly (2 instead of 4) lets the cleanup reach the
// paper's angle range on them: measured on EDTSurf's mAChE, min angle 28.5° instead of 21.0°
// at the same dislocation (docs/inputs.md).
ProcessingOptions user_mesh_processing();

struct ImprovePipelineOptions {
  MeshRepairOptions repair;
  ProcessingOptions processing = user_mesh_processing();  // processing.t0 empty: no coarsening
  bool repair_only = false;                               // stop after the repair

  // Throws molmesh::Error naming the member (core/error.hpp) for a value outside the range of
  // its entry in pipeline/improve_option_specs.hpp (the front ends' ranges), NaN or inf
  // included, then checks `processing` (ProcessingOptions::validate()). improve_surface()
  // calls it first.
  void validate() const;
};

struct ImprovePipelineResult {
  SurfaceMesh repaired;  // the input after repair (what processing started from)
  MeshRepairReport repair;
  double repair_seconds = 0.0;
  SurfaceMesh surface;  // final surface (== repaired with repair_only)
  std::vector<ProcessingStage> stages;
};

// `name` (a file name, or "mesh") prefixes error messages and the repair warning. Throws
// InputError for a mesh without triangles and molmesh::Error for invalid options or what
// repair cannot fix.
ImprovePipelineResult improve_surface(const SurfaceMesh& input, std::string_view name,
                                      const ImprovePipelineOptions& options,
                                      const Reporter& reporter = {});

}  // namespace molmesh
