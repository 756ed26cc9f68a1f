// build_hierarchy overlaps TetGen of level L with the surface processing of level L+1 and
// computes the transfers in parallel; the hierarchy must not depend on that (nor on the
// thread count).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <filesystem>

#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh {
namespace {

Hierarchy build(const SurfaceMesh& surface, const Atoms& atoms) {
  HierarchyOptions options;
  options.t0 = {0.1, 0.3, 0.5};
  options.tetmesh.domain = Domain::interior;
  return build_hierarchy(surface, atoms, options);
}

bool same_matrix(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  const SparseMatrix d = a - b;
  for (Eigen::Index k = 0; k < d.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(d, k); it; ++it)
      if (it.value() != 0.0) return false;
  return true;
}

TEST(BuildHierarchy, SameHierarchyForOneAndTwoThreads) {
  const Atoms atoms = read_atoms(std::filesystem::path(MOLMESH_TEST_DATA_DIR) / "1a1p.pqr");
  SurfacePipelineOptions raw;
  raw.raw = true;
  raw.measure = false;
  const SurfaceMesh surface = surface_from_atoms(atoms, raw).surface;

  Hierarchy one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = build(surface, atoms);
  }
  const Hierarchy two = build(surface, atoms);
  ASSERT_EQ(one.levels.size(), 3u);
  ASSERT_EQ(two.levels.size(), one.levels.size());
  for (std::size_t l = 0; l < one.levels.size(); ++l) {
    SCOPED_TRACE("level " + std::to_string(l));
    EXPECT_EQ(one.levels[l].surface.points, two.levels[l].surface.points);
    EXPECT_EQ(one.levels[l].surface.triangles, two.levels[l].surface.triangles);
    EXPECT_EQ(one.levels[l].surface_provenance, two.levels[l].surface_provenance);
    EXPECT_EQ(one.levels[l].volume.points, two.levels[l].volume.points);
    EXPECT_EQ(one.levels[l].volume.tetrahedra, two.levels[l].volume.tetrahedra);
    EXPECT_EQ(one.levels[l].volume_permutation, two.levels[l].volume_permutation);
  }
  // Coarser levels really are coarser, so the comparison covers three different meshes.
  EXPECT_LT(one.levels[2].surface.points.size(), one.levels[0].surface.points.size());
  ASSERT_EQ(one.transfers.size(), 2u);
  ASSERT_EQ(two.transfers.size(), 2u);
  for (std::size_t t = 0; t < one.transfers.size(); ++t) {
    SCOPED_TRACE("transfer " + std::to_string(t));
    EXPECT_EQ(one.transfers[t].fine_level, static_cast<int>(t));
    EXPECT_EQ(two.transfers[t].coarse_level, static_cast<int>(t) + 1);
    EXPECT_TRUE(same_matrix(one.transfers[t].volume, two.transfers[t].volume));
    EXPECT_TRUE(same_matrix(one.transfers[t].surface, two.transfers[t].surface));
  }
}

}  // namespace
}  // namespace molmesh
