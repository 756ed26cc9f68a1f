#include "molmesh/io/volume_io.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_support.hpp"
#include "io/mrc_test_file.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
using test::make_mrc;
using test::MrcSpec;
using test::write_text;

// Values that differ along every axis, so a transposed reader cannot pass.
double field(double x, double y, double z) {
  return 1.5 * x - 2.25 * y * y + 0.125 * z * x + std::sin(z);
}

Grid sample_grid(bool float_exact) {
  Grid g;
  g.origin = Vec3(-10.25, 3.5, 0.75);
  g.spacing = Vec3(0.5, 0.75, 1.25);
  g.dims = {5, 4, 3};
  g.values.resize(g.size());
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 p = g.position(i, j, k);
        const double v = field(p.x(), p.y(), p.z());
        g.at(i, j, k) = float_exact ? static_cast<double>(static_cast<float>(v)) : v;
      }
  return g;
}

void expect_same(const Grid& a, const Grid& b, double tolerance) {
  ASSERT_EQ(a.dims, b.dims);
  EXPECT_LE((a.origin - b.origin).norm(), tolerance);
  EXPECT_LE((a.spacing - b.spacing).norm(), tolerance);
  ASSERT_EQ(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < a.values.size(); ++i) ASSERT_EQ(a.values[i], b.values[i]) << i;
}

TEST(VolumeIo, DxRoundTripIsExact) {
  const Grid g = sample_grid(false);
  const auto path = testing::test_dir() / "g.dx";
  write_volume(path, g);
  expect_same(g, read_volume(path), 0.0);
  const std::string text = testing::slurp(path);
  EXPECT_NE(text.find("object 1 class gridpositions counts 5 4 3\n"), std::string::npos);
  EXPECT_NE(text.find("object 3 class array type double rank 0 items 60 data follows\n"),
            std::string::npos);
}

TEST(VolumeIo, DxValuesAreZFastest) {
  // nx=2, ny=1, nz=3: the file lists (0,0,0) (0,0,1) (0,0,2) (1,0,0) ...
  const auto path =
      write_text("apbs.dx",
                 "# Data from APBS 3.0\n#\n"
                 "object 1 class gridpositions counts 2 1 3\n"
                 "origin -1.000000e+00 2.000000e+00 3.000000e+00\n"
                 "delta 5.000000e-01 0.000000e+00 0.000000e+00\n"
                 "delta 0.000000e+00 2.500000e-01 0.000000e+00\n"
                 "delta 0.000000e+00 0.000000e+00 1.000000e+00\n"
                 "object 2 class gridconnections counts 2 1 3\n"
                 "object 3 class array type double rank 0 items 6 data follows\n"
                 "0.000000e+00 1.000000e+00 2.000000e+00\n"
                 "1.000000e+01 1.100000e+01 1.200000e+01\n"
                 "attribute \"dep\" string \"positions\"\n"
                 "object \"regular positions regular connections\" class field\n"
                 "component \"positions\" value 1\ncomponent \"connections\" value 2\n"
                 "component \"data\" value 3\n");
  const Grid g = read_volume(path);
  EXPECT_EQ(g.dims, (std::array<int, 3>{2, 1, 3}));
  EXPECT_EQ(g.origin, Vec3(-1, 2, 3));
  EXPECT_EQ(g.spacing, Vec3(0.5, 0.25, 1.0));
  EXPECT_EQ(g.at(0, 0, 2), 2.0);
  EXPECT_EQ(g.at(1, 0, 0), 10.0);
  EXPECT_EQ(g.at(1, 0, 1), 11.0);
}

TEST(VolumeIo, MrcRoundTripKeepsGeometryAndFloats) {
  const Grid g = sample_grid(true);
  for (const char* file : {"g.mrc", "g.map", "g.ccp4"}) {
    const auto path = testing::test_dir() / file;
    write_volume(path, g);
    EXPECT_EQ(std::filesystem::file_size(path), 1024 + 4 * g.size());
    expect_same(g, read_volume(path), 1e-6);
  }
}

TEST(VolumeIo, MrcPermutedAxisOrder) {
  // Columns run along Z, rows along X, sections along Y (MAPC/MAPR/MAPS = 3 1 2).
  // Space dims: X=3 (rows), Y=2 (sections), Z=4 (columns).
  MrcSpec s;
  s.n = {4, 3, 2};
  s.axes = {3, 1, 2};
  s.m = {3, 2, 4};              // MX MY MZ: samples per cell along X, Y, Z
  s.cell = {1.5f, 2.0f, 8.0f};  // voxel 0.5 x 1.0 x 2.0
  s.start = {-2, 5, 1};         // along columns (Z), rows (X), sections (Y)
  std::vector<double> values;
  for (int sec = 0; sec < 2; ++sec)
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 4; ++col) values.push_back(100 * row + 10 * sec + col);  // 100x+10y+z
  const Grid g = read_volume(write_text("perm.mrc", make_mrc(s, values)));
  EXPECT_EQ(g.dims, (std::array<int, 3>{3, 2, 4}));
  EXPECT_EQ(g.spacing, Vec3(0.5, 1.0, 2.0));
  // Origin from N*START (origin words are zero): X start 5, Y start 1, Z start -2.
  EXPECT_EQ(g.origin, Vec3(2.5, 1.0, -4.0));
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 4; ++z) ASSERT_EQ(g.at(x, y, z), 100 * x + 10 * y + z) << x << y << z;
}

TEST(VolumeIo, MrcModesEndiannessExtendedHeaderAndOrigin) {
  const std::vector<double> values{-3, 7, 100, 0, 1, 2};
  for (std::int32_t mode : {0, 1, 2, 6}) {
    for (bool big : {false, true}) {
      MrcSpec s;
      s.n = {3, 2, 1};
      s.m = {3, 2, 1};
      s.cell = {3, 2, 1};
      s.mode = mode;
      s.big_endian = big;
      s.nsymbt = 80;
      s.origin = {1.5f, -2.5f, 0.25f};
      s.start = {7, 7, 7};  // ignored: the origin words are set
      std::vector<double> v = values;
      if (mode == 6) v[0] = 65000;  // unsigned
      const Grid g = read_volume(write_text("m.mrc", make_mrc(s, v)));
      ASSERT_EQ(g.values, v) << "mode " << mode << (big ? " big" : " little");
      EXPECT_EQ(g.origin, Vec3(1.5, -2.5, 0.25));
    }
  }
}

TEST(VolumeIo, MalformedVolumesAreInputErrors) {
  const std::string head =
      "object 1 class gridpositions counts 2 1 1\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n";
  expect_input_error(
      [&] {
        read_volume(write_text(
            "a.dx",
            head +
                "delta 0 0 1\nobject 3 class array type double rank 0 items 2 data follows\n1\n"));
      },
      {"a.dx", "1 of 2 values"});
  expect_input_error(
      [&] {
        read_volume(write_text("b.dx", head + "delta 0 0 1\nobject 3 class array type double rank "
                                              "0 items 3 data follows\n1 2 3\n"));
      },
      {"b.dx:6:", "items must equal"});
  expect_input_error([&] { read_volume(write_text("c.dx", head + "delta 0 0.5 1\n")); },
                     {"c.dx:5:", "rotated"});
  expect_input_error(
      [&] {
        read_volume(write_text("d.dx", head + "delta 0 0 1\nobject 3 class array type double rank "
                                              "0 items 2 data follows\n1 zz\n"));
      },
      {"d.dx:7:", "'zz'"});
  expect_input_error(
      [&] { read_volume(write_text("e.dx", "object 1 class gridpositions counts 2 0 1\n")); },
      {"e.dx:1:", "positive"});
  expect_input_error([&] { read_volume(write_text("f.dx", "# nothing\n")); },
                     {"f.dx", "gridpositions"});
  expect_input_error([&] { read_volume(write_text("g.dx", head + "delta 0 0 -1\n")); },
                     {"g.dx:5:", "positive"});
  expect_input_error([&] { read_volume(write_text("a.mrc", "short")); }, {"a.mrc", "too short"});
  MrcSpec s;
  s.n = {2, 2, 2};
  expect_input_error(
      [&] {
        read_volume(write_text("b.mrc", make_mrc(s, {1, 2, 3})));
      },
      {"b.mrc", "truncated"});
  s.mode = 4;
  expect_input_error([&] { read_volume(write_text("c.mrc", make_mrc(s, {}))); },
                     {"c.mrc", "mode 4"});
  s.mode = 2;
  s.axes = {1, 1, 3};
  expect_input_error(
      [&] { read_volume(write_text("d.mrc", make_mrc(s, std::vector<double>(8, 0.0)))); },
      {"d.mrc", "permutation"});
  s.axes = {1, 2, 3};
  s.cell = {0, 1, 1};
  expect_input_error(
      [&] { read_volume(write_text("e.mrc", make_mrc(s, std::vector<double>(8, 0.0)))); },
      {"e.mrc", "voxel size"});
  expect_input_error([&] { read_volume(write_text("v.vtk", "")); },
                     {"v.vtk", "unknown volume format"});
  expect_input_error([&] { read_volume(testing::test_dir() / "none.dx"); },
                     {"none.dx", "no such file"});
}

// Data that does not match its header (issue 18): each case is an InputError naming the
// file (and for DX the line), never a grid read from part of the file or past it.
// A 2x1x1 DX grid announcing 2 values (data array on line 6) with the given data lines.
std::string dx_with_data(const std::string& data) {
  return "object 1 class gridpositions counts 2 1 1\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n"
         "delta 0 0 1\nobject 3 class array type double rank 0 items 2 data follows\n" +
         data;
}

const std::string kDxTail =
    "attribute \"dep\" string \"positions\"\n"
    "object \"regular positions regular connections\" class field\n";

TEST(VolumeIo, DxFewerValuesThanItemsAtTheEndOfTheFile) {
  expect_input_error([] { read_volume(write_text("short.dx", dx_with_data("1\n"))); },
                     {"short.dx:7: file ends after 1 of 2 values (declared on line 6)"});
}

TEST(VolumeIo, DxFewerValuesThanItemsBeforeTheNextObject) {
  // Was "value 'attribute' is not a finite number": right line, wrong reason.
  expect_input_error(
      [] { read_volume(write_text("short.dx", dx_with_data("1\n" + kDxTail))); },
      {"short.dx:8: data ends after 1 of 2 values (declared on line 6), at 'attribute'"});
}

TEST(VolumeIo, DxMoreValuesThanItemsOnTheLastDataLine) {
  expect_input_error([] { read_volume(write_text("long.dx", dx_with_data("1 2 3\n" + kDxTail))); },
                     {"long.dx:7: more values than the 2 items declared on line 6"});
}

TEST(VolumeIo, DxMoreValuesThanItemsOnLaterLines) {
  // The reader stopped at the count and skipped the rest like an unknown keyword: exit 0
  // with the first two values.
  expect_input_error(
      [] { read_volume(write_text("long.dx", dx_with_data("1 2\n\n3 4\n" + kDxTail))); },
      {"long.dx:9: more values than the 2 items declared on line 6"});
  expect_input_error(
      [] { read_volume(write_text("tail.dx", dx_with_data("1 2\n" + kDxTail + "5\n"))); },
      {"tail.dx:10: more values than the 2 items declared on line 6"});
  // The exact count with APBS's trailer still reads.
  EXPECT_EQ(read_volume(write_text("ok.dx", dx_with_data("1 2\n" + kDxTail))).values,
            (std::vector<double>{1, 2}));
}

TEST(VolumeIo, DxValuesBeforeTheDataArrayAreAnError) {
  // Numbers on a header line were skipped like an unknown keyword: a stray line between
  // the deltas and the array, or ahead of the gridpositions object, read as a valid grid.
  const std::string counts = "object 1 class gridpositions counts 2 1 1\n";
  const std::string geometry = "origin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\ndelta 0 0 1\n";
  const std::string array =
      "object 3 class array type double rank 0 items 2 data follows\n1 2\n" + kDxTail;
  const char* message = "values before the data array";
  expect_input_error(
      [&] { read_volume(write_text("stray.dx", counts + geometry + "1.0 2.0 3.0\n" + array)); },
      {"stray.dx:6:", message, "'origin x y z'"});
  expect_input_error(
      [&] { read_volume(write_text("first.dx", "# APBS\n-1 2\n" + counts + geometry + array)); },
      {"first.dx:2:", message});
  expect_input_error(
      [&] {
        read_volume(write_text(
            "conn.dx",
            counts + geometry + "object 2 class gridconnections counts 2 1 1\n+3\n" + array));
      },
      {"conn.dx:7:", message});
  // Comments stay comments, whole-line or after a keyword's fields.
  EXPECT_EQ(read_volume(write_text("comments.dx", "# 1 2 3\n" + counts + "  # 4.5\n" + geometry +
                                                      "#\t6 7 8\n" + array))
                .values,
            (std::vector<double>{1, 2}));
}

// NSYMBT (word 24) set in the header only, the file built without an extended header.
std::string with_nsymbt(std::string bytes, std::int32_t nsymbt) {
  std::memcpy(bytes.data() + 4 * 23, &nsymbt, 4);
  return bytes;
}

TEST(VolumeIo, MrcDataShorterThanTheHeaderSays) {
  MrcSpec s;
  s.n = {2, 2, 2};
  for (std::int32_t mode : {0, 1, 2, 6}) {
    s.mode = mode;
    // One value short, and (for multi-byte modes) one byte short.
    expect_input_error(
        [&] { read_volume(write_text("short.mrc", make_mrc(s, std::vector<double>(7, 1.0)))); },
        {"short.mrc: file has", "truncated"});
    std::string cut = make_mrc(s, std::vector<double>(8, 1.0));
    cut.pop_back();
    expect_input_error([&] { read_volume(write_text("cut.ccp4", cut)); },
                       {"cut.ccp4: file has " + std::to_string(cut.size()) + " bytes",
                        "needs " + std::to_string(cut.size() + 1)});
  }
}

TEST(VolumeIo, MrcBytesAfterTheDataAreAnError) {
  // Accepted before, the extra bytes ignored: a header whose NX/NY/NZ, MODE or NSYMBT is
  // wrong read a grid the file does not hold (docs/inputs.md).
  MrcSpec s;
  s.n = {2, 2, 2};
  const std::string exact = make_mrc(s, std::vector<double>(8, 1.0));
  EXPECT_EQ(read_volume(write_text("exact.mrc", exact)).values.size(), 8u);
  expect_input_error([&] { read_volume(write_text("long.mrc", exact + '\0')); },
                     {"long.mrc: file has 1057 bytes", "accounts for 1056: 1 byte after the data"});
  // A whole ninth value: the header says 2x2x2.
  expect_input_error(
      [&] { read_volume(write_text("nine.map", make_mrc(s, std::vector<double>(9, 1.0)))); },
      {"nine.map: file has 1060 bytes", "4 bytes after the data"});
  // An extended header the header does not announce (NSYMBT 0) looks the same.
  MrcSpec ext = s;
  ext.nsymbt = 80;
  expect_input_error(
      [&] {
        read_volume(
            write_text("ext.mrc", with_nsymbt(make_mrc(ext, std::vector<double>(8, 1.0)), 0)));
      },
      {"ext.mrc:", "80 bytes after the data"});
}

TEST(VolumeIo, MrcExtendedHeaderRunningPastTheEnd) {
  MrcSpec s;
  s.n = {2, 2, 2};
  const std::string map = make_mrc(s, std::vector<double>(8, 1.0));  // 1056 bytes
  // Past the end of the file, past the data, and the largest int32.
  expect_input_error([&] { read_volume(write_text("a.mrc", with_nsymbt(map, 4096))); },
                     {"a.mrc: file has 1056 bytes", "after 5120 header bytes", "needs 5152"});
  expect_input_error([&] { read_volume(write_text("b.mrc", with_nsymbt(map, 16))); },
                     {"b.mrc: file has 1056 bytes", "after 1040 header bytes", "needs 1072"});
  expect_input_error([&] { read_volume(write_text("c.mrc", with_nsymbt(map, 2147483647))); },
                     {"c.mrc: file has 1056 bytes", "after 2147484671 header bytes"});
  expect_input_error([&] { read_volume(write_text("d.mrc", with_nsymbt(map, -4))); },
                     {"d.mrc:", "negative extended header size NSYMBT"});
}

TEST(VolumeIo, DxHoldsOneGrid) {
  // A second gridpositions object after the data changed the counts but not the values: a
  // 2x1x1 grid of 2 values came back as 3x1x1 (fuzz inputs
  // tests/fuzz/crashes/dx/dx-second-grid-after-data-*).
  const std::string grid =
      "object 1 class gridpositions counts 2 1 1\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n"
      "delta 0 0 1\nobject 3 class array type double rank 0 items 2 data follows\n1 2\n";
  expect_input_error(
      [&] {
        read_volume(
            write_text("a.dx", grid + "object 4 class gridpositions counts 3 1 1\norigin 0 0 0\n"));
      },
      {"a.dx:8:", "a second gridpositions object (the first is on line 1)"});
  expect_input_error([&] { read_volume(write_text("b.dx", grid + "origin 5 5 5\n")); },
                     {"b.dx:8:", "a second origin line (the first is on line 2)"});
  expect_input_error(
      [&] {
        read_volume(write_text(
            "c.dx", grid + "object 5 class array type double rank 0 items 2 data follows\n3 4\n"));
      },
      {"c.dx:8:", "a second data array (the first is on line 6)"});
}

TEST(VolumeIo, WriterRejectsInconsistentGrids) {
  Grid g = sample_grid(false);
  g.values.pop_back();
  EXPECT_THROW(write_volume(testing::test_dir() / "bad.dx", g), OutputError);
  EXPECT_THROW(write_volume(testing::test_dir() / "bad.vol", sample_grid(false)), OutputError);
  EXPECT_FALSE(std::filesystem::exists(testing::test_dir() / "bad.dx"));
}

}  // namespace
}  // namespace molmesh
