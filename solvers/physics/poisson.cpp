#include "solvers/physics/poisson.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/fem/point_locator.hpp"
#include "solvers/physics/units.hpp"

namespace molmesh::solvers {

namespace {

struct Charge {
  double q = 0.0;
  PointLocation where;
};

double evaluate(const TetMesh& mesh, const Eigen::VectorXd& field, const PointLocation& at) {
  double value = 0.0;
  const Tetrahedron& tet = mesh.tetrahedra[static_cast<std::size_t>(at.tetrahedron)];
  for (std::size_t a = 0; a < 4; ++a) value += at.barycentric[a] * field[tet[a]];
  return value;
}

std::vector<char> dirichlet_vertices(const TetMesh& mesh, const std::vector<int>& markers) {
  const std::vector<unsigned> bits = boundary_vertex_marker_bits(mesh);
  const unsigned mask = marker_mask(markers);
  std::vector<char> dirichlet(mesh.points.size(), 0);
  for (std::size_t v = 0; v < dirichlet.size(); ++v) dirichlet[v] = (bits[v] & mask) != 0;
  return dirichlet;
}

// The operator of one permittivity table on a coarse mesh, its Dirichlet vertices removed,
// into `out` (swapped in: multigrid.hpp, MeshOperator, on moving sparse matrices).
void coarse_operator(const TetMesh& mesh, std::span<const std::pair<int, double>> table,
                     const std::vector<int>& dirichlet_markers, MeshOperator& out) {
  // Only the free-free block: the whole matrix and its reduced copy are never built.
  const ReducedSystem numbering = number_free_vertices(dirichlet_vertices(mesh, dirichlet_markers));
  SparseMatrix a =
      assemble_stiffness(mesh, cell_coefficients_by_region(mesh, table), numbering.full_to_free);
  out.a.swap(a);
  out.free_to_full = numbering.free_to_full;
}

}  // namespace

PoissonResult solve_solvation_energy(const TetMesh& mesh, const Atoms& atoms,
                                     std::span<const SparseMatrix> prolongations,
                                     const PoissonOptions& options, const Reporter& reporter,
                                     std::span<const CoarseLevel> coarse_levels) {
  if (!(options.pdie > 0.0) || !(options.sdie > 0.0)) {
    throw Error("Poisson: permittivities must be positive");
  }
  const std::size_t nv = mesh.points.size();
  const auto n = static_cast<Eigen::Index>(nv);
  PoissonResult result;
  reporter.progress("poisson: locate charges", 0.0);
  const PointLocator locator(mesh);
  std::vector<Charge> charges;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    if (atoms[i].charge == 0.0) continue;
    const auto where = locator.locate(atoms[i].center);
    if (!where) {
      throw Error("Poisson: atom " + std::to_string(i + 1) + " (" + atoms[i].residue_name + " " +
                  std::to_string(atoms[i].residue_number) + " " + atoms[i].atom_name +
                  ") lies outside the mesh; a full mesh (molecule and solvent) is needed");
    }
    const Tetrahedron& tet = mesh.tetrahedra[static_cast<std::size_t>(where->tetrahedron)];
    double nearest = 1e300;
    for (int v : tet) {
      nearest =
          std::min(nearest, (mesh.points[static_cast<std::size_t>(v)] - atoms[i].center).norm());
    }
    result.max_charge_offset = std::max(result.max_charge_offset, nearest);
    charges.push_back({atoms[i].charge, *where});
  }
  result.charges = static_cast<int>(charges.size());
  if (charges.empty()) throw Error("Poisson: no atom carries a charge");

  // -div(eps grad phi) = 4 pi C sum q delta: phi in kJ/(mol e), eps relative.
  const double source_scale = 4.0 * std::numbers::pi * units::kCoulombKjAngstromPerMol;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(n);
  for (const Charge& c : charges) {
    const Tetrahedron& tet = mesh.tetrahedra[static_cast<std::size_t>(c.where.tetrahedron)];
    for (std::size_t a = 0; a < 4; ++a) load[tet[a]] += source_scale * c.q * c.where.barycentric[a];
  }

  const std::vector<char> dirichlet = dirichlet_vertices(mesh, options.dirichlet_markers);
  std::vector<std::size_t> boundary;
  for (std::size_t v = 0; v < nv; ++v) {
    if (dirichlet[v]) boundary.push_back(v);
  }
  if (boundary.empty()) throw Error("Poisson: the mesh has no outer-sphere (Dirichlet) vertex");
  // Coulomb sum at boundary vertices, with unit permittivity; scaled per solve below.
  Eigen::VectorXd coulomb = Eigen::VectorXd::Zero(n);
  for (std::size_t v : boundary) {
    double sum = 0.0;
    for (std::size_t i = 0; i < atoms.size(); ++i) {
      if (atoms[i].charge == 0.0) continue;
      sum += atoms[i].charge / (mesh.points[v] - atoms[i].center).norm();
    }
    coulomb[static_cast<Eigen::Index>(v)] = units::kCoulombKjAngstromPerMol * sum;
  }

  auto solve = [&](double inside, double outside, SolveReport& report, const char* stage) {
    reporter.progress(stage, 0.0);
    const std::pair<int, double> table[] = {{markers::kMoleculeRegion, inside},
                                            {markers::kSolventRegion, outside}};
    const SparseMatrix k = assemble_stiffness(mesh, cell_coefficients_by_region(mesh, table));
    const Eigen::VectorXd values = coulomb / outside;
    const ReducedSystem system = reduce_dirichlet(k, load, dirichlet, values);
    result.unknowns = static_cast<int>(system.free_to_full.size());
    // Coarse operators are part of the multigrid setup: timed and counted there.
    const auto coarse_start = std::chrono::steady_clock::now();
    std::vector<MeshOperator> mesh_operators;
    if (options.solver.preconditioning == Preconditioning::kMultigrid) {
      for (const CoarseLevel& coarse : coarse_levels)
        if (coarse.mesh == nullptr) throw Error("Poisson: a coarse level has no mesh");
      mesh_operators.resize(coarse_levels.size());
      // One level after the other, as in smoluchowski.cpp (memory reuse beats overlap).
      for (std::size_t l = 0; l < coarse_levels.size(); ++l)
        coarse_operator(*coarse_levels[l].mesh, table, options.dirichlet_markers,
                        mesh_operators[l]);
    }
    const double coarse_seconds = seconds_since(coarse_start);
    Eigen::VectorXd x;
    report = solve_reduced(system, prolongations, options.solver, x, std::move(mesh_operators));
    report.setup_time_s += coarse_seconds;
    if (!report.converged) {
      reporter.warn(std::string(stage) + ": CG stopped at relative residual " +
                    std::to_string(report.relative_residual));
    }
    reporter.progress(stage, 1.0);
    return expand_solution(system, x, dirichlet, values);
  };
  result.potential = solve(options.pdie, options.sdie, result.solvated, "poisson: solvated");
  const Eigen::VectorXd reference =
      solve(options.pdie, options.pdie, result.reference, "poisson: reference");
  result.reaction_potential = result.potential - reference;
  double energy = 0.0;
  for (const Charge& c : charges) {
    energy += 0.5 * c.q * evaluate(mesh, result.reaction_potential, c.where);
  }
  result.solvation_energy_kj_per_mol = energy;
  return result;
}

}  // namespace molmesh::solvers
