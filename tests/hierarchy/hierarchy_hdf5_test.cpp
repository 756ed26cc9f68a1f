// The hierarchy HDF5 file: exact round trip, point fields, rejection of foreign files, and
// an independent reader (python h5py + scipy, meshio on the XDMF sidecars).
#include "molmesh/io/hierarchy_hdf5.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "hierarchy/hierarchy_support.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/hierarchy/renumber.hpp"
#include "molmesh/hierarchy/transfer.hpp"
#include "molmesh/io/sha256.hpp"
#include "support/files.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

const fs::path kChecker = fs::path(__FILE__).parent_path() / "check_hierarchy.py";

Hierarchy synthetic_hierarchy() {
  Hierarchy h = testing::cube_hierarchy(6, 3);
  h.parameters = {{"domain", "full"}, {"t0", "0.1,0.3"}, {"spacing", "0.5"}};
  h.input_name = "cube.pqr";
  h.input_checksum = sha256_bytes({});
  return h;
}

template <class T>
void expect_same(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << what << " at " << i;
}

TEST(Sha256, KnownDigests) {
  EXPECT_EQ(sha256_bytes({}), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  const std::string abc = "abc";
  EXPECT_EQ(sha256_bytes({reinterpret_cast<const unsigned char*>(abc.data()), abc.size()}),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const auto dir = testing::test_dir("sha");
  testing::write_file(dir / "abc.txt", abc);
  EXPECT_EQ(sha256_file(dir / "abc.txt"),
            sha256_bytes({reinterpret_cast<const unsigned char*>(abc.data()), 3}));
  EXPECT_THROW(sha256_file(dir / "missing.txt"), InputError);
}

TEST(HierarchyHdf5, RoundTripIsExact) {
  const auto dir = testing::test_dir("roundtrip");
  const auto h = synthetic_hierarchy();
  write_hierarchy(dir / "h.h5", h);
  const auto back = read_hierarchy(dir / "h.h5");
  ASSERT_EQ(back.levels.size(), 2u);
  ASSERT_EQ(back.transfers.size(), 1u);
  EXPECT_EQ(back.parameters, h.parameters);
  EXPECT_EQ(back.input_name, h.input_name);
  EXPECT_EQ(back.input_checksum, h.input_checksum);
  for (std::size_t l = 0; l < 2; ++l) {
    const auto& a = h.levels[l];
    const auto& b = back.levels[l];
    EXPECT_EQ(a.t0, b.t0);
    expect_same(a.surface.points, b.surface.points, "surface points");
    expect_same(a.surface.triangles, b.surface.triangles, "triangles");
    expect_same(a.surface.vertex_markers, b.surface.vertex_markers, "surface vertex markers");
    expect_same(a.surface.face_markers, b.surface.face_markers, "face markers");
    expect_same(a.surface_provenance, b.surface_provenance, "provenance");
    expect_same(a.volume.points, b.volume.points, "volume points");
    expect_same(a.volume.tetrahedra, b.volume.tetrahedra, "tetrahedra");
    expect_same(a.volume.cell_markers, b.volume.cell_markers, "cell markers");
    expect_same(a.volume.vertex_markers, b.volume.vertex_markers, "vertex markers");
    expect_same(a.volume.boundary_faces, b.volume.boundary_faces, "boundary faces");
    expect_same(a.volume.boundary_face_markers, b.volume.boundary_face_markers, "bf markers");
    expect_same(a.volume_permutation, b.volume_permutation, "permutation");
  }
  EXPECT_EQ(SparseMatrix(h.transfers[0].volume - back.transfers[0].volume).norm(), 0.0);
  EXPECT_EQ(SparseMatrix(h.transfers[0].surface - back.transfers[0].surface).norm(), 0.0);
  for (const char* sidecar : {"h.xdmf", "h_L0_volume.xdmf", "h_L1_surface.xdmf"}) {
    EXPECT_TRUE(fs::exists(dir / sidecar)) << sidecar;
  }
}

TEST(HierarchyHdf5, SeveralPointFieldsAreStoredAllOrNone) {
  const auto dir = testing::test_dir("fields-many");
  const auto h = synthetic_hierarchy();
  write_hierarchy(dir / "h.h5", h);
  const std::size_t n = h.levels[0].volume.points.size();
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = h.levels[0].volume.points[i].x();
    y[i] = -2.0 * static_cast<double>(i);
  }
  const std::vector<PointFieldView> both{{"x", x}, {"y", y}};
  write_point_fields(dir / "h.h5", 0, both);
  EXPECT_EQ(read_point_field(dir / "h.h5", 0, "x"), x);
  EXPECT_EQ(read_point_field(dir / "h.h5", 0, "y"), y);
  EXPECT_EQ(point_field_names(dir / "h.h5", 0), (std::vector<std::string>{"x", "y"}));

  // A wrong length or name in the second field stores neither, not even the first.
  const std::vector<double> short_field(3);
  const std::vector<PointFieldView> bad_length{{"z", x}, {"w", short_field}};
  EXPECT_THROW(write_point_fields(dir / "h.h5", 0, bad_length), Error);
  const std::vector<PointFieldView> bad_name{{"z", x}, {"a/b", y}};
  EXPECT_THROW(write_point_fields(dir / "h.h5", 0, bad_name), Error);
  EXPECT_EQ(point_field_names(dir / "h.h5", 0), (std::vector<std::string>{"x", "y"}));
  const std::string text = testing::slurp(dir / "h_L0_volume.xdmf");
  EXPECT_NE(text.find("/levels/0/volume/fields/y"), std::string::npos);
  EXPECT_EQ(text.find("/levels/0/volume/fields/z"), std::string::npos);
}

TEST(HierarchyHdf5, PointFieldsAreStoredAndShownInXdmf) {
  const auto dir = testing::test_dir("fields");
  const auto h = synthetic_hierarchy();
  write_hierarchy(dir / "h.h5", h);
  std::vector<double> values(h.levels[1].volume.points.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = h.levels[1].volume.points[i].x();
  write_point_field(dir / "h.h5", 1, "potential", values);
  values[0] = 42.0;  // replacing a field keeps one copy with the new values
  write_point_field(dir / "h.h5", 1, "potential", values);
  EXPECT_EQ(read_point_field(dir / "h.h5", 1, "potential"), values);
  EXPECT_EQ(point_field_names(dir / "h.h5", 1), std::vector<std::string>{"potential"});
  EXPECT_TRUE(point_field_names(dir / "h.h5", 0).empty());
  const std::string text = testing::slurp(dir / "h_L1_volume.xdmf");
  EXPECT_NE(text.find("/levels/1/volume/fields/potential"), std::string::npos);
  EXPECT_THROW(write_point_field(dir / "h.h5", 1, "potential", std::vector<double>(3)), Error);
  EXPECT_THROW(write_point_field(dir / "h.h5", 5, "potential", values), InputError);
  EXPECT_THROW(read_point_field(dir / "h.h5", 0, "potential"), InputError);
  // The file is still complete after the failed writes.
  EXPECT_EQ(read_hierarchy(dir / "h.h5").levels.size(), 2u);

  const testing::CommandRun check =
      testing::run_command("/usr/bin/python3 " + testing::shell_quoted(kChecker.string()) + " " +
                           testing::shell_quoted((dir / "h.h5").string()) + " --field 1 potential");
  EXPECT_EQ(check.exit_code, 0) << check.output();
  EXPECT_NE(check.out.find("OK levels 2"), std::string::npos) << check.output();
}

TEST(HierarchyHdf5, ForeignFilesAreInputErrors) {
  const auto dir = testing::test_dir("foreign");
  testing::write_file(dir / "text.h5", "not hdf5\n");
  EXPECT_THROW(read_hierarchy(dir / "text.h5"), InputError);
  EXPECT_THROW(read_hierarchy(dir / "missing.h5"), InputError);
  testing::edit_with_h5py(dir / "other.h5",
                          "f['x'] = [1, 2]; f.attrs['format'] = 'something-else'");
  try {
    read_hierarchy(dir / "other.h5");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a molmesh hierarchy"), std::string::npos) << e.what();
  }
  // A hierarchy with a dataset removed is reported as damaged, not crashed on.
  write_hierarchy(dir / "h.h5", synthetic_hierarchy());
  testing::edit_with_h5py(dir / "h.h5", "del f['levels/1/volume/tetrahedra']");
  EXPECT_THROW(read_hierarchy(dir / "h.h5"), InputError);
}

TEST(HierarchyHdf5, UnwritableTargetIsOutputError) {
  EXPECT_THROW(write_hierarchy("/nonexistent-folder/h.h5", synthetic_hierarchy()), OutputError);
}

}  // namespace
}  // namespace molmesh
