#include "molmesh/pipeline/hierarchy_surface.hpp"

namespace molmesh {

SurfacePipelineOptions hierarchy_surface_options(const SurfacePipelineOptions& pipeline) {
  SurfacePipelineOptions options = pipeline;
  options.raw = true;
  options.measure = false;
  return options;
}

void process_levels_as(HierarchyOptions& options, const SurfacePipelineOptions& pipeline,
                       const std::function<Vec3(const Vec3&)>& projection) {
  if (keeps_on_surface(pipeline))
    options.processing.project = projection;
  else if (settles_on_surface(pipeline))
    options.processing.settle = projection;
  options.processing.keep_spheres = all_keep_spheres(pipeline);
  options.processing.keep_spheres.insert(options.processing.keep_spheres.end(),
                                         options.tetmesh.active_site.begin(),
                                         options.tetmesh.active_site.end());
}

}  // namespace molmesh
