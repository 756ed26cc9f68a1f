#pragma once
// Electrostatic solvation energy from the linear Poisson equation with a piecewise-constant
// permittivity (pdie in the molecule region, sdie in the solvent) and point charges.
//
// The point-charge singularity is handled by the reference-solve method: the same mesh,
// the same P1 point loads, solved once with (pdie, sdie) and once with pdie everywhere;
//   dG = 1/2 sum_i q_i [phi_solvated(x_i) - phi_reference(x_i)].
// The singular part of both fields is the same Coulomb potential in pdie near each
// charge, so its discretisation error cancels in the difference (exact cancellation as
// the mesh is refined; atom centres should be mesh vertices, as in full meshes).
// Outer sphere: Dirichlet with the Coulomb potential of the charges in the outer
// dielectric (no ions), which is exact for a Born ion.
#include <Eigen/Core>
#include <span>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "solvers/multigrid/linear_solver.hpp"
#include "solvers/physics/coarse_level.hpp"

namespace molmesh::solvers {

struct PoissonOptions {
  double pdie = 1.0;    // molecule (region kMoleculeRegion)
  double sdie = 78.54;  // solvent (region kSolventRegion)
  std::vector<int> dirichlet_markers{markers::kOuterSphere};
  LinearSolverOptions solver;
};

struct PoissonResult {
  double solvation_energy_kj_per_mol = 0.0;
  // Per vertex, kJ/(mol e): the full potential with the solvent, and the reaction field
  // (solvated minus reference).
  Eigen::VectorXd potential;
  Eigen::VectorXd reaction_potential;
  int charges = 0;                 // atoms with a nonzero charge
  double max_charge_offset = 0.0;  // Å from each charge to its nearest mesh vertex (max)
  int unknowns = 0;
  SolveReport solvated;
  SolveReport reference;
};

// mesh: a full mesh (molecule and solvent regions) containing every charged atom.
// prolongations: Hierarchy::transfers[l].volume for the levels below `mesh` (may be empty).
// coarse_levels: one per prolongation to use coarse operators discretised on those meshes
// (same regions and outer-sphere markers) instead of Galerkin products (empty: Galerkin).
// Only their meshes are used: the charges load the finest level alone.
// Throws molmesh::Error when a charge lies outside the mesh or the mesh has no Dirichlet
// (outer sphere) vertex.
PoissonResult solve_solvation_energy(const TetMesh& mesh, const Atoms& atoms,
                                     std::span<const SparseMatrix> prolongations,
                                     const PoissonOptions& options, const Reporter& reporter = {},
                                     std::span<const CoarseLevel> coarse_levels = {});

}  // namespace molmesh::solvers
