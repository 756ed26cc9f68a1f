// molmesh.solve_smoluchowski and molmesh.solve_poisson: the built-in P1 solvers on a level
// of a Hierarchy, CG preconditioned by multigrid over the coarser levels, as `molmesh solve`.
#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bindings.hpp"
#include "casters.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/volume_io.hpp"
#include "progress.hpp"
#include "solvers/physics/hierarchy_solve.hpp"
#include "solvers/physics/poisson.hpp"
#include "solvers/physics/result_json.hpp"
#include "solvers/physics/smoluchowski.hpp"
#include "tables.hpp"
#include "types.hpp"

namespace molmesh::python {
namespace {

using solvers::LinearSolverOptions;

struct SolveSetup {
  solvers::HierarchySolveOptions levels;  // level, max_levels, coarse operators
  LinearSolverOptions solver;
};

// Keyword tables. Solver defaults come from LinearSolverOptions (and its SolveOptions,
// MultigridOptions), the physics defaults from SmoluchowskiOptions / PoissonOptions.
const OptionTable<SolveSetup>& setup_table() {
  static const auto table = [] {
    OptionTable<SolveSetup> t;
    t.field("level", MOLMESH_FIELD(levels.level), "level to solve on (0 = finest)");
    t.field("levels", MOLMESH_FIELD(levels.max_levels),
            "use at most this many multigrid levels, counting the solve level (0 = all)");
    t.choice("preconditioner", MOLMESH_FIELD(solver.preconditioning),
             std::vector<std::pair<std::string, solvers::Preconditioning>>{
                 {"multigrid", solvers::Preconditioning::kMultigrid},
                 {"ic", solvers::Preconditioning::kIncompleteCholesky}},
             "multigrid V-cycle over the hierarchy, or incomplete Cholesky");
    t.field("tolerance", MOLMESH_FIELD(solver.cg.tolerance),
            "CG stops at this relative residual ||b-Ax||/||b||");
    t.field("max_iterations", MOLMESH_FIELD(solver.cg.max_iterations), "CG iteration limit");
    t.field("smoothing_sweeps", MOLMESH_FIELD(solver.multigrid.smoothing_sweeps),
            "Gauss-Seidel sweeps before and after each coarse correction");
    t.field("smoothing_blocks", MOLMESH_FIELD(solver.multigrid.smoothing_blocks),
            "Gauss-Seidel row blocks run in parallel (results depend on it, not on threads)");
    t.choice("coarse_operators", MOLMESH_FIELD(levels.coarse_operators),
             std::vector<std::pair<std::string, solvers::CoarseOperators>>{
                 {"mesh", solvers::CoarseOperators::kMesh},
                 {"galerkin", solvers::CoarseOperators::kGalerkin}},
             "coarse operators discretised on each coarse mesh, or Galerkin P^T A P");
    return t;
  }();
  return table;
}

const OptionTable<solvers::SmoluchowskiOptions>& smoluchowski_table() {
  static const auto table = [] {
    OptionTable<solvers::SmoluchowskiOptions> t;
    t.field("diffusion", MOLMESH_FIELD(diffusion_cm2_per_s),
            "relative diffusion coefficient D, cm^2/s");
    t.choice("absorbing", MOLMESH_FIELD(absorbing_markers),
             std::vector<std::pair<std::string, std::vector<int>>>{
                 {"surface", {markers::kMolecularSurface, markers::kActiveSite}},
                 {"active-site", {markers::kActiveSite}}},
             "absorbing boundary: the whole molecular surface, or the active site (marker 3)");
    return t;
  }();
  return table;
}

// charge= (potential= is taken apart: the call keeps its grid alive).
const OptionTable<solvers::LigandPotential>& ligand_table() {
  static const auto table = [] {
    OptionTable<solvers::LigandPotential> t;
    t.field("charge", MOLMESH_FIELD(charge),
            "charge z of the diffusing ligand: beta W = z * phi (with potential)");
    return t;
  }();
  return table;
}

const OptionTable<solvers::PoissonOptions>& poisson_table() {
  static const auto table = [] {
    OptionTable<solvers::PoissonOptions> t;
    t.field("pdie", MOLMESH_FIELD(pdie), "relative permittivity of the molecule (region 1)");
    t.field("sdie", MOLMESH_FIELD(sdie), "relative permittivity of the solvent (region 2)");
    return t;
  }();
  return table;
}

py::array_t<double> to_array(const Eigen::VectorXd& v) {
  py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
  std::copy(v.data(), v.data() + v.size(), out.mutable_data());
  return out;
}

struct PySolveResult {
  double rate_constant = std::numeric_limits<double>::quiet_NaN();
  double rate_constant_A3_per_s = std::numeric_limits<double>::quiet_NaN();
  double solvation_energy = std::numeric_limits<double>::quiet_NaN();
  py::dict fields;  // name -> (n,) array on the solve level's volume vertices
  py::dict report;  // counts and the solver report(s)
  bool converged() const { return py::cast<bool>(report["converged"]); }
  int iterations() const { return py::cast<int>(report["iterations"]); }
};

}  // namespace

void bind_solvers(py::module_& m) {
  py::class_<PySolveResult>(m, "SolveResult",
                            "A solve's result: rate_constant (M^-1 s^-1, Smoluchowski), "
                            "rate_constant_A3_per_s, solvation_energy (kJ/mol, Poisson), "
                            "fields (name -> float64 array per volume vertex of the solve "
                            "level), report (the keys of `molmesh solve --json`).")
      .def_readonly("rate_constant", &PySolveResult::rate_constant)
      .def_readonly("rate_constant_A3_per_s", &PySolveResult::rate_constant_A3_per_s)
      .def_readonly("solvation_energy", &PySolveResult::solvation_energy)
      .def_readonly("fields", &PySolveResult::fields)
      .def_readonly("report", &PySolveResult::report)
      .def_property_readonly("converged", &PySolveResult::converged)
      .def_property_readonly("iterations", &PySolveResult::iterations)
      .def("__repr__", [](const PySolveResult& r) {
        return std::string("<molmesh.SolveResult: ") +
               (std::isnan(r.rate_constant)
                    ? "solvation energy " + std::to_string(r.solvation_energy) + " kJ/mol"
                    : "rate " + std::to_string(r.rate_constant) + " M^-1 s^-1") +
               ">";
      });

  const std::string smol_doc =
      "solve_smoluchowski(hierarchy, *, potential=None, progress=None, **options) "
      "-> SolveResult\n\n"
      "Steady-state Smoluchowski diffusion in the solvent of a hierarchy level, as `molmesh "
      "solve smoluchowski` (c = bulk on the outer sphere, 0 on absorbing faces). potential: "
      "phi in kT/e (a Volume or a .dx/.mrc path), beta W = charge * phi. fields: "
      "'concentration' (units of c_bulk), 'beta_W'. Options (default):\n" +
      setup_table().describe(SolveSetup{}) +
      smoluchowski_table().describe(solvers::SmoluchowskiOptions{}) +
      ligand_table().describe(solvers::LigandPotential{});
  m.def(
      "solve_smoluchowski",
      [](const PyHierarchy& h, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        py::object potential = kw.contains("potential") ? kw.attr("pop")("potential") : py::none();
        SolveSetup setup;
        solvers::SmoluchowskiOptions options;
        solvers::LigandPotential ligand;
        setup_table().take(kw, setup);
        smoluchowski_table().take(kw, options);
        ligand_table().take(kw, ligand);
        reject_unknown(kw, "solve_smoluchowski",
                       names_of(setup_table(), smoluchowski_table(), ligand_table()));
        options.solver = setup.solver;
        std::shared_ptr<const Grid> grid;
        if (py::isinstance<PyVolume>(potential)) {
          grid = potential.cast<PyVolume&>().grid;
        } else if (!potential.is_none()) {
          const auto path = py::cast<std::filesystem::path>(potential);
          py::gil_scoped_release release;
          grid = std::make_shared<const Grid>(read_volume(path));
        }
        ligand.potential = grid.get();
        const std::shared_ptr<const Hierarchy> hierarchy = h.hierarchy;
        PythonProgress bridge(progress);
        solvers::HierarchySmoluchowskiResult out = bridge.run([&](const Reporter& r) {
          return solvers::solve_smoluchowski(*hierarchy, setup.levels, options, ligand, r);
        });
        PySolveResult result;
        result.rate_constant = out.result.rate_constant_per_molar_per_s;
        result.rate_constant_A3_per_s = out.result.rate_constant_A3_per_s;
        result.fields["concentration"] = to_array(out.result.concentration);
        if (!out.beta_w.empty())
          result.fields["beta_W"] =
              py::array_t<double>(static_cast<py::ssize_t>(out.beta_w.size()), out.beta_w.data());
        // The keys of `molmesh solve smoluchowski --json` that the solve reports.
        result.report = json_to_python(solvers::to_json(out).dump());
        py::dict parameters = setup_table().values(setup);
        parameters.attr("update")(smoluchowski_table().values(options));
        parameters.attr("update")(ligand_table().values(ligand));
        result.report["parameters"] = parameters;
        return result;
      },
      py::arg("hierarchy"), smol_doc.c_str());
  register_defaults("solve_smoluchowski", [] {
    py::dict d = setup_table().values(SolveSetup{});
    d.attr("update")(smoluchowski_table().values(solvers::SmoluchowskiOptions{}));
    d.attr("update")(ligand_table().values(solvers::LigandPotential{}));
    d["potential"] = py::none();
    return d;
  });

  const std::string poisson_doc =
      "solve_poisson(hierarchy, atoms, *, progress=None, **options) -> SolveResult\n\n"
      "Electrostatic solvation energy (kJ/mol) of `atoms` (positions and charges) from the "
      "linear Poisson equation on a full-mesh hierarchy level, by the reference-solve "
      "method, as `molmesh solve poisson`. fields: 'potential_kJ_per_mol_e', "
      "'reaction_potential_kJ_per_mol_e'. Options (default):\n" +
      setup_table().describe(SolveSetup{}) + poisson_table().describe(solvers::PoissonOptions{});
  m.def(
      "solve_poisson",
      [](const PyHierarchy& h, const PyAtoms& atoms, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        SolveSetup setup;
        solvers::PoissonOptions options;
        setup_table().take(kw, setup);
        poisson_table().take(kw, options);
        reject_unknown(kw, "solve_poisson", names_of(setup_table(), poisson_table()));
        options.solver = setup.solver;
        const std::shared_ptr<const Hierarchy> hierarchy = h.hierarchy;
        const std::shared_ptr<const Atoms> charges = atoms.atoms;
        PythonProgress bridge(progress);
        solvers::PoissonResult out = bridge.run([&](const Reporter& r) {
          return solvers::solve_solvation_energy(*hierarchy, setup.levels, *charges, options, r);
        });
        PySolveResult result;
        result.solvation_energy = out.solvation_energy_kj_per_mol;
        result.fields["potential_kJ_per_mol_e"] = to_array(out.potential);
        result.fields["reaction_potential_kJ_per_mol_e"] = to_array(out.reaction_potential);
        // The keys of `molmesh solve poisson --json` that the solve reports.
        result.report = json_to_python(solvers::to_json(out).dump());
        py::dict parameters = setup_table().values(setup);
        parameters.attr("update")(poisson_table().values(options));
        result.report["parameters"] = parameters;
        return result;
      },
      py::arg("hierarchy"), py::arg("atoms"), poisson_doc.c_str());
  register_defaults("solve_poisson", [] {
    py::dict d = setup_table().values(SolveSetup{});
    d.attr("update")(poisson_table().values(solvers::PoissonOptions{}));
    return d;
  });
}

}  // namespace molmesh::python
