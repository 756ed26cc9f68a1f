#pragma once
// Symmetric block Gauss-Seidel: the multigrid smoother.
//
// The rows are cut into a fixed number of contiguous blocks. Within a block the sweep is
// plain Gauss-Seidel (new values as soon as they exist); across blocks it is Jacobi (the
// values of other blocks are those from the start of the sweep). Blocks are then
// independent and run in parallel, and the result depends on the number of blocks, never
// on the number of threads. The meshes are renumbered by reverse Cuthill-McKee, so a block
// is a slab of the mesh and only rows at its faces see other blocks: with a few blocks the
// smoother is nearly as strong as the sequential one (docs/validation.md has the counts).
//
// The forward sweep uses M = D + L_B (L_B: the strictly lower part inside blocks), the
// backward sweep M^T = D + U_B, so forward-before and backward-after smoothing keep the
// V-cycle symmetric, as CG requires.
#include <Eigen/Core>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh::solvers {

struct GaussSeidelSmoother {
  const SparseMatrix* a = nullptr;   // the level's operator; outlives the smoother
  Eigen::VectorXd inverse_diagonal;  // 1 / a_ii
  std::vector<int> diagonal;         // position of a_ii in a's value array
  std::vector<Eigen::Index> block;   // block b holds rows block[b] .. block[b+1]-1
};

// Throws molmesh::Error if a row has no positive diagonal entry (a is then not SPD).
// Levels with fewer than min_rows_per_block rows per block get fewer blocks.
GaussSeidelSmoother make_gauss_seidel(const SparseMatrix& a, int blocks,
                                      Eigen::Index min_rows_per_block = 4096);

// Forward sweep from x = 0 (x is overwritten): reads only the lower triangle of each block.
void forward_sweep_from_zero(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                             Eigen::VectorXd& x);
void forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x);
void backward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x);

// b - A x right after a forward sweep took x from `before` (nullptr: zero) to `after`.
// Each row was exactly satisfied when it was updated, with old values for the entries the
// sweep had not updated yet, so its residual is sum of a_ij (before_j - after_j) over just
// those entries: right of the diagonal in its block, and every other block. That reads
// half the matrix instead of all of it.
void residual_after_forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd* before,
                                  const Eigen::VectorXd& after, Eigen::VectorXd& residual);

}  // namespace molmesh::solvers
