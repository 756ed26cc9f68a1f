#pragma once
// Moving a mesh's vertices onto the surface it stands for (ProcessingOptions::project and
// ::settle), without turning any triangle over: a vertex whose projection would reverse the
// normal of one of its triangles (or make it degenerate) stays where it is.
#include <cstddef>
#include <functional>

#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// The projections run in parallel; the vertices are then moved in index order, each checked
// against its neighbours' current positions, so the result does not depend on the thread
// count. Returns the number of vertices left in place.
std::size_t project_vertices(SurfaceMesh& mesh, const std::function<Vec3(const Vec3&)>& project);

// The same, and a vertex also stays where it is when the move would take the angles of its
// triangles outside [floor_deg, 180° - 2·floor_deg] further than they already are: the smallest
// angle may not fall below min(its value before, floor_deg), the largest may not rise above
// max(its value before, 180° - 2·floor_deg). The smallest and largest are guarded apart, since
// one quality number that mixes them lets a move trade a slightly larger min for a max past the
// floors. For a surface whose projection pulls vertices onto creases (the distance-field
// surfaces, ProcessingOptions::settle): what can move onto the surface without spoiling the
// angles does.
std::size_t project_vertices_keeping_angles(SurfaceMesh& mesh,
                                            const std::function<Vec3(const Vec3&)>& project,
                                            double floor_deg);

}  // namespace molmesh
