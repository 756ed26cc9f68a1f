#pragma once
// Dirichlet conditions by elimination: the unknowns are the free vertices only, and the
// known values move to the right-hand side. The reduced matrix is the free-free block of
// the assembled one, so it stays symmetric positive definite and Galerkin coarse operators
// built from it stay consistent (docs/validation.md, "Dirichlet nodes and multigrid").
#include <Eigen/Core>
#include <span>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::solvers {

// Bit b set in boundary_vertex_marker_bits(mesh)[v] when v lies on a boundary face whose
// marker is b (markers 0..30).
std::vector<unsigned> boundary_vertex_marker_bits(const TetMesh& mesh);

// The bits of `markers` in the form boundary_vertex_marker_bits uses (markers outside
// 0..30 are ignored).
unsigned marker_mask(std::span<const int> markers);

struct ReducedSystem {
  std::vector<int> free_to_full;  // free index -> vertex
  std::vector<int> full_to_free;  // vertex -> free index, or -1 for a Dirichlet vertex
  SparseMatrix matrix;            // A_ff
  Eigen::VectorXd rhs;            // b_f - A_fd g_d
};

// The numbering of the free vertices (is_dirichlet[v] == 0), in vertex order: a
// ReducedSystem's free_to_full and full_to_free, its matrix and rhs left empty. Throws
// molmesh::Error when no vertex is free.
ReducedSystem number_free_vertices(std::span<const char> is_dirichlet);

// is_dirichlet[v] != 0 marks Dirichlet vertices; values[v] is used only there.
ReducedSystem reduce_dirichlet(const SparseMatrix& a, const Eigen::VectorXd& b,
                               std::span<const char> is_dirichlet, const Eigen::VectorXd& values);

// The full vector: solution at free vertices, prescribed values at Dirichlet ones.
Eigen::VectorXd expand_solution(const ReducedSystem& system, const Eigen::VectorXd& free_values,
                                std::span<const char> is_dirichlet, const Eigen::VectorXd& values);

}  // namespace molmesh::solvers
