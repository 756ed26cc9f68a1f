#include "molmesh/io/volume_io.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "io/io_test_support.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
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
  const auto path = test::scratch_dir() / "g.dx";
  write_volume(path, g);
  expect_same(g, read_volume(path), 0.0);
  const std::string text = test::slurp(path);
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
    const auto path = test::scratch_dir() / file;
    write_volume(path, g);
    EXPECT_EQ(std::filesystem::file_size(path), 1024 + 4 * g.size());
    expect_same(g, read_volume(path), 1e-6);
  }
}

// A hand-made MRC: header words set explicitly, data in the given file order.
struct MrcSpec {
  std::array<std::int32_t, 3> n{1, 1, 1};
  std::int32_t mode = 2;
  std::array<std::int32_t, 3> start{0, 0, 0};
  std::array<std::int32_t, 3> m{1, 1, 1};
  std::array<float, 3> cell{1, 1, 1};
  std::array<std::int32_t, 3> axes{1, 2, 3};
  std::array<float, 3> origin{0, 0, 0};
  std::int32_t nsymbt = 0;
  bool big_endian = false;
};

std::string make_mrc(const MrcSpec& s, const std::vector<double>& file_order_values) {
  std::string b(1024 + static_cast<std::size_t>(s.nsymbt), '\0');
  auto put = [&](int word, const void* v) {
    char raw[4];
    std::memcpy(raw, v, 4);
    if (s.big_endian) std::reverse(raw, raw + 4);
    std::memcpy(b.data() + 4 * (word - 1), raw, 4);
  };
  for (int k = 0; k < 3; ++k) {
    put(1 + k, &s.n[k]);
    put(5 + k, &s.start[k]);
    put(8 + k, &s.m[k]);
    put(11 + k, &s.cell[k]);
    put(17 + k, &s.axes[k]);
    put(50 + k, &s.origin[k]);
  }
  put(4, &s.mode);
  put(24, &s.nsymbt);
  std::memcpy(b.data() + 208, "MAP ", 4);
  const unsigned char stamp = s.big_endian ? 0x11 : 0x44;
  std::memset(b.data() + 212, stamp, 2);
  for (double v : file_order_values) {
    char raw[4];
    std::size_t n = 4;
    if (s.mode == 0) {
      raw[0] = static_cast<char>(static_cast<signed char>(v));
      n = 1;
    } else if (s.mode == 1) {
      const auto x = static_cast<std::int16_t>(v);
      std::memcpy(raw, &x, 2);
      n = 2;
    } else if (s.mode == 6) {
      const auto x = static_cast<std::uint16_t>(v);
      std::memcpy(raw, &x, 2);
      n = 2;
    } else {
      const auto x = static_cast<float>(v);
      std::memcpy(raw, &x, 4);
    }
    if (s.big_endian) std::reverse(raw, raw + n);
    b.append(raw, n);
  }
  return b;
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
  expect_input_error([&] { read_volume(test::scratch_dir() / "none.dx"); },
                     {"none.dx", "no such file"});
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
  EXPECT_THROW(write_volume(test::scratch_dir() / "bad.dx", g), OutputError);
  EXPECT_THROW(write_volume(test::scratch_dir() / "bad.vol", sample_grid(false)), OutputError);
  EXPECT_FALSE(std::filesystem::exists(test::scratch_dir() / "bad.dx"));
}

}  // namespace
}  // namespace molmesh
