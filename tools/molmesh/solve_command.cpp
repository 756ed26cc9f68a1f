// The `smoluchowski` and `poisson` subcommands of `molmesh solve` and of `molmesh-petsc`:
// options, output (stdout, JSON, fields stored back into the HDF5) and the call into
// solvers/physics/hierarchy_solve.hpp.
#include "solve_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "help_formatter.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/volume_io.hpp"
#include "solvers/physics/hierarchy_solve.hpp"
#include "solvers/physics/result_json.hpp"

namespace molmesh::cli {
namespace {

struct CommonArgs {
  std::string hierarchy;
  int level = 0;
  int max_levels = 0;  // 0: every level from `level` down to the coarsest
  std::string preconditioner = "multigrid";
  double tolerance = 1e-8;
  int max_iterations = 2000;
  int sweeps = solvers::MultigridOptions{}.smoothing_sweeps;
  int blocks = solvers::MultigridOptions{}.smoothing_blocks;
  std::string coarse_operators = "mesh";
  std::string json;
  bool no_fields = false;
};

struct SmoluchowskiArgs {
  CommonArgs common;
  double diffusion = 1e-5;
  std::string absorbing = "surface";
  std::string potential;
  double charge = solvers::LigandPotential{}.charge;
};

struct PoissonArgs {
  CommonArgs common;
  std::string pqr;
  double pdie = 1.0;
  double sdie = 78.54;
};

void add_common(CLI::App* cmd, CommonArgs& a) {
  cmd->add_option("hierarchy", a.hierarchy,
                  "Mesh hierarchy (HDF5 written by `molmesh hierarchy`); result fields are "
                  "stored back into it")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--level", a.level, "Level to solve on (0 = finest); coarser levels precondition")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--levels", a.max_levels,
                  "Use at most this many multigrid levels, counting the solve level (0 = all)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  one_of(cmd->add_option("--preconditioner", a.preconditioner,
                         "multigrid (V-cycle over the hierarchy, see --coarse-operators) or ic "
                         "(incomplete Cholesky, the baseline)"),
         {"multigrid", "ic"})
      ->capture_default_str();
  cmd->add_option("--tolerance", a.tolerance, "CG stops at this relative residual ||b-Ax||/||b||")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--max-iterations", a.max_iterations, "CG iteration limit")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--smoothing-sweeps", a.sweeps,
                  "Gauss-Seidel sweeps before and after each coarse correction")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  cmd->add_option("--smoothing-blocks", a.blocks,
                  "Gauss-Seidel runs on this many row blocks in parallel (Jacobi between blocks); "
                  "results depend on it, not on the thread count; 1 = sequential")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  one_of(cmd->add_option("--coarse-operators", a.coarse_operators,
                         "Multigrid coarse operators: mesh (discretised on each coarse mesh; "
                         "fast) or galerkin (P^T A P: the exact projection, but on a non-nested "
                         "hierarchy its stencil widens level by level and the setup becomes "
                         "slower than the solve)"),
         {"mesh", "galerkin"})
      ->capture_default_str();
  cmd->add_option("--json", a.json,
                  "Write the results (and solver report with residual history) as JSON");
  cmd->add_flag("--no-fields", a.no_fields,
                "Do not store the solution fields in the hierarchy file (it is left untouched)");
}

solvers::HierarchySolveOptions hierarchy_options(const CommonArgs& a) {
  return {.level = a.level,
          .max_levels = a.max_levels,
          .coarse_operators = a.coarse_operators == "galerkin" ? solvers::CoarseOperators::kGalerkin
                                                               : solvers::CoarseOperators::kMesh};
}

solvers::LinearSolverOptions solver_options(const CommonArgs& a) {
  solvers::LinearSolverOptions o;
  o.preconditioning = a.preconditioner == "ic" ? solvers::Preconditioning::kIncompleteCholesky
                                               : solvers::Preconditioning::kMultigrid;
  o.cg.tolerance = a.tolerance;
  o.cg.max_iterations = a.max_iterations;
  o.multigrid.smoothing_sweeps = a.sweeps;
  o.multigrid.smoothing_blocks = a.blocks;
  return o;
}

// What every result names: the problem, the engine, the level and its size.
void add_problem_json(nlohmann::json& j, const char* problem, const CommonArgs& a,
                      const SolveEngine& engine, const TetMesh& mesh, int unknowns) {
  j["problem"] = problem;
  j["engine"] = engine.name;
  j["hierarchy"] = a.hierarchy;
  j["level"] = a.level;
  j["vertices"] = mesh.points.size();
  j["tetrahedra"] = mesh.tetrahedra.size();
  j["unknowns"] = unknowns;
}

// Both fields of a solve go in with one rewrite of the hierarchy file, or neither does.
void store_fields(const CommonArgs& a, const std::vector<PointFieldView>& fields) {
  if (a.no_fields) return;
  write_point_fields(a.hierarchy, a.level, fields);
}

std::span<const double> values_of(const Eigen::VectorXd& v) {
  return {v.data(), static_cast<std::size_t>(v.size())};
}

void write_json(const std::string& path, const nlohmann::json& j) {
  if (!path.empty()) write_json_file(path, j);
}

void run_smoluchowski(const SmoluchowskiArgs& args, const CliContext& ctx,
                      const SolveEngine& engine) {
  const auto start = std::chrono::steady_clock::now();
  const Reporter reporter = ctx.reporter();
  const Hierarchy hierarchy = read_hierarchy(args.common.hierarchy);
  std::optional<Grid> grid;
  if (!args.potential.empty()) grid = read_volume(args.potential);
  solvers::SmoluchowskiOptions options;
  options.diffusion_cm2_per_s = args.diffusion;
  options.absorbing_markers =
      args.absorbing == "active-site"
          ? std::vector<int>{markers::kActiveSite}
          : std::vector<int>{markers::kMolecularSurface, markers::kActiveSite};
  options.solver = solver_options(args.common);
  options.solver.engine = engine.linear_engine;
  const auto solved = solvers::solve_smoluchowski(
      hierarchy, hierarchy_options(args.common), options,
      solvers::LigandPotential{grid ? &*grid : nullptr, args.charge}, reporter);
  const auto& result = solved.result;
  if (!engine.writes_output) return;
  const TetMesh& mesh = hierarchy.levels[static_cast<std::size_t>(args.common.level)].volume;
  std::vector<PointFieldView> fields{{"concentration", values_of(result.concentration)}};
  if (!solved.beta_w.empty()) fields.push_back({"beta_W", solved.beta_w});
  store_fields(args.common, fields);
  nlohmann::json j = solvers::to_json(solved);
  add_problem_json(j, "steady-state Smoluchowski", args.common, engine, mesh, result.unknowns);
  j["absorbing"] = args.absorbing;
  j["coarse_operators"] = args.common.coarse_operators;
  j["diffusion_cm2_per_s"] = args.diffusion;
  j["potential"] = args.potential.empty() ? nlohmann::json() : nlohmann::json(args.potential);
  j["charge"] = args.charge;
  j["total_time_s"] = seconds_since(start);
  write_json(args.common.json, j);
  std::printf("rate constant %.6e M^-1 s^-1 (%d CG iterations, relative residual %.2e, %.2f s)\n",
              result.rate_constant_per_molar_per_s, result.solve.iterations,
              result.solve.relative_residual,
              result.solve.setup_time_s + result.solve.solve_time_s);
  if (!result.solve.converged) throw Error("CG did not reach the tolerance (see --max-iterations)");
}

void run_poisson(const PoissonArgs& args, const CliContext& ctx, const SolveEngine& engine) {
  const auto start = std::chrono::steady_clock::now();
  const Reporter reporter = ctx.reporter();
  const Atoms atoms = read_atoms(args.pqr, {}, reporter);
  const Hierarchy hierarchy = read_hierarchy(args.common.hierarchy);
  solvers::PoissonOptions options;
  options.pdie = args.pdie;
  options.sdie = args.sdie;
  options.solver = solver_options(args.common);
  options.solver.engine = engine.linear_engine;
  const auto result = solvers::solve_solvation_energy(hierarchy, hierarchy_options(args.common),
                                                      atoms, options, reporter);
  if (!engine.writes_output) return;
  const TetMesh& mesh = hierarchy.levels[static_cast<std::size_t>(args.common.level)].volume;
  store_fields(args.common,
               {{"potential_kJ_per_mol_e", values_of(result.potential)},
                {"reaction_potential_kJ_per_mol_e", values_of(result.reaction_potential)}});
  nlohmann::json j = solvers::to_json(result);
  add_problem_json(j, "Poisson solvation energy (reference-solve method)", args.common, engine,
                   mesh, result.unknowns);
  j["pqr"] = args.pqr;
  j["pdie"] = args.pdie;
  j["sdie"] = args.sdie;
  j["coarse_operators"] = args.common.coarse_operators;
  j["total_time_s"] = seconds_since(start);
  write_json(args.common.json, j);
  if (result.max_charge_offset > 1e-3) {
    reporter.warn("some charges are not mesh vertices (up to " +
                  std::to_string(result.max_charge_offset) +
                  " Å away); their loads are spread over the containing tetrahedron");
  }
  std::printf("solvation energy %.4f kJ/mol (%d + %d CG iterations, %.2f s)\n",
              result.solvation_energy_kj_per_mol, result.solvated.iterations,
              result.reference.iterations, seconds_since(start));
  if (!result.solvated.converged || !result.reference.converged) {
    throw Error("CG did not reach the tolerance (see --max-iterations)");
  }
}

}  // namespace

void add_solve_subcommands(CLI::App* cmd, CliContext& ctx,
                           std::shared_ptr<const SolveEngine> engine) {
  auto smol = std::make_shared<SmoluchowskiArgs>();
  auto* s = cmd->add_subcommand(
      "smoluchowski",
      "Steady-state Smoluchowski diffusion in the solvent: c = c_bulk*exp(-z*phi) on the outer "
      "sphere, c = 0 on absorbing faces, reflective elsewhere; prints the rate constant "
      "(M^-1 s^-1) from the flux into the absorbing faces; stores field 'concentration' "
      "(units of c_bulk) and 'beta_W'");
  add_common(s, smol->common);
  s->add_option("--diffusion", smol->diffusion, "Relative diffusion coefficient D (cm^2/s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  one_of(s->add_option("--absorbing", smol->absorbing,
                       "Absorbing boundary: surface (the whole molecular surface) or active-site "
                       "(faces marked 3 by --active-site at meshing time; the rest reflects)"),
         {"surface", "active-site"})
      ->capture_default_str();
  s->add_option("--potential", smol->potential,
                "Electrostatic potential phi in kT/e (APBS OpenDX .dx, or .mrc), trilinearly "
                "interpolated to the vertices; vertices beyond the grid take the nearest grid "
                "value (a warning counts them)")
      ->check(CLI::ExistingFile);
  s->add_option("--charge", smol->charge,
                "Charge z of the diffusing ligand: beta W = z * phi (used with --potential)")
      ->capture_default_str();
  s->callback([smol, &ctx, engine] { run_smoluchowski(*smol, ctx, *engine); });

  auto pois = std::make_shared<PoissonArgs>();
  auto* p = cmd->add_subcommand(
      "poisson",
      "Electrostatic solvation energy (kJ/mol) from the linear Poisson equation without ions "
      "on "
      "a full mesh, by the reference-solve method (solvated minus uniform-pdie, same mesh); "
      "outer sphere: Coulomb potential in sdie; stores fields 'potential_kJ_per_mol_e' and "
      "'reaction_potential_kJ_per_mol_e'");
  add_common(p, pois->common);
  p->add_option("--pqr", pois->pqr, "Charges and positions (.pqr; any molecule format works)")
      ->required()
      ->check(CLI::ExistingFile);
  p->add_option("--pdie", pois->pdie, "Relative permittivity of the molecule (region 1)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  p->add_option("--sdie", pois->sdie, "Relative permittivity of the solvent (region 2)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  p->callback([pois, &ctx, engine] { run_poisson(*pois, ctx, *engine); });
}

}  // namespace molmesh::cli
