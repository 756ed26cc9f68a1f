// The whole `molmesh hierarchy` command on a real molecule (fasciculin-2, exterior domain),
// checked through the library reader, the transfer invariants, an independent python
// reader and `molmesh info`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "hierarchy/hierarchy_support.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/sha256.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

class HierarchyCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = testing::test_dir();
    input_ = fs::path(MOLMESH_TEST_DATA_DIR) / "fas2.pqr";
    const testing::CliRun run =
        testing::run_cli("hierarchy " + input_.string() +
                         " --t0 0.1,0.3,0.5 --domain exterior --outer-radius 60 -q -o " +
                         (dir_ / "fas2.h5").string());
    status_ = run.exit_code;
    log_ = run.out + run.err;
  }
  static std::string log() { return log_; }
  static inline fs::path dir_;
  static inline fs::path input_;
  static inline int status_ = -1;
  static inline std::string log_;
};

TEST_F(HierarchyCli, WritesAConsistentHierarchy) {
  ASSERT_EQ(status_, 0) << log();
  const Hierarchy h = read_hierarchy(dir_ / "fas2.h5");
  ASSERT_EQ(h.levels.size(), 3u);
  ASSERT_EQ(h.transfers.size(), 2u);
  EXPECT_EQ(h.input_name, "fas2.pqr");
  EXPECT_EQ(h.input_checksum, sha256_file(input_));
  EXPECT_EQ(h.parameters.at("domain"), "exterior");
  EXPECT_EQ(h.parameters.at("outer_radius"), "60");
  const double t0[] = {0.1, 0.3, 0.5};
  for (std::size_t l = 0; l < h.levels.size(); ++l) {
    const auto& level = h.levels[l];
    EXPECT_EQ(level.t0, t0[l]);
    const auto stats = compute_tet_stats(level.volume);
    EXPECT_EQ(stats.inverted_or_flat, 0u) << "level " << l;
    EXPECT_GT(stats.min_dihedral_deg, 1.0) << "level " << l;
    // Exterior domain: solvent only, bounded by the molecular surface and the outer sphere.
    EXPECT_EQ(stats.tets_per_region.size(), 1u);
    EXPECT_TRUE(stats.tets_per_region.count(markers::kSolventRegion));
    EXPECT_TRUE(stats.faces_per_marker.count(markers::kOuterSphere));
    EXPECT_TRUE(stats.faces_per_marker.count(markers::kMolecularSurface));
    // Same outer sphere (radius 60 Å) on every level: outer-sphere face vertices lie at
    // 60 Å from their centroid.
    std::vector<Vec3> sphere;
    for (std::size_t f = 0; f < level.volume.boundary_faces.size(); ++f) {
      if (level.volume.boundary_face_markers[f] != markers::kOuterSphere) continue;
      for (int v : level.volume.boundary_faces[f])
        sphere.push_back(level.volume.points[static_cast<std::size_t>(v)]);
    }
    ASSERT_FALSE(sphere.empty());
    Vec3 centre = Vec3::Zero();
    for (const auto& p : sphere) centre += p;
    centre /= static_cast<double>(sphere.size());
    for (const auto& p : sphere) ASSERT_NEAR((p - centre).norm(), 60.0, 0.6) << "level " << l;
    // Renumbering kept, and it is a permutation.
    ASSERT_EQ(level.volume_permutation.size(), level.volume.points.size());
    if (l > 0) {
      // Coarser levels are strictly smaller.
      EXPECT_LT(level.surface.points.size(), h.levels[l - 1].surface.points.size());
      EXPECT_LT(level.volume.points.size(), h.levels[l - 1].volume.points.size());
    }
  }
  for (const auto& t : h.transfers) {
    const auto& coarse = h.levels[static_cast<std::size_t>(t.coarse_level)];
    const auto& fine = h.levels[static_cast<std::size_t>(t.fine_level)];
    testing::check_volume_transfer(t.volume, coarse.volume, fine.volume, 0.35);
    testing::check_surface_transfer(t.surface, coarse, fine);
  }
}

TEST_F(HierarchyCli, IndependentReaderAgrees) {
  ASSERT_EQ(status_, 0) << log();
  const auto text = testing::run_python_checker(dir_ / "fas2.h5");
  EXPECT_NE(text.find("OK levels 3"), std::string::npos) << text;
}

TEST_F(HierarchyCli, SolverFieldsAreAddedAndInfoSummarises) {
  ASSERT_EQ(status_, 0) << log();
  const auto copy = dir_ / "fields.h5";
  fs::copy_file(dir_ / "fas2.h5", copy, fs::copy_options::overwrite_existing);
  const auto h = read_hierarchy(copy);
  std::vector<double> values(h.levels[2].volume.points.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = h.levels[2].volume.points[i].norm();
  write_point_field(copy, 2, "distance", values);
  EXPECT_EQ(read_point_field(copy, 2, "distance"), values);
  const testing::CliRun run = testing::run_cli("info " + copy.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string info = run.out + run.err;
  EXPECT_NE(info.find("3 levels"), std::string::npos) << info;
  EXPECT_NE(info.find("level 2 point fields: distance"), std::string::npos) << info;
  EXPECT_NE(info.find("fas2.pqr"), std::string::npos) << info;
  // Not a hierarchy: exit code 3 (input error).
  EXPECT_EQ(
      testing::run_cli("info " + (fs::path(MOLMESH_TEST_DATA_DIR) / "fas2.pqr").string()).exit_code,
      3);
}

}  // namespace
}  // namespace molmesh
