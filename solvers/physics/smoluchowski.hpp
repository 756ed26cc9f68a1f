#pragma once
// Steady-state Smoluchowski diffusion around a molecule (GAMer §4.4, as in SMOL):
//   div D (grad c + c grad(beta W)) = 0  in the solvent,
//   c = c_bulk exp(-beta W) on the outer sphere (the bulk in Boltzmann equilibrium, which
//   is c_bulk where the potential has decayed), c = 0 on absorbing faces, zero flux
//   elsewhere.
// With the Slotboom variable s = c exp(beta W) the operator is symmetric:
//   div (D exp(-beta W) grad s) = 0,
// solved with P1 elements and multigrid-preconditioned CG. The rate constant is the
// particle flux into the absorbing faces, read from the residual of the assembled
// (un-reduced) system at the absorbing vertices, which is the consistent discrete flux
// (no differencing of the solution).
#include <Eigen/Core>
#include <span>
#include <vector>

#include "molmesh/core/reporter.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "solvers/multigrid/linear_solver.hpp"
#include "solvers/physics/coarse_level.hpp"

namespace molmesh::solvers {

struct SmoluchowskiOptions {
  double diffusion_cm2_per_s = 1e-5;  // relative diffusion coefficient D
  // Boundary-face markers that absorb (c = 0) and that carry the bulk concentration.
  std::vector<int> absorbing_markers{markers::kMolecularSurface, markers::kActiveSite};
  std::vector<int> bulk_markers{markers::kOuterSphere};
  // Only cells with this region marker hold solvent (cells of other regions are ignored,
  // so a full mesh works as well as an exterior one). Meshes without cell markers are all
  // solvent.
  int solvent_region = markers::kSolventRegion;
  LinearSolverOptions solver;
};

struct SmoluchowskiResult {
  // Per mesh vertex, in units of the bulk concentration (c_bulk = 1). Vertices outside
  // the solvent get 0.
  Eigen::VectorXd concentration;
  Eigen::VectorXd slotboom;  // c exp(beta W)
  double rate_constant_A3_per_s = 0.0;
  double rate_constant_per_molar_per_s = 0.0;  // M^-1 s^-1
  int absorbing_vertices = 0;
  int bulk_vertices = 0;
  int unknowns = 0;
  int isolated_vertices = 0;  // in closed solvent cavities: left out, c = 0
  SolveReport solve;
};

// beta_w: beta*W per mesh vertex (dimensionless, kT units), or empty for pure diffusion.
// prolongations: Hierarchy::transfers[l].volume for the levels below `mesh` (may be empty).
// coarse_levels: one per prolongation to use re-discretised coarse operators instead of
// Galerkin products (empty: Galerkin).
// Throws molmesh::Error when there is no absorbing or no bulk vertex.
SmoluchowskiResult solve_smoluchowski(const TetMesh& mesh, std::span<const double> beta_w,
                                      std::span<const SparseMatrix> prolongations,
                                      const SmoluchowskiOptions& options,
                                      const Reporter& reporter = {},
                                      std::span<const CoarseLevel> coarse_levels = {});

}  // namespace molmesh::solvers
