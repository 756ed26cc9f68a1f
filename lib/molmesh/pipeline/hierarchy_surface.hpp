#pragma once
// A hierarchy built from the surface of the surface pipeline (`molmesh hierarchy`,
// molmesh.hierarchy with atoms): how the pipeline's options become the raw surface's and the
// levels' processing, written once for both front ends.
#include <functional>

#include "molmesh/core/geometry.hpp"
#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh {

// The options of the raw surface a hierarchy is built from: `pipeline` without processing
// (each level processes its own with its own T0) and without measurement.
SurfacePipelineOptions hierarchy_surface_options(const SurfacePipelineOptions& pipeline);

// Every level's processing as `pipeline` asks for it: coarsening keeps dense the spheres of
// all_keep_spheres(pipeline), then options.tetmesh.active_site (the active site stays dense
// on every level, paper Fig. 5); when keeps_on_surface(pipeline), vertices are moved back
// onto the surface by `projection` (SurfacePipelineResult::projection; empty for a surface
// given as it is). The T0 list and the other processing options stay as given. InputError
// when the keep-spheres file cannot be read.
void process_levels_as(HierarchyOptions& options, const SurfacePipelineOptions& pipeline,
                       const std::function<Vec3(const Vec3&)>& projection);

}  // namespace molmesh
