// `molmesh export` on a real hierarchy: FETK's own MC reader reads every exported level
// with the HDF5 level's counts, positive orientation, materials and face types.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "fetk/fetk_reader.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

TEST(FetkReader, ReadsEveryExportedLevel) {
  const fs::path dir = testing::test_dir();
  testing::write_file(dir / "ion.pqr",
                      "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00\n");
  const fs::path h5 = dir / "ion.h5";
  const testing::CliRun hierarchy =
      testing::run_cli("-q hierarchy " + (dir / "ion.pqr").string() + " -o " + h5.string() +
                       " --domain full --outer-radius 20");
  ASSERT_EQ(hierarchy.exit_code, 0) << hierarchy.output();
  const testing::CliRun exported =
      testing::run_cli("-q export " + h5.string() + " --all-levels -o " + (dir / "ion").string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output();
  const Hierarchy h = read_hierarchy(h5);
  ASSERT_GE(h.levels.size(), 2u);
  for (std::size_t l = 0; l < h.levels.size(); ++l) {
    const TetMesh& mesh = h.levels[l].volume;
    const fs::path m = dir / ("ion_L" + std::to_string(l) + "_volume.m");
    const FetkMesh fetk = read_with_fetk(m);
    SCOPED_TRACE(m.string());
    EXPECT_TRUE(fetk.read_ok);
    EXPECT_EQ(fetk.vertices, static_cast<int>(mesh.points.size()));
    EXPECT_EQ(fetk.simplices, static_cast<int>(mesh.tetrahedra.size()));
    EXPECT_EQ(fetk.negative, 0);
    std::map<int, int> regions;
    for (int c : mesh.cell_markers) ++regions[c];
    EXPECT_EQ(fetk.materials, regions);
    // A full mesh: only the outer sphere is boundary, Dirichlet type 5.
    int outer = 0;
    for (int marker : mesh.boundary_face_markers) outer += marker == markers::kOuterSphere;
    ASSERT_EQ(fetk.boundary_face_types.size(), 1u);
    EXPECT_EQ(fetk.boundary_face_types.at(5), outer);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
