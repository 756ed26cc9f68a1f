// mAChE (8,279 atoms), four levels with the default T0 series, exterior domain: the
// floor requirements of the hierarchy (steadily falling level sizes, transfer invariants,
// a file an independent reader accepts).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "hierarchy/hierarchy_support.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

TEST(HierarchyMache, FourLevelsExterior) {
  const auto dir = testing::test_dir();
  const auto h5 = dir / "mache.h5";
  const testing::CliRun run =
      testing::run_cli("hierarchy " + (fs::path(MOLMESH_TEST_DATA_DIR) / "mache.pqr").string() +
                       " --domain exterior -o " + h5.string());
  const std::string log = run.out + run.err;
  ASSERT_EQ(run.exit_code, 0) << log;
  const Hierarchy h = read_hierarchy(h5);
  ASSERT_EQ(h.levels.size(), 4u);
  for (std::size_t l = 1; l < h.levels.size(); ++l) {
    const double ratio = static_cast<double>(h.levels[l - 1].volume.points.size()) /
                         static_cast<double>(h.levels[l].volume.points.size());
    EXPECT_GE(ratio, 1.3) << "level " << l - 1 << " -> " << l << "\n" << log;
    EXPECT_EQ(compute_tet_stats(h.levels[l].volume).inverted_or_flat, 0u);
  }
  for (const auto& t : h.transfers) {
    const auto& coarse = h.levels[static_cast<std::size_t>(t.coarse_level)];
    const auto& fine = h.levels[static_cast<std::size_t>(t.fine_level)];
    testing::check_volume_transfer(t.volume, coarse.volume, fine.volume, 0.35);
    testing::check_surface_transfer(t.surface, coarse, fine);
  }
  const auto text = testing::run_python_checker(h5);
  EXPECT_NE(text.find("OK levels 4"), std::string::npos) << text;
}

}  // namespace
}  // namespace molmesh
