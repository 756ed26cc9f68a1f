#include "solvers/physics/hierarchy_solve.hpp"

#include <algorithm>
#include <string>

#include "molmesh/core/error.hpp"
#include "solvers/physics/grid_interpolation.hpp"

namespace molmesh::solvers {

SolveLevels solve_levels(const Hierarchy& hierarchy, const HierarchySolveOptions& options,
                         Preconditioning preconditioning) {
  const int levels = static_cast<int>(hierarchy.levels.size());
  require_level(hierarchy, options.level);
  if (options.max_levels < 0) throw OptionError("`max_levels` must not be negative");
  SolveLevels out;
  out.mesh = &hierarchy.levels[static_cast<std::size_t>(options.level)].volume;
  int last = levels - 1;
  if (options.max_levels > 0) last = std::min(last, options.level + options.max_levels - 1);
  for (int l = options.level; l < last; ++l)
    out.prolongations.push_back(hierarchy.transfers.at(static_cast<std::size_t>(l)).volume);
  if (options.coarse_operators == CoarseOperators::kMesh &&
      preconditioning == Preconditioning::kMultigrid) {
    for (int l = options.level + 1; l <= last; ++l)
      out.coarse_meshes.push_back(&hierarchy.levels[static_cast<std::size_t>(l)].volume);
  }
  return out;
}

PotentialSamples sample_potential(const Grid& potential, double charge, const TetMesh& mesh) {
  InterpolatedField field = interpolate_trilinear(potential, mesh.points);
  for (double& v : field.values) v *= charge;
  return {std::move(field.values), field.outside};
}

HierarchySmoluchowskiResult solve_smoluchowski(const Hierarchy& hierarchy,
                                               const HierarchySolveOptions& options,
                                               const SmoluchowskiOptions& physics,
                                               const LigandPotential& ligand,
                                               const Reporter& reporter) {
  const Grid* potential = ligand.potential;
  const double charge = ligand.charge;
  const SolveLevels levels = solve_levels(hierarchy, options, physics.solver.preconditioning);
  HierarchySmoluchowskiResult out;
  if (potential != nullptr) {
    PotentialSamples fine = sample_potential(*potential, charge, *levels.mesh);
    out.beta_w = std::move(fine.beta_w);
    out.vertices_outside_potential_grid = fine.outside;
    if (fine.outside > 0) {
      reporter.warn(std::to_string(fine.outside) + " of " +
                    std::to_string(levels.mesh->points.size()) +
                    " mesh vertices lie outside the potential grid; they take the value at the "
                    "nearest grid point");
    }
  }
  // Every coarse mesh samples the potential the same way as the solve level.
  std::vector<std::vector<double>> coarse_beta_w;
  coarse_beta_w.reserve(levels.coarse_meshes.size());  // coarse_levels point into it
  std::vector<CoarseLevel> coarse_levels;
  for (const TetMesh* coarse : levels.coarse_meshes) {
    coarse_beta_w.push_back(potential != nullptr
                                ? sample_potential(*potential, charge, *coarse).beta_w
                                : std::vector<double>{});
    coarse_levels.push_back({coarse, coarse_beta_w.back()});
  }
  out.result = solve_smoluchowski(*levels.mesh, out.beta_w, levels.prolongations, physics, reporter,
                                  coarse_levels);
  return out;
}

PoissonResult solve_solvation_energy(const Hierarchy& hierarchy,
                                     const HierarchySolveOptions& options, const Atoms& atoms,
                                     const PoissonOptions& physics, const Reporter& reporter) {
  const SolveLevels levels = solve_levels(hierarchy, options, physics.solver.preconditioning);
  std::vector<CoarseLevel> coarse_levels;
  for (const TetMesh* coarse : levels.coarse_meshes) coarse_levels.push_back({coarse, {}});
  return solve_solvation_energy(*levels.mesh, atoms, levels.prolongations, physics, reporter,
                                coarse_levels);
}

}  // namespace molmesh::solvers
