// The van der Waals surface of the small test molecules (1a1p, fas2) meshes end to end
// (issue 12): TetGen meshes the interior, exterior and full domains, and the four-level
// hierarchy (whose coarse levels folded on fas2's nearly flat patches where spheres meet,
// processing/untangle.hpp) is written. Each run exits 0, never by a signal.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

class VdwSurface : public ::testing::TestWithParam<const char*> {};

std::string molecule_path(const char* name) {
  return testing::shell_quoted((fs::path(MOLMESH_TEST_DATA_DIR) / name).string());
}

TEST_P(VdwSurface, TetGenMeshesEveryDomain) {
  const fs::path dir = testing::test_dir(std::string("vdw_tetmesh_") + GetParam());
  for (const char* domain : {"interior", "exterior", "full"}) {
    const fs::path out = dir / (std::string(domain) + ".vtu");
    const testing::CliRun run =
        testing::run_cli("-q tetmesh " + molecule_path(GetParam()) + " --surface vdw --domain " +
                         domain + " -o " + testing::shell_quoted(out.string()));
    EXPECT_EQ(run.signal, 0) << domain;
    EXPECT_EQ(run.exit_code, 0) << domain << "\n" << run.err;
    EXPECT_TRUE(fs::exists(out)) << domain;
  }
}

TEST_P(VdwSurface, FourLevelHierarchyOfTheFullDomain) {
  const fs::path dir = testing::test_dir(std::string("vdw_hierarchy_") + GetParam());
  const fs::path h5 = dir / "vdw.h5";
  const testing::CliRun run =
      testing::run_cli("-q hierarchy " + molecule_path(GetParam()) +
                       " --surface vdw --domain full -o " + testing::shell_quoted(h5.string()));
  ASSERT_EQ(run.signal, 0);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Hierarchy h = read_hierarchy(h5);
  ASSERT_EQ(h.levels.size(), 4u);
  for (const auto& level : h.levels) {
    EXPECT_GT(level.volume.points.size(), level.surface.points.size());
    EXPECT_EQ(compute_tet_stats(level.volume).inverted_or_flat, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(SmallMolecules, VdwSurface, ::testing::Values("1a1p.pqr", "fas2.pqr"),
                         [](const auto& param_info) {
                           std::string n = param_info.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace molmesh
