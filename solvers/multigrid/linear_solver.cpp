#include "solvers/multigrid/linear_solver.hpp"

#include <chrono>
#include <memory>

namespace molmesh::solvers {

SolveReport solve_reduced(const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                          const LinearSolverOptions& options, Eigen::VectorXd& x) {
  const auto start = std::chrono::steady_clock::now();
  Preconditioner preconditioner;
  std::vector<int> sizes;
  std::string name;
  std::shared_ptr<MultigridPreconditioner> mg;
  if (options.preconditioning == Preconditioning::kMultigrid) {
    mg = std::make_shared<MultigridPreconditioner>(system.matrix, system.free_to_full,
                                                   prolongations, options.multigrid);
    sizes = mg->level_sizes();
    // Without a usable coarse level the "V-cycle" is a sparse direct solve of the whole
    // system, which is only sensible for small systems.
    if (sizes.size() < 2 && system.matrix.rows() > options.direct_solve_limit) {
      mg.reset();
      sizes.clear();
    }
  }
  if (mg) {
    preconditioner = [mg](const Eigen::VectorXd& r, Eigen::VectorXd& z) { mg->apply(r, z); };
    name = sizes.size() < 2 ? "direct (sparse LDLT; no coarse level)"
                            : std::string(
                                  "multigrid V-cycle (symmetric Gauss-Seidel, Galerkin coarse "
                                  "operators") +
                                  (mg->coarsest_was_shifted() ? ", shifted coarsest)" : ")");
  } else if (options.preconditioning == Preconditioning::kMultigrid) {
    preconditioner = make_incomplete_cholesky(system.matrix);
    name = "incomplete Cholesky (fallback: the hierarchy has no level coarse enough)";
  } else {
    preconditioner = make_incomplete_cholesky(system.matrix);
    name = "incomplete Cholesky";
  }
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  x = Eigen::VectorXd::Zero(system.rhs.size());
  SolveReport report = preconditioned_cg(system.matrix, system.rhs, x, preconditioner, options.cg);
  report.setup_time_s = setup;
  report.preconditioner = name;
  report.level_sizes = std::move(sizes);
  return report;
}

}  // namespace molmesh::solvers
