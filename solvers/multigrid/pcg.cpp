#include "solvers/multigrid/pcg.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/IterativeLinearSolvers>
#include <chrono>
#include <cmath>
#include <memory>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"

namespace molmesh::solvers {

void parallel_multiply(const SparseMatrix& a, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  y.resize(a.rows());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* values = a.valuePtr();
  const bool compressed = a.isCompressed();
  const int* nnz = a.innerNonZeroPtr();
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, a.rows(), 2048),
                    [&](const tbb::blocked_range<Eigen::Index>& range) {
                      for (Eigen::Index i = range.begin(); i != range.end(); ++i) {
                        const int begin = outer[i];
                        const int end = compressed ? outer[i + 1] : begin + nnz[i];
                        double sum = 0.0;
                        for (int k = begin; k < end; ++k) sum += values[k] * x[inner[k]];
                        y[i] = sum;
                      }
                    });
}

namespace {

// The CG iteration. With kProductFromPreconditioner the preconditioner also returns A z,
// and the search direction's product follows the same recurrence as the direction,
// A p = A z + beta A p_old, instead of costing a pass over A every iteration. Both products
// are the same up to rounding; the final residual is recomputed from A x either way.
template <bool kProductFromPreconditioner, class Precondition>
SolveReport cg(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
               const Precondition& precondition, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    x.setZero();
    report.converged = true;
    report.residual_history.push_back(0.0);
    return report;
  }
  Eigen::VectorXd r(b.size()), z(b.size()), p(b.size()), q(b.size());
  Eigen::VectorXd az;  // sized by the preconditioner that fills it
  // The usual start is x = 0 (solve_reduced's), where A x needs no pass over A.
  if (x.isZero(0.0)) {
    r = b;
  } else {
    parallel_multiply(a, x, q);
    r = b - q;
  }
  double rnorm = r.norm();
  report.residual_history.push_back(rnorm / bnorm);
  precondition(r, z, az);
  p = z;
  if constexpr (kProductFromPreconditioner) q = az;
  double rz = r.dot(z);
  int k = 0;
  while (rnorm / bnorm > options.tolerance && k < options.max_iterations) {
    if constexpr (!kProductFromPreconditioner) parallel_multiply(a, p, q);
    const double pq = p.dot(q);
    if (!(pq > 0.0)) break;  // breakdown: A or M not positive definite on this direction
    const double alpha = rz / pq;
    x += alpha * p;
    r -= alpha * q;
    rnorm = r.norm();
    ++k;
    report.residual_history.push_back(rnorm / bnorm);
    if (rnorm / bnorm <= options.tolerance) break;
    precondition(r, z, az);
    const double rz_new = r.dot(z);
    const double beta = rz_new / rz;
    p = z + beta * p;
    if constexpr (kProductFromPreconditioner) q = az + beta * q;
    rz = rz_new;
  }
  parallel_multiply(a, x, q);
  report.iterations = k;
  report.relative_residual = (b - q).norm() / bnorm;
  // The recurrence residual can drift from the true one; judge by the true residual, with
  // a little slack for rounding in the recomputation itself.
  report.converged = report.relative_residual <= 10.0 * options.tolerance;
  report.solve_time_s = seconds_since(start);
  return report;
}

}  // namespace

SolveReport preconditioned_cg(const SparseMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              const Preconditioner& preconditioner, const SolveOptions& options) {
  return cg<false>(
      a, b, x,
      [&](const Eigen::VectorXd& r, Eigen::VectorXd& z, Eigen::VectorXd&) { preconditioner(r, z); },
      options);
}

SolveReport preconditioned_cg_with_product(const SparseMatrix& a, const Eigen::VectorXd& b,
                                           Eigen::VectorXd& x,
                                           const PreconditionerWithProduct& preconditioner,
                                           const SolveOptions& options) {
  return cg<true>(a, b, x, preconditioner, options);
}

Preconditioner make_incomplete_cholesky(const SparseMatrix& a) {
  using ColMajor = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  using Factor = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>;
  auto factor = std::make_shared<Factor>();
  const ColMajor lower = ColMajor(a).triangularView<Eigen::Lower>();
  factor->compute(lower);
  if (factor->info() != Eigen::Success) {
    throw Error("incomplete Cholesky factorisation failed (matrix not positive definite?)");
  }
  return [factor](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = factor->solve(r); };
}

}  // namespace molmesh::solvers
