#include "solvers/physics/result_json.hpp"

#include <algorithm>

namespace molmesh::solvers {

nlohmann::json to_json(const SolveReport& r) {
  return {{"converged", r.converged},
          {"iterations", r.iterations},
          {"relative_residual", r.relative_residual},
          {"residual_history", r.residual_history},
          {"setup_time_s", r.setup_time_s},
          {"solve_time_s", r.solve_time_s},
          {"time_s", r.setup_time_s + r.solve_time_s},
          {"preconditioner", r.preconditioner},
          {"levels_used", r.level_sizes.empty() ? 1 : r.level_sizes.size()},
          {"level_unknowns", r.level_sizes},
          {"level_nonzeros", r.level_nonzeros},
          {"mesh_levels_used", r.mesh_levels}};
}

nlohmann::json to_json(const HierarchySmoluchowskiResult& solved) {
  const SmoluchowskiResult& result = solved.result;
  nlohmann::json j = to_json(result.solve);
  j["unknowns"] = result.unknowns;
  j["absorbing_vertices"] = result.absorbing_vertices;
  j["bulk_vertices"] = result.bulk_vertices;
  j["isolated_cavity_vertices"] = result.isolated_vertices;
  j["vertices_outside_potential_grid"] = solved.vertices_outside_potential_grid;
  j["rate_constant_A3_per_s"] = result.rate_constant_A3_per_s;
  j["rate_constant_M-1s-1"] = result.rate_constant_per_molar_per_s;
  return j;
}

nlohmann::json to_json(const PoissonResult& result) {
  nlohmann::json j = to_json(result.solvated);
  j["unknowns"] = result.unknowns;
  j["charges"] = result.charges;
  j["max_charge_offset_A"] = result.max_charge_offset;
  j["reference_solve"] = to_json(result.reference);
  j["iterations"] = result.solvated.iterations + result.reference.iterations;
  j["converged"] = result.solvated.converged && result.reference.converged;
  j["relative_residual"] =
      std::max(result.solvated.relative_residual, result.reference.relative_residual);
  j["time_s"] = result.solvated.setup_time_s + result.solvated.solve_time_s +
                result.reference.setup_time_s + result.reference.solve_time_s;
  j["solvation_energy_kJ_per_mol"] = result.solvation_energy_kj_per_mol;
  return j;
}

}  // namespace molmesh::solvers
