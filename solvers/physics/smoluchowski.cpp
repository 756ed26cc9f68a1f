#include "solvers/physics/smoluchowski.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <chrono>
#include <cmath>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "solvers/fem/dirichlet.hpp"
#include "solvers/fem/p1_assembly.hpp"
#include "solvers/physics/units.hpp"

namespace molmesh::solvers {

namespace {

// The fine level needs the whole stiffness matrix (the flux is its residual at the absorbing
// vertices); a coarse level needs only the reduced one.
enum class WholeMatrix { kNeeded, kNotNeeded };

// The assembled Slotboom operator of one mesh with its boundary conditions.
struct Discretisation {
  SparseMatrix k;  // un-reduced stiffness (empty for WholeMatrix::kNotNeeded)
  std::vector<char> dirichlet, is_absorbing, in_solvent;
  Eigen::VectorXd values;
  ReducedSystem system;
  int absorbing_vertices = 0, bulk_vertices = 0, isolated_vertices = 0;
};

Discretisation discretise(const TetMesh& mesh, std::span<const double> beta_w,
                          const SmoluchowskiOptions& options, const Reporter& reporter,
                          WholeMatrix matrix) {
  const std::size_t nv = mesh.points.size();
  if (!beta_w.empty() && beta_w.size() != nv) {
    throw Error("Smoluchowski: " + std::to_string(beta_w.size()) + " potential values for " +
                std::to_string(nv) + " vertices");
  }
  Discretisation out;
  // One exponential per vertex, not four per cell.
  std::vector<double> boltzmann(nv, 1.0);
  for (std::size_t v = 0; v < beta_w.size(); ++v) {
    boltzmann[v] = std::exp(-beta_w[v]);
    if (!std::isfinite(boltzmann[v]) || !(boltzmann[v] > 0.0)) {
      throw Error("Smoluchowski: beta*W = " + std::to_string(beta_w[v]) + " at vertex " +
                  std::to_string(v) +
                  " puts the Boltzmann factor exp(-beta*W) outside the range of a double; is "
                  "the potential in kT/e, and sampled in the solvent?");
    }
  }

  // exp(-beta W) averaged over each cell's vertices: the integral of its P1 interpolant,
  // which stays accurate where the potential varies quickly near the surface.
  const bool has_regions = mesh.cell_markers.size() == mesh.tetrahedra.size();
  std::vector<double> coefficient(mesh.tetrahedra.size(), 0.0);
  out.in_solvent.assign(nv, 0);
  auto& in_solvent = out.in_solvent;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    if (has_regions && mesh.cell_markers[t] != options.solvent_region) continue;
    double sum = 0.0;
    for (int v : mesh.tetrahedra[t]) {
      sum += boltzmann[static_cast<std::size_t>(v)];
      in_solvent[static_cast<std::size_t>(v)] = 1;
    }
    coefficient[t] = 0.25 * sum;
  }

  const std::vector<unsigned> bits = boundary_vertex_marker_bits(mesh);
  const unsigned absorbing = marker_mask(options.absorbing_markers);
  const unsigned bulk = marker_mask(options.bulk_markers);
  out.dirichlet.assign(nv, 0);
  out.is_absorbing.assign(nv, 0);
  out.values = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nv));
  auto& dirichlet = out.dirichlet;
  auto& is_absorbing = out.is_absorbing;
  auto& values = out.values;

  for (std::size_t v = 0; v < nv; ++v) {
    if (!in_solvent[v]) {
      dirichlet[v] = 1;  // not part of the problem
    } else if (bits[v] & absorbing) {
      dirichlet[v] = 1;
      is_absorbing[v] = 1;
      ++out.absorbing_vertices;
    } else if (bits[v] & bulk) {
      dirichlet[v] = 1;
      // Bulk in Boltzmann equilibrium: c = exp(-beta W), i.e. s = 1 (= c_bulk where W = 0).
      values[static_cast<Eigen::Index>(v)] = 1.0;
      ++out.bulk_vertices;
    }
  }
  // Solvent pockets that touch neither the bulk nor an absorbing face (closed cavities)
  // would make the system singular; nothing diffuses into them, so they are left out
  // (c = 0 there) and counted.
  {
    boost::disjoint_sets_with_storage<> sets(nv);
    for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
      if (coefficient[t] == 0.0) continue;
      for (std::size_t a = 1; a < 4; ++a)
        sets.union_set(mesh.tetrahedra[t][0], mesh.tetrahedra[t][a]);
    }
    std::vector<char> anchored(nv, 0);
    for (std::size_t v = 0; v < nv; ++v) {
      if (in_solvent[v] && dirichlet[v]) anchored[sets.find_set(v)] = 1;
    }
    for (std::size_t v = 0; v < nv; ++v) {
      if (in_solvent[v] && !anchored[sets.find_set(v)]) {
        in_solvent[v] = 0;
        dirichlet[v] = 1;
        ++out.isolated_vertices;
      }
    }
  }
  if (out.isolated_vertices > 0) {
    reporter.warn("Smoluchowski: " + std::to_string(out.isolated_vertices) +
                  " solvent vertices lie in closed cavities (no bulk or absorbing boundary); "
                  "they are left out with c = 0");
  }
  if (out.absorbing_vertices == 0) {
    throw Error(
        "Smoluchowski: no solvent vertex lies on an absorbing boundary face (is the "
        "active site marked in this mesh?)");
  }
  if (out.bulk_vertices == 0) {
    throw Error("Smoluchowski: no vertex lies on the outer (bulk) boundary");
  }
  if (matrix == WholeMatrix::kNotNeeded) {
    // A coarse level: only the free-free block, assembled directly (no whole matrix and no
    // reduced copy of it, whose fresh pages cost more than the arithmetic; issue 16).
    out.system = number_free_vertices(dirichlet);
    SparseMatrix a = assemble_stiffness(mesh, coefficient, out.system.full_to_free);
    out.system.matrix.swap(a);  // not `= ...`, which copies (multigrid.hpp, MeshOperator)
    return out;
  }
  {
    SparseMatrix k = assemble_stiffness(mesh, coefficient);
    out.k.swap(k);
  }
  // Assigned (a copy of the matrix): swapping the fine system in was measured slower, in
  // setup and in the solve (docs/benchmarks.md, issue 16).
  out.system = reduce_dirichlet(out.k, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nv)),
                                dirichlet, values);
  return out;
}

}  // namespace

SmoluchowskiResult solve_smoluchowski(const TetMesh& mesh, std::span<const double> beta_w,
                                      std::span<const SparseMatrix> prolongations,
                                      const SmoluchowskiOptions& options, const Reporter& reporter,
                                      std::span<const CoarseLevel> coarse_levels) {
  const std::size_t nv = mesh.points.size();
  if (!(options.diffusion_cm2_per_s > 0.0)) {
    throw Error("Smoluchowski: the diffusion coefficient must be positive");
  }
  reporter.progress("smoluchowski: assemble", 0.0);
  auto bw = [&](std::size_t v) { return beta_w.empty() ? 0.0 : beta_w[v]; };
  Discretisation fine = discretise(mesh, beta_w, options, reporter, WholeMatrix::kNeeded);
  SmoluchowskiResult result;
  result.absorbing_vertices = fine.absorbing_vertices;
  result.bulk_vertices = fine.bulk_vertices;
  result.isolated_vertices = fine.isolated_vertices;
  const ReducedSystem& system = fine.system;
  const SparseMatrix& k = fine.k;
  const auto& in_solvent = fine.in_solvent;
  const auto& is_absorbing = fine.is_absorbing;
  const auto& dirichlet = fine.dirichlet;
  const auto& values = fine.values;
  // Discretising the coarse meshes is part of the multigrid setup: timed and counted there.
  const auto coarse_start = std::chrono::steady_clock::now();
  // One level after the other, on this thread (each assembly is parallel inside): the
  // levels then reuse the memory the fine level freed, where side by side the worker
  // threads' malloc arenas handed out fresh pages, slower on the 1.5M-tet benchmark
  // (docs/benchmarks.md, issue 16).
  // Only multigrid uses them.
  if (options.solver.preconditioning != Preconditioning::kMultigrid) coarse_levels = {};
  std::vector<MeshOperator> mesh_operators(coarse_levels.size());
  for (const CoarseLevel& level : coarse_levels)
    if (level.mesh == nullptr) throw Error("Smoluchowski: a coarse level has no mesh");
  // Coarse levels only precondition. Their vertices can sample the potential grid inside
  // the molecule (coarse surfaces deviate from the fine one), where grid potentials near
  // atom centres reach hundreds of kT/e and exp(-beta W) over- or underflows. Their beta W
  // is clamped to the range the fine level sees: the answer is the fine level's either way.
  double lowest = 0.0, highest = 0.0;
  if (!beta_w.empty()) {
    const auto [lo, hi] = std::minmax_element(beta_w.begin(), beta_w.end());
    lowest = *lo;
    highest = *hi;
  }
  for (std::size_t l = 0; l < coarse_levels.size(); ++l) {
    std::vector<double> clamped(coarse_levels[l].beta_w.begin(), coarse_levels[l].beta_w.end());
    for (double& w : clamped) w = std::clamp(w, lowest, highest);
    Discretisation coarse =
        discretise(*coarse_levels[l].mesh, clamped, options, {}, WholeMatrix::kNotNeeded);
    mesh_operators[l].a.swap(coarse.system.matrix);
    mesh_operators[l].free_to_full = std::move(coarse.system.free_to_full);
  }
  result.unknowns = static_cast<int>(system.free_to_full.size());
  reporter.progress("smoluchowski: assemble", 1.0);
  reporter.progress("smoluchowski: solve", 0.0);
  Eigen::VectorXd x;
  const double coarse_seconds = seconds_since(coarse_start);
  result.solve = solve_reduced(system, prolongations, options.solver, x, std::move(mesh_operators));
  result.solve.setup_time_s += coarse_seconds;
  reporter.progress("smoluchowski: solve", 1.0);
  if (!result.solve.converged) {
    reporter.warn("Smoluchowski: CG stopped at relative residual " +
                  std::to_string(result.solve.relative_residual) + " after " +
                  std::to_string(result.solve.iterations) + " iterations");
  }
  result.slotboom = expand_solution(system, x, dirichlet, values);
  // Residual of the full system at the absorbing vertices = -(flux into them) for unit D.
  const Eigen::VectorXd residual = k * result.slotboom;
  double flux = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    if (is_absorbing[v]) flux -= residual[static_cast<Eigen::Index>(v)];
  }
  const double d = options.diffusion_cm2_per_s * units::kSquareAngstromPerSquareCm;
  result.rate_constant_A3_per_s = d * flux;
  result.rate_constant_per_molar_per_s =
      units::rate_to_per_molar_per_second(result.rate_constant_A3_per_s);
  result.concentration.resize(static_cast<Eigen::Index>(nv));
  for (std::size_t v = 0; v < nv; ++v) {
    const auto i = static_cast<Eigen::Index>(v);
    result.concentration[i] = in_solvent[v] ? result.slotboom[i] * std::exp(-bw(v)) : 0.0;
  }
  return result;
}

}  // namespace molmesh::solvers
