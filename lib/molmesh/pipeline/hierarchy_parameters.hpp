#pragma once
// The meshing parameters a hierarchy file records (Hierarchy::parameters, docs/formats.md),
// as text, from the options it was built with: one writer for `molmesh hierarchy` and
// molmesh.hierarchy, so a file says the same whichever front end wrote it.
#include <map>
#include <optional>
#include <string>

#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/pipeline/surface_source.hpp"

namespace molmesh {

// `options` and `report` as given to and returned by build_hierarchy(); `active_site_file`:
// the sphere list options.tetmesh.active_site was read from (empty: none, or given as
// spheres); `source`: the atoms and the options of the raw surface, nullopt for a hierarchy built
// from a given surface (then only the hierarchy's own parameters are recorded). Numbers are the
// shortest text that reads back to the same double (0.2, not 0.20000000000000001).
std::map<std::string, std::string> hierarchy_parameters(const HierarchyOptions& options,
                                                        const HierarchyReport& report,
                                                        const std::string& active_site_file,
                                                        const std::optional<SurfaceSource>& source);

}  // namespace molmesh
