#pragma once
// The outer boundary of exterior and full meshes: a sphere triangulated as a subdivided
// icosahedron, whose triangles are near-equilateral and all about the same size, so TetGen
// needs no Steiner points on it and the far field stays coarse.
#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Level L has 10·4^L + 2 vertices and 20·4^L triangles, oriented outward. Throws
// molmesh::Error for radius <= 0 or a level outside [0, 7].
SurfaceMesh icosphere(const Vec3& center, double radius, int subdivisions);

}  // namespace molmesh
