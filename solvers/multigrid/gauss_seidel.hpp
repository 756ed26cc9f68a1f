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
  // Rows with an entry in another block (the rows at the blocks' faces), increasing.
  std::vector<Eigen::Index> cross_block_rows;
};

// Throws molmesh::Error if a row has no positive diagonal entry (a is then not SPD).
// Levels with fewer than min_rows_per_block rows per block get fewer blocks.
GaussSeidelSmoother make_gauss_seidel(const SparseMatrix& a, int blocks,
                                      Eigen::Index min_rows_per_block = 4096);

// Forward sweep from x = 0 (x is overwritten): reads only the lower triangle of each block.
void forward_sweep_from_zero(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                             Eigen::VectorXd& x);
// One sweep from the given x. With several blocks the sweep keeps a copy of x from its
// start (the values other blocks read); `sweep_start`, when given, holds that copy, so a
// caller that sweeps often allocates it once.
void forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   Eigen::VectorXd* sweep_start = nullptr);
void backward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    Eigen::VectorXd* sweep_start = nullptr);

// The two sweeps of a V(1,1) cycle with the products around them folded in. Both rely on
// A being symmetric: the entries a row reads for its own update are, transposed, the
// entries other rows of its block still miss, so the row hands its contribution on
// (a scatter into rows of its own block, in a fixed order) instead of those rows reading
// the matrix again. Entries across blocks are added afterwards, for cross_block_rows only.
//
// forward_sweep_from_zero followed by residual_after_forward_sweep(s, nullptr, ...): x and
// b - A x from one pass over the lower triangle (instead of that pass and another over
// the upper one).
void forward_sweep_from_zero_with_residual(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                                           Eigen::VectorXd& x, Eigen::VectorXd& residual);
// backward_sweep, and A x for the x it leaves (CG's next product) from the same pass: when
// row i was updated it was exactly satisfied with the values of the rows after it in its
// block and the sweep-start values of everything else, so
// (A x)_i = b_i + sum of a_ij (x_j - start_j) over the rows before it in its block (each
// hands a_ji delta_j on when it is updated) and over other blocks. `sweep_start` is
// scratch, as in backward_sweep.
void backward_sweep_with_product(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x, Eigen::VectorXd& sweep_start,
                                 Eigen::VectorXd& ax);

// b - A x right after a forward sweep took x from `before` (nullptr: zero) to `after`.
// Each row was exactly satisfied when it was updated, with old values for the entries the
// sweep had not updated yet, so its residual is sum of a_ij (before_j - after_j) over just
// those entries: right of the diagonal in its block, and every other block. That reads
// half the matrix instead of all of it.
void residual_after_forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd* before,
                                  const Eigen::VectorXd& after, Eigen::VectorXd& residual);

}  // namespace molmesh::solvers
