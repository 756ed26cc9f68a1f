#include "solvers/multigrid/linear_solver.hpp"

#include <chrono>
#include <memory>

#include "molmesh/core/timing.hpp"

namespace molmesh::solvers {

SolveReport solve_reduced(const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                          const LinearSolverOptions& options, Eigen::VectorXd& x,
                          std::vector<MeshOperator> mesh_operators) {
  if (options.engine)
    return options.engine(system, prolongations, options, x, std::move(mesh_operators));
  const bool mesh_coarse_operators = !mesh_operators.empty();
  const auto start = std::chrono::steady_clock::now();
  Preconditioner preconditioner;
  std::vector<int> sizes;
  std::string name;
  std::shared_ptr<MultigridPreconditioner> mg;
  std::size_t mesh_levels = 0;
  std::vector<long> nonzeros;
  if (options.preconditioning == Preconditioning::kMultigrid) {
    mg =
        std::make_shared<MultigridPreconditioner>(system.matrix, system.free_to_full, prolongations,
                                                  options.multigrid, std::move(mesh_operators));
    sizes = mg->level_sizes();
    mesh_levels = mg->mesh_levels();
    nonzeros = mg->level_nonzeros();
    if (sizes.size() < 2) {
      name = "direct (sparse LDLT)";
    } else {
      name = std::string("multigrid V-cycle (symmetric Gauss-Seidel, ") +
             (!mesh_coarse_operators ? "Galerkin coarse operators; "
                                     : "re-discretised coarse mesh operators; ") +
             std::to_string(mesh_levels) + " mesh + " + std::to_string(sizes.size() - mesh_levels) +
             " aggregation levels" + (mg->coarsest_was_shifted() ? ", shifted coarsest)" : ")");
    }
  } else {
    preconditioner = make_incomplete_cholesky(system.matrix);
    name = "incomplete Cholesky";
  }
  const double setup = seconds_since(start);
  x = Eigen::VectorXd::Zero(system.rhs.size());
  SolveReport report =
      mg ? preconditioned_cg_with_product(
               system.matrix, system.rhs, x,
               [&](const Eigen::VectorXd& r, Eigen::VectorXd& z, Eigen::VectorXd& az) {
                 mg->apply_with_product(r, z, az);
               },
               options.cg)
         : preconditioned_cg(system.matrix, system.rhs, x, preconditioner, options.cg);
  report.setup_time_s = setup;
  report.preconditioner = name;
  report.level_sizes = std::move(sizes);
  report.mesh_levels = static_cast<int>(mesh_levels);
  report.level_nonzeros = std::move(nonzeros);
  return report;
}

}  // namespace molmesh::solvers
