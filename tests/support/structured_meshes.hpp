#pragma once
// Small synthetic meshes with known structure for tests of the hierarchy transfer
// operators and the HDF5 files (independent of the meshing pipeline), and a helper that
// joins surfaces into one mesh of several components.
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::testing {

// The box [lo, hi]^3 cut into n^3 cubes of 6 positively oriented tetrahedra each (Kuhn
// subdivision, conforming). cell_markers = 2 (solvent); boundary faces outward with marker
// 2, vertex markers 2 on the boundary and 0 inside.
TetMesh structured_cube(int n, double lo = 0.0, double hi = 1.0);

// The boundary of structured_cube(n, lo, hi) as a closed surface, triangles outward.
SurfaceMesh structured_cube_surface(int n, double lo = 0.0, double hi = 1.0);

// Appends `part` to `mesh` as a further component: its points after mesh's, its triangles
// renumbered to match. Markers are appended where both meshes have them on every vertex
// (face), and dropped otherwise, so the result is never half marked.
void append_surface(SurfaceMesh& mesh, const SurfaceMesh& part);

}  // namespace molmesh::testing
