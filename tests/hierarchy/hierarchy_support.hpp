#pragma once
// Checks shared by the real-molecule hierarchy tests (fast and slow).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/hierarchy/renumber.hpp"
#include "molmesh/hierarchy/transfer.hpp"
#include "support/files.hpp"
#include "support/process.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh::testing {

// Two levels of a structured cube [-2, 2]^3 (n_fine and n_coarse cells per edge), renumbered,
// with surface provenance and both prolongations: a small valid hierarchy file's contents.
inline Hierarchy cube_hierarchy(int n_fine, int n_coarse) {
  Hierarchy h;
  for (int n : {n_fine, n_coarse}) {
    HierarchyLevel level;
    level.t0 = n == n_fine ? 0.1 : 0.3;
    TetMesh volume = structured_cube(n, -2.0, 2.0);
    level.volume_permutation = reverse_cuthill_mckee(volume);
    level.volume = permute_vertices(volume, level.volume_permutation);
    level.surface = structured_cube_surface(n, -2.0, 2.0);
    h.levels.push_back(std::move(level));
  }
  // Coarse surface vertices coincide with fine ones.
  auto& coarse = h.levels[1];
  const auto& fine = h.levels[0];
  for (const auto& p : coarse.surface.points) {
    int match = -1;
    for (std::size_t f = 0; f < fine.surface.points.size(); ++f)
      if ((fine.surface.points[f] - p).norm() < 1e-12) match = static_cast<int>(f);
    coarse.surface_provenance.push_back(match);
  }
  LevelTransfer t;
  t.coarse_level = 1;
  t.fine_level = 0;
  t.volume = volume_prolongation(coarse.volume, fine.volume);
  t.surface = surface_prolongation(coarse.surface, fine.surface, coarse.surface_provenance);
  h.transfers.push_back(std::move(t));
  return h;
}

inline Eigen::MatrixXd coordinates(const std::vector<Vec3>& points) {
  Eigen::MatrixXd x(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    x.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  return x;
}

// A prolongation from `coarse_size` to `fine_size` vertices is a partition of unity: every
// row sums to 1 (stops at the first row that does not, so one defect is one failure) and
// every coarse vertex reaches some fine vertex (no empty column).
inline void check_partition_of_unity(const SparseMatrix& p, std::size_t coarse_size,
                                     std::size_t fine_size) {
  EXPECT_EQ(p.rows(), static_cast<Eigen::Index>(fine_size));
  EXPECT_EQ(p.cols(), static_cast<Eigen::Index>(coarse_size));
  Eigen::VectorXi column_count = Eigen::VectorXi::Zero(p.cols());
  for (Eigen::Index r = 0; r < p.rows(); ++r) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(p, r); it; ++it) {
      sum += it.value();
      if (it.value() != 0.0) ++column_count[it.col()];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << "row " << r;
    if (std::abs(sum - 1.0) > 1e-12) break;
  }
  EXPECT_EQ((column_count.array() == 0).count(), 0) << "coarse vertices with empty columns";
}

// Row sums, non-empty columns, and linear reproduction: P applied to the coarse coordinates
// gives the fine coordinates exactly except at fine vertices outside the coarse mesh,
// which must be few and close to the coarse boundary they are projected onto (the levels'
// molecular surfaces differ by less than `max_projection` Å). Returns the number of fine
// vertices not reproduced.
inline long check_volume_transfer(const SparseMatrix& p, const TetMesh& coarse, const TetMesh& fine,
                                  double max_outside_fraction, double max_projection = 3.0) {
  check_partition_of_unity(p, coarse.points.size(), fine.points.size());
  const Eigen::MatrixXd xf = coordinates(fine.points);
  const Eigen::MatrixXd interpolated = p * coordinates(coarse.points);
  // An arbitrary linear function, too.
  const Eigen::Vector3d a(0.3, -1.7, 2.2);
  const double scale = xf.cwiseAbs().maxCoeff() + 1.0;
  long outside = 0;
  for (Eigen::Index i = 0; i < xf.rows(); ++i) {
    const double position_error = (interpolated.row(i) - xf.row(i)).norm();
    if (position_error > 1e-9 * scale) {
      ++outside;
      EXPECT_LE(position_error, max_projection) << "fine vertex " << i;
      continue;
    }
    // Inside: the linear function a.x + 4 is reproduced to 1e-9 relative. A position error
    // just under 1e-9 * scale moves a.x by up to |a| times that, hence |a| * scale.
    const double exact = xf.row(i).dot(a) + 4.0;
    const double got = interpolated.row(i).dot(a) + 4.0;
    EXPECT_NEAR(got, exact, 1e-9 * (a.norm() * scale + std::max(1.0, std::abs(exact))));
  }
  EXPECT_LE(static_cast<double>(outside), max_outside_fraction * static_cast<double>(xf.rows()))
      << "fine vertices outside the coarse mesh";
  return outside;
}

inline void check_surface_transfer(const SparseMatrix& p, const HierarchyLevel& coarse,
                                   const HierarchyLevel& fine) {
  check_partition_of_unity(p, coarse.surface.points.size(), fine.surface.points.size());
  // Provenance: coarse vertex c comes from fine vertex provenance[c] and maps by identity.
  ASSERT_EQ(coarse.surface_provenance.size(), coarse.surface.points.size());
  for (std::size_t c = 0; c < coarse.surface_provenance.size(); ++c) {
    const int f = coarse.surface_provenance[c];
    ASSERT_GE(f, 0);
    ASSERT_LT(static_cast<std::size_t>(f), fine.surface.points.size());
    EXPECT_EQ(p.coeff(f, static_cast<Eigen::Index>(c)), 1.0);
  }
}

// Runs the independent python reader on `h5`; returns its output, expects exit status 0.
inline std::string run_python_checker(const std::filesystem::path& h5) {
  const auto checker = std::filesystem::path(__FILE__).parent_path() / "check_hierarchy.py";
  const CommandRun run = run_command("/usr/bin/python3 " + shell_quoted(checker.string()) + " " +
                                     shell_quoted(h5.string()));
  EXPECT_EQ(run.exit_code, 0) << run.output();
  return run.output();
}

// Opens `file` with h5py (created if missing), runs the python `statements` on it as `f`
// (numpy as `np`), closes it; expects exit status 0. Damages files the way another program
// could.
inline void edit_with_h5py(const std::filesystem::path& file, const std::string& statements) {
  const CommandRun run =
      run_command("/usr/bin/python3 -c \"import h5py, numpy as np; f = h5py.File('" +
                  file.string() + "', 'a'); " + statements + "; f.close()\"");
  EXPECT_EQ(run.exit_code, 0) << statements << "\n" << run.output();
}

}  // namespace molmesh::testing
