#pragma once
// Locality renumbering of volume meshes: reverse Cuthill-McKee (Boost.Graph) on the
// vertex graph of the tetrahedra, so the P1 stiffness matrix has a small bandwidth and
// sparse products touch memory nearly sequentially.
#include <vector>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

// permutation[new] = old vertex index.
std::vector<int> reverse_cuthill_mckee(const TetMesh& mesh);

// The same mesh with vertex i of the result = vertex permutation[i] of `mesh` (points and
// vertex markers moved, cells and faces relabelled; cell order unchanged).
TetMesh permute_vertices(const TetMesh& mesh, const std::vector<int>& permutation);

// The same mesh with its cells (and their markers) sorted by their lowest vertex index,
// ties kept in order. After a locality renumbering of the vertices, this makes the cells
// around consecutive vertices neighbours in memory too: a row-wise P1 assembly reads the
// cells around each vertex, and in TetGen's cell order those reads were scattered over
// the whole mesh.
TetMesh sort_cells_by_vertex(const TetMesh& mesh);

// Largest |i - j| over edges of the tetrahedra (the stiffness matrix's half-bandwidth).
int vertex_bandwidth(const TetMesh& mesh);

}  // namespace molmesh
