#pragma once
// Solving on a level of a mesh Hierarchy: the one place that picks the levels a solve uses
// (the solve level, at most `max_levels` of them, the prolongations between them), builds
// the coarse levels multigrid discretises on their own meshes, and samples a potential
// grid on every level the same way. The CLI (`molmesh solve`), the PETSc program and the
// Python module all call these, so they keep only their options and output.
#include <optional>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/volume/grid.hpp"
#include "solvers/physics/coarse_level.hpp"
#include "solvers/physics/poisson.hpp"
#include "solvers/physics/smoluchowski.hpp"

namespace molmesh::solvers {

enum class CoarseOperators {
  kMesh,      // discretised on each coarse mesh (fast; the default)
  kGalerkin,  // P^T A P: exact projection, but its stencil widens on non-nested levels
};

struct HierarchySolveOptions {
  int level = 0;       // level to solve on (0 = finest); the coarser ones precondition
  int max_levels = 0;  // at most this many multigrid levels counting `level` (0 = all)
  CoarseOperators coarse_operators = CoarseOperators::kMesh;
};

// The levels of a hierarchy one solve uses. Points into the hierarchy (keep it alive).
struct SolveLevels {
  const TetMesh* mesh = nullptr;            // the solve level
  std::vector<SparseMatrix> prolongations;  // level+1 -> level, level+2 -> level+1, ...
  // One per prolongation when multigrid uses mesh coarse operators, else empty.
  std::vector<const TetMesh*> coarse_meshes;
};

// Throws molmesh::Error when `options.level` is not a level of `hierarchy`.
SolveLevels solve_levels(const Hierarchy& hierarchy, const HierarchySolveOptions& options,
                         Preconditioning preconditioning);

// beta*W = charge * phi, phi (kT/e, as APBS writes it) trilinearly interpolated to the
// mesh vertices; vertices beyond the grid take the nearest grid value and are counted.
struct PotentialSamples {
  std::vector<double> beta_w;
  int outside = 0;
};
PotentialSamples sample_potential(const Grid& potential, double charge, const TetMesh& mesh);

// The electrostatic steering of a Smoluchowski solve: beta W = charge * phi. The one home of
// the ligand charge default (`molmesh solve smoluchowski --charge`, Python charge=).
struct LigandPotential {
  const Grid* potential = nullptr;  // phi in kT/e, as APBS writes it; nullptr: no steering
  double charge = 1.0;              // z of the diffusing ligand
};

struct HierarchySmoluchowskiResult {
  SmoluchowskiResult result;
  std::vector<double> beta_w;  // on the solve level; empty without a potential
  int vertices_outside_potential_grid = 0;
};

// Steady-state Smoluchowski on `options.level`, steered by `ligand.potential` when given.
// Warns through `reporter` when vertices lie outside the potential grid.
HierarchySmoluchowskiResult solve_smoluchowski(const Hierarchy& hierarchy,
                                               const HierarchySolveOptions& options,
                                               const SmoluchowskiOptions& physics,
                                               const LigandPotential& ligand = {},
                                               const Reporter& reporter = {});

// Poisson solvation energy on `options.level` (a full mesh).
PoissonResult solve_solvation_energy(const Hierarchy& hierarchy,
                                     const HierarchySolveOptions& options, const Atoms& atoms,
                                     const PoissonOptions& physics, const Reporter& reporter = {});

}  // namespace molmesh::solvers
