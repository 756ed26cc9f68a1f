#pragma once
// Smoothed aggregation (Vaněk, Mandel & Brezina 1996): algebraic coarse levels for the part
// of the multigrid cycle below the mesh hierarchy. A GAMer hierarchy's coarsest mesh is
// still a full volume mesh (thousands of unknowns) and an exterior hierarchy may shrink
// slowly, so a sparse direct solve there would cost more than the whole cycle above it;
// aggregation continues the coarsening on the matrix alone until a direct solve is cheap.
#include <Eigen/Core>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh::solvers {

struct AggregationOptions {
  // j is a strong neighbour of i when |a_ij| >= theta * sqrt(a_ii a_jj). 0.08 is the
  // usual choice for 3D problems; it keeps weak couplings across coefficient jumps (the
  // 1 : 78.54 dielectric interface, e^{-βW} in the Slotboom operator) out of aggregates.
  double strength_threshold = 0.08;
  // Prolongation smoothing P = (I - ω D^-1 A) T with ω = relaxation / ρ(D^-1 A).
  double relaxation = 4.0 / 3.0;
};

// The smoothed prolongation (rows: unknowns of `a`, columns: aggregates) of one level.
// Invariant: every row of the tentative prolongator has exactly one 1, so the coarse space
// contains the constants of every aggregate; a symmetric positive definite `a` gives a
// symmetric positive definite P^T A P. Returns a matrix with no columns when `a` has no
// off-diagonal couplings left.
SparseMatrix smoothed_aggregation_prolongation(const SparseMatrix& a,
                                               const AggregationOptions& options = {});

}  // namespace molmesh::solvers
