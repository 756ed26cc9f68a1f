#include "solvers/petsc/petsc_engine.hpp"

#include <petscksp.h>

#include <chrono>
#include <deque>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"

namespace molmesh::solvers {
namespace {

// PETSc calls return an error code; turn any failure into a molmesh::Error naming it.
void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw Error(std::string("PETSc: ") + what + " failed: " + (text ? text : "unknown error"));
}

// Destroys PETSc objects when the solve leaves (also on exceptions). Not copyable: a
// copy would destroy the object twice.
struct MatHolder {
  Mat m = nullptr;
  MatHolder() = default;
  MatHolder(const MatHolder&) = delete;
  MatHolder& operator=(const MatHolder&) = delete;
  ~MatHolder() {
    if (m) MatDestroy(&m);
  }
};
struct VecHolder {
  Vec v = nullptr;
  VecHolder() = default;
  VecHolder(const VecHolder&) = delete;
  VecHolder& operator=(const VecHolder&) = delete;
  ~VecHolder() {
    if (v) VecDestroy(&v);
  }
};
struct KspHolder {
  KSP k = nullptr;
  KspHolder() = default;
  KspHolder(const KspHolder&) = delete;
  KspHolder& operator=(const KspHolder&) = delete;
  ~KspHolder() {
    if (k) KSPDestroy(&k);
  }
};

struct Layout {
  PetscInt local = 0, global = 0, first = 0;
};

Layout split(Eigen::Index global) {
  Layout l;
  l.global = static_cast<PetscInt>(global);
  l.local = PETSC_DECIDE;
  check(PetscSplitOwnership(PETSC_COMM_WORLD, &l.local, &l.global), "PetscSplitOwnership");
  check(MPI_Scan(&l.local, &l.first, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS
            ? 0
            : PETSC_ERR_LIB,
        "MPI_Scan");
  l.first -= l.local;
  return l;
}

// The rows of `m` this rank owns (rows.first .. +rows.local) as a distributed AIJ matrix,
// columns laid out as `cols` (local column size = the owned part of the column space).
Mat distributed(const SparseMatrix& m, const Layout& rows, const Layout& cols) {
  // Where PetscInt is int and PetscScalar double (Debian's petsc-dev), the column and value
  // arrays of the owned rows are handed to PETSc as they are, which copies them once; only
  // the row starts are shifted to begin at zero. Gathering them first into growing vectors
  // took half of PCMG's setup on mAChE (fresh pages; docs/benchmarks.md, session 24).
  constexpr bool kSameTypes = std::is_same_v<PetscInt, int> && std::is_same_v<PetscScalar, double>;
  std::vector<PetscInt> indptr(static_cast<std::size_t>(rows.local) + 1, 0);
  std::vector<PetscInt> index_copy;
  std::vector<PetscScalar> value_copy;
  const PetscInt* indices = nullptr;
  const PetscScalar* values = nullptr;
  if (kSameTypes && m.isCompressed()) {
    const int* outer = m.outerIndexPtr();
    const int begin = outer[rows.first];
    for (PetscInt r = 0; r <= rows.local; ++r)
      indptr[static_cast<std::size_t>(r)] = static_cast<PetscInt>(outer[rows.first + r] - begin);
    indices = reinterpret_cast<const PetscInt*>(m.innerIndexPtr() + begin);
    values = reinterpret_cast<const PetscScalar*>(m.valuePtr() + begin);
  } else {
    for (PetscInt r = 0; r < rows.local; ++r) {
      for (SparseMatrix::InnerIterator it(m, rows.first + r); it; ++it) {
        index_copy.push_back(static_cast<PetscInt>(it.col()));
        value_copy.push_back(it.value());
      }
      indptr[static_cast<std::size_t>(r) + 1] = static_cast<PetscInt>(index_copy.size());
    }
    indices = index_copy.data();
    values = value_copy.data();
  }
  Mat a = nullptr;
  check(MatCreate(PETSC_COMM_WORLD, &a), "MatCreate");
  check(MatSetSizes(a, rows.local, cols.local, rows.global, cols.global), "MatSetSizes");
  check(MatSetType(a, MATAIJ), "MatSetType");
  // Exact preallocation and values in one call (sequential or MPI, whichever `a` is).
  check(MatSeqAIJSetPreallocationCSR(a, indptr.data(), indices, values),
        "MatSeqAIJSetPreallocationCSR");
  check(MatMPIAIJSetPreallocationCSR(a, indptr.data(), indices, values),
        "MatMPIAIJSetPreallocationCSR");
  return a;
}

SolveReport solve(const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                  const LinearSolverOptions& options, Eigen::VectorXd& x,
                  std::vector<MeshOperator> mesh_operators, const PetscEngineOptions& engine) {
  const auto setup_start = std::chrono::steady_clock::now();
  const Eigen::Index n = system.matrix.rows();
  const Layout fine = split(n);
  MatHolder a;
  a.m = distributed(system.matrix, fine, fine);
  check(MatSetOption(a.m, MAT_SPD, PETSC_TRUE), "MatSetOption");
  VecHolder b, solution;
  check(MatCreateVecs(a.m, &solution.v, &b.v), "MatCreateVecs");
  for (PetscInt r = 0; r < fine.local; ++r)
    check(VecSetValue(b.v, fine.first + r, system.rhs[fine.first + r], INSERT_VALUES),
          "VecSetValue");
  check(VecAssemblyBegin(b.v), "VecAssemblyBegin");
  check(VecAssemblyEnd(b.v), "VecAssemblyEnd");

  KspHolder ksp;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp.k), "KSPCreate");
  if (!engine.options_prefix.empty())
    check(KSPSetOptionsPrefix(ksp.k, engine.options_prefix.c_str()), "KSPSetOptionsPrefix");
  check(KSPSetOperators(ksp.k, a.m, a.m), "KSPSetOperators");
  check(KSPSetType(ksp.k, KSPCG), "KSPSetType");
  // The built-in solver's criterion: ||b - A x|| / ||b|| from x = 0.
  check(KSPSetNormType(ksp.k, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(
      KSPSetTolerances(ksp.k, options.cg.tolerance, 0.0, PETSC_DEFAULT, options.cg.max_iterations),
      "KSPSetTolerances");
  PC pc = nullptr;
  check(KSPGetPC(ksp.k, &pc), "KSPGetPC");

  SolveReport report;
  // PCMG takes its own references; ours go when the solve leaves. A deque never moves its
  // elements.
  std::deque<MatHolder> level_matrices;
  switch (engine.preconditioner) {
    case PetscPreconditioner::kMolmeshMultigrid: {
      // The built-in setup picks the levels (skipping, Dirichlet columns, aggregation
      // below the coarsest mesh); PCMG gets exactly those operators and prolongations.
      const MultigridPreconditioner mg(system.matrix, system.free_to_full, prolongations,
                                       options.multigrid, std::move(mesh_operators));
      report.level_sizes = mg.level_sizes();
      report.level_nonzeros = mg.level_nonzeros();
      report.mesh_levels = static_cast<int>(mg.mesh_levels());
      const auto levels = static_cast<PetscInt>(report.level_sizes.size());
      std::vector<Layout> layouts{fine};
      for (PetscInt l = 1; l < levels; ++l)
        layouts.push_back(split(mg.level_operator(static_cast<std::size_t>(l)).rows()));
      check(PCSetType(pc, PCMG), "PCSetType");
      check(PCMGSetLevels(pc, levels, nullptr), "PCMGSetLevels");
      check(PCMGSetType(pc, PC_MG_MULTIPLICATIVE), "PCMGSetType");
      check(PCMGSetGalerkin(pc, PC_MG_GALERKIN_NONE), "PCMGSetGalerkin");
      // PCMG numbers levels coarsest = 0; molmesh's level 0 is the finest.
      for (PetscInt l = 0; l < levels; ++l) {
        const auto ours = static_cast<std::size_t>(levels - 1 - l);
        KSP smoother = nullptr;
        check(PCMGGetSmoother(pc, l, &smoother), "PCMGGetSmoother");
        if (l > 0) {
          // The built-in smoother: symmetric Gauss-Seidel (SOR with omega 1; local to each
          // rank's rows in parallel), options.multigrid.smoothing_sweeps sweeps each way.
          PC smoother_pc = nullptr;
          check(KSPSetType(smoother, KSPRICHARDSON), "KSPSetType");
          check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT,
                                 options.multigrid.smoothing_sweeps),
                "KSPSetTolerances");
          check(KSPGetPC(smoother, &smoother_pc), "KSPGetPC");
          check(PCSetType(smoother_pc, PCSOR), "PCSetType");
        }
        if (ours == 0) {
          check(KSPSetOperators(smoother, a.m, a.m), "KSPSetOperators");
        } else {
          level_matrices.emplace_back();
          level_matrices.back().m =
              distributed(mg.level_operator(ours), layouts[ours], layouts[ours]);
          check(KSPSetOperators(smoother, level_matrices.back().m, level_matrices.back().m),
                "KSPSetOperators");
        }
        if (l > 0) {
          level_matrices.emplace_back();
          level_matrices.back().m =
              distributed(mg.level_prolongation(ours), layouts[ours], layouts[ours + 1]);
          check(PCMGSetInterpolation(pc, l, level_matrices.back().m), "PCMGSetInterpolation");
        }
      }
      report.preconditioner = "PETSc PCMG on molmesh's levels (" +
                              std::to_string(report.mesh_levels) + " mesh + " +
                              std::to_string(levels - report.mesh_levels) + " aggregation)";
      break;
    }
    case PetscPreconditioner::kGamg:
      check(PCSetType(pc, PCGAMG), "PCSetType");
      report.preconditioner = "PETSc PCGAMG";
      break;
    case PetscPreconditioner::kBoomerAmg:
      check(PCSetType(pc, PCHYPRE), "PCSetType");
      check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
      report.preconditioner = "hypre BoomerAMG (through PETSc)";
      break;
    case PetscPreconditioner::kIcc: {
      PetscMPIInt size = 1;
      MPI_Comm_size(PETSC_COMM_WORLD, &size);
      if (size == 1) {
        check(PCSetType(pc, PCICC), "PCSetType");
      } else {
        check(PCSetType(pc, PCBJACOBI), "PCSetType");
        check(PetscOptionsSetValue(nullptr, ("-" + engine.options_prefix + "sub_pc_type").c_str(),
                                   "icc"),
              "PetscOptionsSetValue");
      }
      report.preconditioner = size == 1 ? "PETSc ICC(0)" : "PETSc block Jacobi + ICC(0)";
      break;
    }
    case PetscPreconditioner::kOptions:
      report.preconditioner = "PETSc (from the options database)";
      break;
  }
  check(KSPSetFromOptions(ksp.k), "KSPSetFromOptions");
  check(KSPSetUp(ksp.k), "KSPSetUp");
  report.setup_time_s = seconds_since(setup_start);

  const auto solve_start = std::chrono::steady_clock::now();
  check(KSPSolve(ksp.k, b.v, solution.v), "KSPSolve");
  report.solve_time_s = seconds_since(solve_start);
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(ksp.k, &iterations), "KSPGetIterationNumber");
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(ksp.k, &reason), "KSPGetConvergedReason");
  report.iterations = static_cast<int>(iterations);
  {
    KSPType type = nullptr;
    PCType pc_type = nullptr;
    KSPGetType(ksp.k, &type);
    PCGetType(pc, &pc_type);
    report.preconditioner +=
        std::string(" [KSP ") + (type ? type : "?") + ", PC " + (pc_type ? pc_type : "?") + "]";
  }

  // Every rank gets the whole solution (the physics post-processing runs everywhere).
  VecScatter to_all = nullptr;
  VecHolder gathered;
  check(VecScatterCreateToAll(solution.v, &to_all, &gathered.v), "VecScatterCreateToAll");
  check(VecScatterBegin(to_all, solution.v, gathered.v, INSERT_VALUES, SCATTER_FORWARD),
        "VecScatterBegin");
  check(VecScatterEnd(to_all, solution.v, gathered.v, INSERT_VALUES, SCATTER_FORWARD),
        "VecScatterEnd");
  VecScatterDestroy(&to_all);
  const PetscScalar* values = nullptr;
  check(VecGetArrayRead(gathered.v, &values), "VecGetArrayRead");
  x = Eigen::Map<const Eigen::VectorXd>(values, n);
  check(VecRestoreArrayRead(gathered.v, &values), "VecRestoreArrayRead");

  // The true relative residual, as the built-in CG reports it.
  const double b_norm = system.rhs.norm();
  report.relative_residual = b_norm > 0.0 ? (system.rhs - system.matrix * x).norm() / b_norm : 0.0;
  report.converged = reason > 0 && report.relative_residual <= options.cg.tolerance * 1.0001;
  report.residual_history = {1.0};  // PETSc's monitors (-ksp_monitor) show the history
  return report;
}

}  // namespace

LinearEngine petsc_engine(const PetscEngineOptions& engine) {
  return [engine](const ReducedSystem& system, std::span<const SparseMatrix> prolongations,
                  const LinearSolverOptions& options, Eigen::VectorXd& x,
                  std::vector<MeshOperator> mesh_operators) {
    return solve(system, prolongations, options, x, std::move(mesh_operators), engine);
  };
}

PetscPreconditioner parse_petsc_preconditioner(const std::string& name) {
  if (name == "mg") return PetscPreconditioner::kMolmeshMultigrid;
  if (name == "gamg") return PetscPreconditioner::kGamg;
  if (name == "hypre") return PetscPreconditioner::kBoomerAmg;
  if (name == "icc") return PetscPreconditioner::kIcc;
  if (name == "options") return PetscPreconditioner::kOptions;
  throw Error("unknown PETSc preconditioner '" + name + "' (mg, gamg, hypre, icc, options)");
}

}  // namespace molmesh::solvers
