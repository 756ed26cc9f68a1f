#pragma once
// Vertex normals as the paper defines them ("weighted average of the normals of all its
// incident triangles"). The weight is the triangle's interior angle at the vertex
// (Thürmer & Wüthrich): unlike area weights it does not let one large triangle dominate,
// and unlike uniform weights it is independent of how the star is split, which matters on
// marching-cubes output full of slivers.
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Unit outward normal of every triangle (zero for a degenerate triangle).
std::vector<Vec3> face_normals(const SurfaceMesh& mesh);

// Unit angle-weighted vertex normals (zero for an isolated vertex).
std::vector<Vec3> vertex_normals(const SurfaceMesh& mesh);

}  // namespace molmesh
