#pragma once
// A multigrid V-cycle over a mesh hierarchy, used as the preconditioner of CG.
//
// Coarse operators are Galerkin products P^T A P. Dirichlet vertices are eliminated on the
// finest level only: the rows of the first prolongation that belong to Dirichlet vertices
// are removed, and any coarse column left without a significant entry is dropped (its
// basis function lives only on the Dirichlet boundary). This keeps every level's operator
// symmetric positive definite and exactly consistent with the fine one; no coarse-level
// boundary markers are needed, so non-nested hierarchies whose coarse boundaries differ
// from the fine ones are handled the same way.
//
// Below the coarsest mesh level, smoothed-aggregation levels (aggregation.hpp) continue
// until at most max_direct_unknowns are left; a hierarchy of one level gives plain
// algebraic multigrid.
//
// Smoothing is symmetric block Gauss-Seidel (forward before restriction, backward after
// prolongation; gauss_seidel.hpp), the coarsest level is solved exactly with a sparse LDL^T, so the
// V-cycle is a symmetric positive definite operator, as CG requires.
#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "solvers/multigrid/aggregation.hpp"

namespace molmesh::solvers {

struct MultigridOptions {
  int smoothing_sweeps = 1;  // Gauss-Seidel sweeps before and after the coarse correction
  // Gauss-Seidel runs on this many row blocks in parallel (gauss_seidel.hpp). Results
  // depend on it, not on the thread count; 1 is the classic sequential smoother.
  int smoothing_blocks = 2;
  // A coarse column whose largest remaining weight is below this is dropped (see above).
  double drop_column_below = 1e-6;
  // A hierarchy level with more than this fraction of the current level's unknowns is
  // skipped (its prolongation is composed with the next one); the last level is used if
  // it has at most max_last_coarse_ratio of them.
  double max_coarse_ratio = 0.6;
  double max_last_coarse_ratio = 0.9;
  // The coarsest level is solved directly; larger ones get algebraic levels below them.
  Eigen::Index max_direct_unknowns = 1500;
  AggregationOptions aggregation;
  // Aggregation that keeps more than this fraction of the unknowns has stalled: stop.
  double max_aggregation_ratio = 0.8;
  // Relative diagonal shift applied to the coarsest operator only if it is singular.
  double coarse_shift = 1e-8;
};

// A coarse level's operator discretised on its own mesh (instead of P^T A P): `a` acts on
// the level's free vertices `free_to_full` (its own Dirichlet vertices eliminated).
// Galerkin products over a non-nested hierarchy widen the stencil level by level (54 and
// 276 nonzeros per row on mAChE levels 1 and 2, against 14 on level 0); re-discretised
// operators keep the mesh stencil. The V-cycle stays symmetric; it is no longer the exact
// Galerkin projection, so it converges somewhat slower per iteration.
//
// Eigen 3.4's SparseMatrix has no move constructor or move assignment (std::move copies
// it), so code that hands these matrices on swaps them: `out.a.swap(matrix)`.
struct MeshOperator {
  SparseMatrix a;
  std::vector<int> free_to_full;
};

class MultigridPreconditioner {
 public:
  // a: the fine operator on free unknowns; fine_free_to_full[i] = fine mesh vertex of
  // unknown i; prolongations[l] maps level l+1 vertices to level l vertices (all vertices,
  // as stored in Hierarchy::transfers[l].volume). An empty list gives algebraic multigrid.
  // mesh_operators[l], when given, replaces the Galerkin operator of level l+1 (swapped
  // out of the list: they are the coarse levels' operators from then on).
  // `a` is not copied: it must outlive the preconditioner (CG holds it anyway).
  MultigridPreconditioner(const SparseMatrix& a, std::span<const int> fine_free_to_full,
                          std::span<const SparseMatrix> prolongations,
                          const MultigridOptions& options = {},
                          std::vector<MeshOperator> mesh_operators = {});
  ~MultigridPreconditioner();
  MultigridPreconditioner(MultigridPreconditioner&&) noexcept;
  MultigridPreconditioner& operator=(MultigridPreconditioner&&) noexcept;

  // z = V-cycle applied to r with a zero initial guess. The cycle reuses vectors it keeps
  // between calls, so one preconditioner must not be applied from two threads at once.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // The same z, and az = A z from the last smoothing sweep (from the pass over A the sweep
  // makes anyway, instead of a product; pcg.hpp's preconditioned_cg_with_product uses it).
  void apply_with_product(const Eigen::VectorXd& r, Eigen::VectorXd& z, Eigen::VectorXd& az) const;

  std::vector<int> level_sizes() const;
  // Nonzeros of every level's operator (their sum over the first is the operator
  // complexity, the cost of a cycle relative to one fine-level sweep).
  std::vector<long> level_nonzeros() const;
  // How many of level_sizes() come from meshes; the rest are algebraic (aggregation).
  std::size_t mesh_levels() const;
  // True when the coarsest Galerkin operator was singular and got coarse_shift.
  bool coarsest_was_shifted() const;
  // The hierarchy this V-cycle runs on, for handing the same levels to another multigrid
  // implementation (PETSc's PCMG, solvers/petsc): level l's operator (l = 0: the fine `a`)
  // and its prolongation from level l+1 (l < level_sizes().size() - 1).
  const SparseMatrix& level_operator(std::size_t l) const;
  const SparseMatrix& level_prolongation(std::size_t l) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace molmesh::solvers
