#pragma once
// Where a volume mesh's or hierarchy's molecular surface came from, when it was made from
// atoms: how they were read and the options of the surface pipeline. What the parameter
// writers (parameters_json.hpp, hierarchy_parameters.hpp) record about the surface.
#include <optional>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh {

struct SurfaceSource {
  std::optional<AtomReadOptions> atoms;  // nullopt: not read from a file (e.g. arrays, a volume)
  SurfacePipelineOptions surface;
  bool volume_input = false;  // contoured from a volume (surface_from_grid), not from atoms
};

}  // namespace molmesh
