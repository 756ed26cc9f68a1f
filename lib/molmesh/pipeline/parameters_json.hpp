#pragma once
// The "parameters" object of `molmesh surface|tetmesh|improve --stats` and of the Python
// module's report["parameters"]: the options a run used, one writer each, so both front ends
// record the same keys and values (docs/cli.md). Hierarchies record theirs as text in the
// file instead (hierarchy_parameters.hpp).
#include <nlohmann/json.hpp>
#include <optional>

#include "molmesh/pipeline/improve_pipeline.hpp"
#include "molmesh/pipeline/surface_source.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {

// surface, probe_radius, keep_on_surface (resolved: true/false), spacing, blobbyness,
// isovalue, kernel_truncation, min_cavity_volume, blur, raw, coarsen, rings, alpha, beta,
// keep_spheres (the sphere file; "" for none or spheres given directly) and, when the atoms
// were read from a file, radii ("" for none), hetatm, waters.
nlohmann::json surface_parameters_json(const SurfaceSource& source);

// The surface's parameters (when `source` is given: the surface was made from atoms), then
// domain, sphere_ratio, outer_sphere_subdivisions, max_radius_edge_ratio, min_dihedral_deg,
// outer_radius and max_volume (when set), size_factor, active_site_spheres (a count).
nlohmann::json tetmesh_parameters_json(const TetMeshOptions& options,
                                       const std::optional<SurfaceSource>& source);

// t0, rings, sweeps, feature_weight, smooth_normal_iterations, flips, cleanup_rounds,
// merge_tolerance, repair_only.
nlohmann::json improve_parameters_json(const ImprovePipelineOptions& options);

}  // namespace molmesh
