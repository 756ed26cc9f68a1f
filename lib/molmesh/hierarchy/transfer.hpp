#pragma once
// Inter-level transfer operators of the multilevel hierarchy (GAMer §4.3).
//
// Prolongation P maps coarse-level nodal values to the fine level: u_fine = P u_coarse,
// P is (fine vertices x coarse vertices). Restriction is its transpose, R = P^T (the
// Galerkin choice: A_coarse = P^T A_fine P); we store only P.
//
// Volume: P1 interpolation. Each fine vertex is located in a coarse tetrahedron (AABB
// tree) and gets that tetrahedron's barycentric coordinates. A fine vertex outside the
// coarse mesh (the levels' molecular surfaces differ) takes the barycentric coordinates of
// the closest point of the coarse boundary. Surface: barycentric coordinates of the closest
// point of the nearest coarse triangle, except that a fine vertex a coarse vertex was
// derived from (provenance) maps to it by identity.
//
// Guarantees (tested): every row sums to 1; linear functions are reproduced exactly at fine
// vertices inside the coarse volume mesh; every coarse vertex has a non-empty column. A
// coarse volume vertex that no fine vertex interpolates from (possible where the fine mesh
// is locally coarser) is given to its nearest fine vertices by adding t·(e_c − λ_T(x_c)) to
// that fine vertex's row, where λ_T(x_c) are the barycentric coordinates of x_c with
// respect to the tetrahedron the row came from: the added term has zero sum and zero first
// moment, so row sums and linear reproduction are untouched.
#include <span>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh {

struct TransferStats {
  int fine_outside = 0;            // fine vertices projected onto the coarse boundary
  int empty_columns_repaired = 0;  // coarse vertices given a column by the repair above
};

SparseMatrix volume_prolongation(const TetMesh& coarse, const TetMesh& fine,
                                 TransferStats* stats = nullptr);

// `provenance[c]` = fine vertex coarse vertex c was derived from (may be empty).
SparseMatrix surface_prolongation(const SurfaceMesh& coarse, const SurfaceMesh& fine,
                                  std::span<const int> provenance, TransferStats* stats = nullptr);

// Faces of `mesh` that belong to exactly one tetrahedron.
std::vector<Triangle> tet_mesh_boundary(const TetMesh& mesh);

}  // namespace molmesh
