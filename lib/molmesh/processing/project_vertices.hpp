#pragma once
// Moving a mesh's vertices onto the surface it stands for (ProcessingOptions::project), without
// turning any triangle over: a vertex whose projection would reverse the normal of one of its
// triangles (or make it degenerate) stays where it is.
#include <cstddef>
#include <functional>

#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// The projections run in parallel; the vertices are then moved in index order, each checked
// against its neighbours' current positions, so the result does not depend on the thread
// count. Returns the number of vertices left in place.
std::size_t project_vertices(SurfaceMesh& mesh, const std::function<Vec3(const Vec3&)>& project);

}  // namespace molmesh
