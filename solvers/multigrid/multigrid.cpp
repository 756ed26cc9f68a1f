#include "solvers/multigrid/multigrid.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <deque>
#include <string>

#include "molmesh/core/error.hpp"
#include "solvers/multigrid/aggregation.hpp"
#include "solvers/multigrid/gauss_seidel.hpp"
#include "solvers/multigrid/pcg.hpp"
#include "solvers/multigrid/sparse_product.hpp"

namespace molmesh::solvers {

namespace {

using ColMajor = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

struct Level {
  // The level's operator: the caller's fine matrix on level 0 (not copied), `owned` below.
  // Set, with the smoother that also points at it, once every level exists.
  const SparseMatrix* a = nullptr;
  SparseMatrix owned;
  GaussSeidelSmoother smoother;
  SparseMatrix p;   // this level x next coarser level (empty on the coarsest)
  SparseMatrix pt;  // restriction
};

// The rows `rows` of m (in that order), with column c renumbered column_index[c] and
// dropped where that is negative. Renumbering is increasing, so rows stay sorted.
SparseMatrix select_rows_and_columns(const SparseMatrix& m, std::span<const int> rows,
                                     std::span<const int> column_index, Eigen::Index columns) {
  SparseMatrix out(static_cast<Eigen::Index>(rows.size()), columns);
  std::size_t upper_bound = 0;
  for (int r : rows)
    upper_bound += static_cast<std::size_t>(m.outerIndexPtr()[r + 1] - m.outerIndexPtr()[r]);
  out.resizeNonZeros(static_cast<Eigen::Index>(upper_bound));
  int* outer = out.outerIndexPtr();
  int count = 0;
  outer[0] = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (SparseMatrix::InnerIterator it(m, rows[i]); it; ++it) {
      const int c = column_index[static_cast<std::size_t>(it.col())];
      if (c >= 0) {
        out.innerIndexPtr()[count] = c;
        out.valuePtr()[count] = it.value();
        ++count;
      }
    }
    outer[i + 1] = count;
  }
  out.resizeNonZeros(count);
  return out;
}

}  // namespace

// One level's vectors in a V-cycle, kept from cycle to cycle so that a cycle allocates
// nothing (on a 1M-tetrahedron fine level each is ~2 MB, fresh pages for every cycle).
struct CycleWorkspace {
  Eigen::VectorXd before;       // x before the last forward sweep (several sweeps only)
  Eigen::VectorXd sweep_start;  // a sweep's copy of x (gauss_seidel.hpp)
  Eigen::VectorXd residual;
  Eigen::VectorXd coarse_rhs;
  Eigen::VectorXd coarse_x;
  Eigen::VectorXd correction;
};

struct MultigridPreconditioner::Impl {
  // A deque, so adding a level moves none of the others (moving a Level would copy its
  // matrices: hierarchy.hpp).
  std::deque<Level> levels;
  Eigen::SimplicialLDLT<ColMajor> coarse_solver;
  MultigridOptions options;
  bool coarse_shifted = false;
  std::size_t mesh_levels = 0;
  mutable std::vector<CycleWorkspace> workspace;  // one per level
  const SparseMatrix* fine = nullptr;             // the caller's fine operator, if compressed

  // Level l's operator: the caller's matrix on level 0 (when compressed), else `owned`.
  const SparseMatrix& operator_of(std::size_t l) const {
    return l == 0 && fine ? *fine : levels[l].owned;
  }
  void add_mesh_levels(std::span<const int> fine_free_to_full,
                       std::span<const SparseMatrix> prolongations,
                       std::vector<MeshOperator>& mesh_operators);
  void add_aggregation_levels();
  void set_up_smoothers_and_coarsest_solve();

  // x = V-cycle(b) from a zero guess on level l; *product = A x when asked for (level 0
  // only: the last backward sweep gives it from its own pass over A).
  void vcycle(std::size_t l, const Eigen::VectorXd& b, Eigen::VectorXd& x,
              Eigen::VectorXd* product = nullptr) const {
    if (l + 1 == levels.size()) {
      x = coarse_solver.solve(b);
      if (product) parallel_multiply(*levels[l].a, x, *product);
      return;
    }
    const Level& level = levels[l];
    CycleWorkspace& w = workspace[l];
    if (options.smoothing_sweeps == 1) {
      forward_sweep_from_zero_with_residual(level.smoother, b, x, w.residual);
    } else {
      forward_sweep_from_zero(level.smoother, b, x);
      for (int s = 1; s < options.smoothing_sweeps; ++s) {
        w.before = x;
        forward_sweep(level.smoother, b, x, &w.sweep_start);
      }
      residual_after_forward_sweep(level.smoother, &w.before, x, w.residual);
    }
    parallel_multiply(level.pt, w.residual, w.coarse_rhs);
    vcycle(l + 1, w.coarse_rhs, w.coarse_x);
    parallel_multiply(level.p, w.coarse_x, w.correction);
    x += w.correction;
    for (int s = 0; s < options.smoothing_sweeps; ++s) {
      if (product && s + 1 == options.smoothing_sweeps)
        backward_sweep_with_product(level.smoother, b, x, w.sweep_start, *product);
      else
        backward_sweep(level.smoother, b, x, &w.sweep_start);
    }
  }
};

namespace {

// The coarse unknowns of a mesh level reached by `full` (level's vertices x coarse vertices)
// from the unknowns `rows_kept`: a given operator's own free vertices (its Dirichlet
// vertices are not coarse unknowns), or else the columns whose largest weight among those
// rows reaches drop_column_below. column_index[c] is c's unknown number or -1.
void choose_coarse_unknowns(const SparseMatrix& full, const std::vector<int>& rows_kept,
                            const MeshOperator* given, const MultigridOptions& options,
                            std::vector<int>& column_index, std::vector<int>& coarse_kept) {
  column_index.assign(static_cast<std::size_t>(full.cols()), -1);
  coarse_kept.clear();
  if (given) {
    for (int v : given->free_to_full) {
      if (v < 0 || v >= full.cols())
        throw Error("multigrid: a coarse operator refers to vertex " + std::to_string(v) +
                    " beyond its level");
      column_index[static_cast<std::size_t>(v)] = static_cast<int>(coarse_kept.size());
      coarse_kept.push_back(v);
    }
    return;
  }
  // Largest weight per coarse column among the rows that stay.
  std::vector<double> column_max(static_cast<std::size_t>(full.cols()), 0.0);
  for (int v : rows_kept) {
    for (SparseMatrix::InnerIterator it(full, v); it; ++it) {
      auto& m = column_max[static_cast<std::size_t>(it.col())];
      m = std::max(m, std::abs(it.value()));
    }
  }
  for (std::size_t c = 0; c < column_max.size(); ++c) {
    if (column_max[c] >= options.drop_column_below) {
      column_index[c] = static_cast<int>(coarse_kept.size());
      coarse_kept.push_back(static_cast<int>(c));
    }
  }
}

}  // namespace

void MultigridPreconditioner::Impl::add_mesh_levels(std::span<const int> fine_free_to_full,
                                                    std::span<const SparseMatrix> prolongations,
                                                    std::vector<MeshOperator>& mesh_operators) {
  // rows_kept[i] = vertex (of the current coarse mesh) behind unknown i on that level.
  std::vector<int> rows_kept(fine_free_to_full.begin(), fine_free_to_full.end());
  // A hierarchy level that is barely smaller than the current one would cost as much as
  // the current level and help little; it is skipped by composing its prolongation with
  // the next one.
  SparseMatrix pending;
  bool has_pending = false;
  std::vector<int> column_index, coarse_kept;
  for (std::size_t l = 0; l < prolongations.size(); ++l) {
    SparseMatrix composed;
    if (has_pending) composed = multiply(pending, prolongations[l]);
    const SparseMatrix& full = has_pending ? composed : prolongations[l];
    has_pending = false;
    for (int v : rows_kept) {
      if (v < 0 || v >= full.rows()) {
        throw Error("multigrid: prolongation " + std::to_string(l) + " has " +
                    std::to_string(full.rows()) + " rows but the level has vertex " +
                    std::to_string(v));
      }
    }
    MeshOperator* given = l < mesh_operators.size() ? &mesh_operators[l] : nullptr;
    choose_coarse_unknowns(full, rows_kept, given, options, column_index, coarse_kept);
    if (coarse_kept.empty()) break;
    const double ratio =
        static_cast<double>(coarse_kept.size()) / static_cast<double>(rows_kept.size());
    if (ratio > options.max_coarse_ratio) {
      if (l + 1 < prolongations.size()) {
        pending = full;
        has_pending = true;
        continue;
      }
      if (ratio > options.max_last_coarse_ratio) break;
    }
    if (given && given->a.rows() != static_cast<Eigen::Index>(coarse_kept.size()))
      throw Error("multigrid: a coarse operator's size does not match its unknowns");
    const std::size_t current = levels.size() - 1;
    Level& level = levels[current];
    {
      SparseMatrix p = select_rows_and_columns(full, rows_kept, column_index,
                                               static_cast<Eigen::Index>(coarse_kept.size()));
      level.p.swap(p);
    }
    level.pt = level.p.transpose();
    Level& coarse = levels.emplace_back();
    if (given) {
      coarse.owned.swap(given->a);
    } else {
      SparseMatrix product = galerkin_product(level.pt, operator_of(current), level.p);
      coarse.owned.swap(product);
    }
    coarse.owned.makeCompressed();
    rows_kept.swap(coarse_kept);
  }
  mesh_levels = levels.size();
}

// Below the mesh hierarchy: algebraic levels until a direct solve is cheap.
void MultigridPreconditioner::Impl::add_aggregation_levels() {
  while (operator_of(levels.size() - 1).rows() > options.max_direct_unknowns) {
    const std::size_t current = levels.size() - 1;
    SparseMatrix p = smoothed_aggregation_prolongation(operator_of(current), options.aggregation);
    if (p.cols() == 0 || static_cast<double>(p.cols()) >
                             options.max_aggregation_ratio * static_cast<double>(p.rows()))
      break;
    Level& level = levels[current];
    level.p.swap(p);
    level.pt = level.p.transpose();
    Level& coarse = levels.emplace_back();
    SparseMatrix product = galerkin_product(level.pt, operator_of(current), level.p);
    coarse.owned.swap(product);
    coarse.owned.makeCompressed();
  }
}

void MultigridPreconditioner::Impl::set_up_smoothers_and_coarsest_solve() {
  // The level list is final: operators and smoothers can point into it now.
  for (std::size_t l = 0; l < levels.size(); ++l) {
    levels[l].a = &operator_of(l);
    levels[l].smoother = make_gauss_seidel(*levels[l].a, options.smoothing_blocks);
  }
  workspace.resize(levels.size());

  const ColMajor coarsest(*levels.back().a);
  coarse_solver.compute(coarsest);
  if (coarse_solver.info() != Eigen::Success && levels.size() > 1) {
    // Non-nested hierarchies can give linearly dependent coarse basis functions (after the
    // Dirichlet rows are dropped), so P^T A P is only semidefinite. Its null vectors z have
    // P z = 0 (A is definite), so a small diagonal shift changes nothing that is
    // prolongated back, and the shifted operator factorises.
    ColMajor shifted = coarsest;
    for (Eigen::Index i = 0; i < shifted.rows(); ++i) {
      shifted.coeffRef(i, i) *= 1.0 + options.coarse_shift;
    }
    coarse_solver.compute(shifted);
    coarse_shifted = true;
  }
  if (coarse_solver.info() != Eigen::Success) {
    throw Error("multigrid: the coarsest operator could not be factorised");
  }
}

MultigridPreconditioner::MultigridPreconditioner(const SparseMatrix& a,
                                                 std::span<const int> fine_free_to_full,
                                                 std::span<const SparseMatrix> prolongations,
                                                 const MultigridOptions& options,
                                                 std::vector<MeshOperator> mesh_operators)
    : impl_(std::make_unique<Impl>()) {
  if (options.smoothing_sweeps < 1)
    throw Error("multigrid: at least one smoothing sweep is needed (got " +
                std::to_string(options.smoothing_sweeps) + ")");
  impl_->options = options;
  impl_->levels.emplace_back();
  if (a.isCompressed()) {
    impl_->fine = &a;
  } else {
    impl_->levels[0].owned = a;
    impl_->levels[0].owned.makeCompressed();
  }
  impl_->add_mesh_levels(fine_free_to_full, prolongations, mesh_operators);
  impl_->add_aggregation_levels();
  impl_->set_up_smoothers_and_coarsest_solve();
}

MultigridPreconditioner::~MultigridPreconditioner() = default;
MultigridPreconditioner::MultigridPreconditioner(MultigridPreconditioner&&) noexcept = default;
MultigridPreconditioner& MultigridPreconditioner::operator=(MultigridPreconditioner&&) noexcept =
    default;

void MultigridPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  impl_->vcycle(0, r, z);
}

void MultigridPreconditioner::apply_with_product(const Eigen::VectorXd& r, Eigen::VectorXd& z,
                                                 Eigen::VectorXd& az) const {
  impl_->vcycle(0, r, z, &az);
}

bool MultigridPreconditioner::coarsest_was_shifted() const { return impl_->coarse_shifted; }

const SparseMatrix& MultigridPreconditioner::level_operator(std::size_t l) const {
  return *impl_->levels.at(l).a;
}

const SparseMatrix& MultigridPreconditioner::level_prolongation(std::size_t l) const {
  if (l + 1 >= impl_->levels.size())
    throw Error("multigrid: the coarsest level has no prolongation");
  return impl_->levels[l].p;
}

std::size_t MultigridPreconditioner::mesh_levels() const { return impl_->mesh_levels; }

std::vector<long> MultigridPreconditioner::level_nonzeros() const {
  std::vector<long> nonzeros;
  for (const Level& level : impl_->levels)
    nonzeros.push_back(static_cast<long>(level.a->nonZeros()));
  return nonzeros;
}

std::vector<int> MultigridPreconditioner::level_sizes() const {
  std::vector<int> sizes;
  for (const Level& level : impl_->levels) sizes.push_back(static_cast<int>(level.a->rows()));
  return sizes;
}

}  // namespace molmesh::solvers
