#pragma once
// JSON of what a solve reports: the keys of `molmesh solve --json` that come from the
// solve itself (the CLI adds its options and file names), and of SolveResult.report in
// the Python module. One writer for both (docs/solvers.md).
#include <nlohmann/json.hpp>

#include "solvers/multigrid/pcg.hpp"
#include "solvers/physics/hierarchy_solve.hpp"

namespace molmesh::solvers {

// converged, iterations, relative_residual, residual_history, setup_time_s, solve_time_s,
// time_s, preconditioner, levels_used, level_unknowns, level_nonzeros, mesh_levels_used.
nlohmann::json to_json(const SolveReport& report);

// The solver report, unknowns, absorbing/bulk/isolated-cavity vertex counts, vertices
// outside the potential grid and the rate constant in Å^3/s and M^-1 s^-1.
nlohmann::json to_json(const HierarchySmoluchowskiResult& result);

// The solvated solve's report with iterations, relative_residual and time_s of both solves,
// reference_solve, unknowns, charges, max_charge_offset_A, solvation_energy_kJ_per_mol.
nlohmann::json to_json(const PoissonResult& result);

}  // namespace molmesh::solvers
