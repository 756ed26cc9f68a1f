// Transfer operators on synthetic meshes with known geometry: rows sum to 1, linear
// functions are reproduced, every coarse vertex is reached, and results do not depend on
// the thread count.
#include "molmesh/hierarchy/transfer.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "molmesh/hierarchy/renumber.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh {
namespace {

double linear(const Vec3& p) { return 1.5 + 2.0 * p.x() - 3.0 * p.y() + 0.5 * p.z(); }

void expect_rows_sum_to_one(const SparseMatrix& p) {
  for (Eigen::Index r = 0; r < p.rows(); ++r) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(p, r); it; ++it) sum += it.value();
    ASSERT_NEAR(sum, 1.0, 1e-12) << "row " << r;
  }
}

void expect_no_empty_column(const SparseMatrix& p) {
  Eigen::VectorXi count = Eigen::VectorXi::Zero(p.cols());
  for (Eigen::Index r = 0; r < p.rows(); ++r) {
    for (SparseMatrix::InnerIterator it(p, r); it; ++it) {
      if (it.value() != 0.0) ++count[it.col()];
    }
  }
  for (Eigen::Index c = 0; c < p.cols(); ++c) ASSERT_GT(count[c], 0) << "column " << c;
}

Eigen::VectorXd sample(const std::vector<Vec3>& points) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    v[static_cast<Eigen::Index>(i)] = linear(points[i]);
  return v;
}

TEST(StructuredMeshes, CubeIsPositivelyOrientedAndClosed) {
  const auto cube = testing::structured_cube(3);
  EXPECT_EQ(cube.points.size(), 64u);
  EXPECT_EQ(cube.tetrahedra.size(), 6u * 27u);
  double volume = 0.0;
  for (const auto& t : cube.tetrahedra) {
    const Vec3& a = cube.points[static_cast<std::size_t>(t[0])];
    const double v = (cube.points[static_cast<std::size_t>(t[1])] - a)
                         .cross(cube.points[static_cast<std::size_t>(t[2])] - a)
                         .dot(cube.points[static_cast<std::size_t>(t[3])] - a) /
                     6.0;
    ASSERT_GT(v, 0.0);
    volume += v;
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  EXPECT_EQ(cube.boundary_faces.size(), 6u * 2u * 9u);
  EXPECT_EQ(tet_mesh_boundary(cube).size(), cube.boundary_faces.size());
}

TEST(VolumeProlongation, NestedCubesReproduceLinearFunctionsEverywhere) {
  const auto coarse = testing::structured_cube(3);
  const auto fine = testing::structured_cube(7);
  TransferStats stats;
  const auto p = volume_prolongation(coarse, fine, &stats);
  ASSERT_EQ(p.rows(), static_cast<Eigen::Index>(fine.points.size()));
  ASSERT_EQ(p.cols(), static_cast<Eigen::Index>(coarse.points.size()));
  EXPECT_EQ(stats.fine_outside, 0);
  expect_rows_sum_to_one(p);
  expect_no_empty_column(p);
  const Eigen::VectorXd interpolated = p * sample(coarse.points);
  const Eigen::VectorXd exact = sample(fine.points);
  for (Eigen::Index i = 0; i < exact.size(); ++i) {
    ASSERT_NEAR(interpolated[i], exact[i], 1e-9 * std::max(1.0, std::abs(exact[i])));
  }
  // Coinciding vertices (corners of the coarse grid are fine vertices) map by identity.
  EXPECT_NEAR(p.coeff(0, 0), 1.0, 1e-12);
}

TEST(VolumeProlongation, FineVerticesOutsideGoToTheClosestBoundaryPoint) {
  const auto coarse = testing::structured_cube(2, 0.0, 1.0);
  const auto fine = testing::structured_cube(4, -0.25, 1.25);
  TransferStats stats;
  const auto p = volume_prolongation(coarse, fine, &stats);
  expect_rows_sum_to_one(p);
  expect_no_empty_column(p);
  EXPECT_GT(stats.fine_outside, 0);
  // The value at an outside vertex is the coarse interpolant at its clamped position.
  const Eigen::VectorXd coarse_values = sample(coarse.points);
  const Eigen::VectorXd fine_values = p * coarse_values;
  for (std::size_t i = 0; i < fine.points.size(); ++i) {
    const Vec3 clamped = fine.points[i].cwiseMax(Vec3::Zero()).cwiseMin(Vec3::Ones());
    ASSERT_NEAR(fine_values[static_cast<Eigen::Index>(i)], linear(clamped), 1e-9) << i;
  }
}

TEST(VolumeProlongation, CoarseVertexWithoutFineNeighboursGetsAColumnAndKeepsExactness) {
  // A fine mesh much coarser than the "coarse" one: most coarse vertices are in no fine
  // vertex's tetrahedron, so the repair must give them columns without losing exactness.
  const auto coarse = testing::structured_cube(6);
  const auto fine = testing::structured_cube(2);
  TransferStats stats;
  const auto p = volume_prolongation(coarse, fine, &stats);
  EXPECT_GT(stats.empty_columns_repaired, 0);
  expect_rows_sum_to_one(p);
  expect_no_empty_column(p);
  const Eigen::VectorXd interpolated = p * sample(coarse.points);
  const Eigen::VectorXd exact = sample(fine.points);
  for (Eigen::Index i = 0; i < exact.size(); ++i) ASSERT_NEAR(interpolated[i], exact[i], 1e-9);
}

TEST(VolumeProlongation, IndependentOfThreadCount) {
  const auto coarse = testing::structured_cube(4, 0.05, 0.95);
  const auto fine = testing::structured_cube(9);
  SparseMatrix one_thread;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one_thread = volume_prolongation(coarse, fine);
  }
  const auto parallel = volume_prolongation(coarse, fine);
  ASSERT_EQ(one_thread.nonZeros(), parallel.nonZeros());
  EXPECT_EQ((SparseMatrix(one_thread - parallel)).norm(), 0.0);
}

TEST(SurfaceProlongation, ProvenanceIsIdentityAndRowsSumToOne) {
  const auto coarse = testing::structured_cube_surface(2);
  const auto fine = testing::structured_cube_surface(4);
  // Every coarse surface vertex is also a fine one (grid refinement by 2).
  std::vector<int> provenance(coarse.points.size(), -1);
  for (std::size_t c = 0; c < coarse.points.size(); ++c) {
    for (std::size_t f = 0; f < fine.points.size(); ++f) {
      if ((fine.points[f] - coarse.points[c]).norm() < 1e-12) provenance[c] = static_cast<int>(f);
    }
    ASSERT_GE(provenance[c], 0);
  }
  const auto p = surface_prolongation(coarse, fine, provenance);
  expect_rows_sum_to_one(p);
  expect_no_empty_column(p);
  for (std::size_t c = 0; c < coarse.points.size(); ++c) {
    EXPECT_EQ(p.coeff(provenance[c], static_cast<Eigen::Index>(c)), 1.0);
  }
  // The cube faces are planar, so linear functions are reproduced on the surface too.
  const Eigen::VectorXd interpolated = p * sample(coarse.points);
  const Eigen::VectorXd exact = sample(fine.points);
  for (Eigen::Index i = 0; i < exact.size(); ++i) ASSERT_NEAR(interpolated[i], exact[i], 1e-9);
}

TEST(Renumber, ReverseCuthillMcKeeIsAPermutationThatShrinksBandwidth) {
  auto cube = testing::structured_cube(8);
  // Scramble the numbering first so there is something to recover.
  std::vector<int> scramble(cube.points.size());
  for (std::size_t i = 0; i < scramble.size(); ++i) {
    scramble[i] = static_cast<int>((i * 7919) % scramble.size());
  }
  const auto scrambled = permute_vertices(cube, scramble);
  const auto rcm = reverse_cuthill_mckee(scrambled);
  const auto ordered = permute_vertices(scrambled, rcm);
  EXPECT_LT(vertex_bandwidth(ordered), vertex_bandwidth(scrambled) / 4);
  for (std::size_t i = 0; i < ordered.points.size(); ++i) {
    ASSERT_EQ(ordered.points[i], scrambled.points[static_cast<std::size_t>(rcm[i])]);
  }
  for (const auto& t : ordered.tetrahedra) {
    const Vec3& a = ordered.points[static_cast<std::size_t>(t[0])];
    ASSERT_GT((ordered.points[static_cast<std::size_t>(t[1])] - a)
                  .cross(ordered.points[static_cast<std::size_t>(t[2])] - a)
                  .dot(ordered.points[static_cast<std::size_t>(t[3])] - a),
              0.0);
  }
}

TEST(Renumber, CellsSortedByLowestVertexKeepTheirMarkers) {
  auto cube = testing::structured_cube(4);
  cube.cell_markers.resize(cube.tetrahedra.size());
  for (std::size_t t = 0; t < cube.tetrahedra.size(); ++t)
    cube.cell_markers[t] = static_cast<int>(t % 5);
  std::reverse(cube.tetrahedra.begin(), cube.tetrahedra.end());
  std::reverse(cube.cell_markers.begin(), cube.cell_markers.end());
  const TetMesh sorted = sort_cells_by_vertex(cube);
  ASSERT_EQ(sorted.tetrahedra.size(), cube.tetrahedra.size());
  ASSERT_EQ(sorted.cell_markers.size(), cube.cell_markers.size());
  auto lowest = [](const Tetrahedron& t) { return *std::min_element(t.begin(), t.end()); };
  // (cell, marker) pairs are the same multiset, now in order of their lowest vertex.
  std::vector<std::pair<Tetrahedron, int>> before, after;
  for (std::size_t t = 0; t < cube.tetrahedra.size(); ++t) {
    before.emplace_back(cube.tetrahedra[t], cube.cell_markers[t]);
    after.emplace_back(sorted.tetrahedra[t], sorted.cell_markers[t]);
    if (t > 0) {
      EXPECT_LE(lowest(sorted.tetrahedra[t - 1]), lowest(sorted.tetrahedra[t]));
    }
  }
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  EXPECT_EQ(before, after);
  EXPECT_EQ(sorted.points, cube.points);
  EXPECT_EQ(sorted.boundary_faces, cube.boundary_faces);
}

}  // namespace
}  // namespace molmesh
