// Results never depend on the thread count (issue 18 floor): the processed surface, the
// tetrahedral mesh and every dataset of a hierarchy file are identical with 1 and 2 threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <filesystem>
#include <string>

#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

struct Outputs {
  SurfaceMesh surface;
  TetMesh volume;
  Hierarchy hierarchy;
};

Outputs run_with(int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr");
  Outputs r;
  r.surface = surface_from_atoms(atoms, {}).surface;
  r.volume = tetrahedralize(r.surface, atoms, {});
  SurfacePipelineOptions raw;
  raw.raw = true;
  HierarchyOptions options;
  options.t0 = {0.2, 0.4};
  r.hierarchy = build_hierarchy(surface_from_atoms(atoms, raw).surface, atoms, options);
  return r;
}

TEST(ThreadIndependence, SurfaceTetmeshAndHierarchyAreIdenticalWithOneAndTwoThreads) {
  const Outputs one = run_with(1);
  const Outputs two = run_with(2);
  EXPECT_EQ(one.surface.points, two.surface.points);
  EXPECT_EQ(one.surface.triangles, two.surface.triangles);
  EXPECT_EQ(one.volume.points, two.volume.points);
  EXPECT_EQ(one.volume.tetrahedra, two.volume.tetrahedra);
  EXPECT_EQ(one.volume.cell_markers, two.volume.cell_markers);
  EXPECT_EQ(one.volume.boundary_faces, two.volume.boundary_faces);
  // Level by level first, so a failure says where the two runs part.
  ASSERT_EQ(one.hierarchy.levels.size(), two.hierarchy.levels.size());
  for (std::size_t L = 0; L < one.hierarchy.levels.size(); ++L) {
    const HierarchyLevel& a = one.hierarchy.levels[L];
    const HierarchyLevel& b = two.hierarchy.levels[L];
    EXPECT_EQ(a.surface.points, b.surface.points) << "level " << L;
    EXPECT_EQ(a.surface.triangles, b.surface.triangles) << "level " << L;
    EXPECT_EQ(a.surface_provenance, b.surface_provenance) << "level " << L;
    EXPECT_EQ(a.volume.points, b.volume.points) << "level " << L;
    EXPECT_EQ(a.volume.tetrahedra, b.volume.tetrahedra) << "level " << L;
    EXPECT_EQ(a.volume_permutation, b.volume_permutation) << "level " << L;
  }
  for (std::size_t i = 0; i < one.hierarchy.transfers.size(); ++i) {
    const LevelTransfer& a = one.hierarchy.transfers[i];
    const LevelTransfer& b = two.hierarchy.transfers[i];
    EXPECT_TRUE(a.volume.isApprox(b.volume, 0.0) && a.volume.nonZeros() == b.volume.nonZeros())
        << "volume transfer " << i;
    EXPECT_TRUE(a.surface.isApprox(b.surface, 0.0) && a.surface.nonZeros() == b.surface.nonZeros())
        << "surface transfer " << i;
  }
  // Every HDF5 dataset: byte-identical files (the writer stores no object times, so this
  // holds across a clock-second boundary too).
  const auto dir = testing::test_dir();
  write_hierarchy(dir / "one.h5", one.hierarchy);
  write_hierarchy(dir / "two.h5", two.hierarchy);
  EXPECT_EQ(testing::slurp(dir / "one.h5"), testing::slurp(dir / "two.h5"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
