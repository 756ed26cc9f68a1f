#pragma once
// "Errors" of GAMer Table 1: how far the processed surface moved away from the surface
// marching cubes extracted. For every vertex of the processed mesh, the distance (Å) to the
// nearest point of the reference triangles (not just its vertices).
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct Dislocation {
  double max = 0;   // Å
  double mean = 0;  // Å, over all vertices referenced by a triangle
};

// Point-to-triangle distances through a BVH over `reference`; parallel, and the mean is
// summed in vertex order so the result does not depend on the thread count.
Dislocation measure_dislocation(const SurfaceMesh& mesh, const SurfaceMesh& reference);

// The per-vertex distances themselves (0 for unreferenced vertices).
std::vector<double> vertex_dislocations(const SurfaceMesh& mesh, const SurfaceMesh& reference);

}  // namespace molmesh
