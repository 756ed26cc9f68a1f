#pragma once
// Linear (P1) finite elements on tetrahedra: the stiffness matrix of -div(k grad u) with a
// coefficient that is constant on each tetrahedron. Everything the solvers need from a
// mesh is built from this one operator (boundary conditions are applied afterwards, by
// reduce_dirichlet, so the assembled matrix can still be used to compute boundary fluxes).
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::solvers {

// Gradients of the four barycentric basis functions of tetrahedron t, and its volume.
struct TetGeometry {
  std::array<Vec3, 4> gradients;
  double volume = 0.0;
};
TetGeometry tet_geometry(const TetMesh& mesh, std::size_t t);

// K[i][j] = sum_T k_T |T| grad(phi_i) . grad(phi_j). cell_coefficient has one value per
// tetrahedron. Throws molmesh::Error for inverted or degenerate tetrahedra (a P1 solve on
// them would be silently wrong).
//
// kept_index, if given, assembles only the block of the kept vertices, renumbered:
// kept_index[v] is v's row and column, or -1 to leave v out, kept vertices numbered
// 0, 1, 2, ... in vertex order (ReducedSystem::full_to_free has this form). That is the
// free-free block reduce_dirichlet would cut from the whole matrix, entry for entry, without
// building the whole matrix first (the coarse multigrid levels need only that block). Only
// the cells around kept vertices are checked then.
SparseMatrix assemble_stiffness(const TetMesh& mesh, std::span<const double> cell_coefficient,
                                std::span<const int> kept_index = {});

// Per-cell coefficient from a per-region table: value_of_region(cell_markers[t]).
// regions lists (marker, value) pairs; a marker not listed throws molmesh::Error.
std::vector<double> cell_coefficients_by_region(const TetMesh& mesh,
                                                std::span<const std::pair<int, double>> regions);

}  // namespace molmesh::solvers
