#pragma once
// The keyword-argument tables of every stage, over the library's option structs
// (options.hpp). Names are the CLI's option names with '-' -> '_'.
#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/pipeline/improve_pipeline.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "options.hpp"

namespace molmesh::python {

// Surface kind, blurring and contouring (surface, probe_radius, keep_on_surface, spacing,
// blobbyness, isovalue, blur, min_cavity_volume, ...):
// the part of the surface options the hierarchy also takes.
const OptionTable<SurfacePipelineOptions>& volume_table();
// Quality improvement, smoothing and coarsening weights (not the T0 list).
const OptionTable<ProcessingOptions>& processing_table();
// molmesh.surface: volume_table + coarsen + processing_table + raw, keep_spheres, keep_volume.
const OptionTable<SurfacePipelineOptions>& surface_table();
// keep_spheres (a sphere file or an (n, 4) array), for surface() and hierarchy().
const OptionTable<SurfacePipelineOptions>& keep_spheres_table();
// molmesh.improve: t0, repair and processing options.
const OptionTable<ImprovePipelineOptions>& improve_table();
// molmesh.tetmesh: domain, outer sphere, TetGen bounds, active site.
const OptionTable<TetMeshOptions>& tetmesh_table();
// molmesh.hierarchy: t0 per level, size_growth, renumber + processing_table + tetmesh_table.
const OptionTable<HierarchyOptions>& hierarchy_table();

// options.validate(input) (the entry points call it too) with the keyword of surface() and
// tetmesh() for the coarsening thresholds: the library's `t0` is `coarsen` there, while
// improve() and hierarchy() call theirs t0.
void validate_surface_keywords(const SurfacePipelineOptions& options, SurfaceInput input);

// A str or os.PathLike (a file name), as opposed to an array.
bool is_path(const py::handle& v);

// (n, 4) float64 array of spheres (x, y, z, r) <-> std::vector<Sphere>.
std::vector<Sphere> to_spheres(const py::handle& value, const char* name);
py::object spheres_array(const std::vector<Sphere>& spheres);

}  // namespace molmesh::python
