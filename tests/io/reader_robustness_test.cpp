// Issue 18 (readers): headers are checked against the data before memory is reserved,
// non-finite values and NUL bytes are errors in every reader, messages are in file:line
// form, and odd-but-real PDB layouts are read with a warning. Each case here was accepted,
// crashed or allocated gigabytes before the fix.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "io/io_test_support.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/atoms_pqr.hpp"
#include "molmesh/io/atoms_structure.hpp"
#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/mesh_obj.hpp"
#include "molmesh/io/mesh_off.hpp"
#include "molmesh/io/mesh_ply.hpp"
#include "molmesh/io/mesh_stl.hpp"
#include "molmesh/io/msms.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/volume_dx.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/io/volume_mrc.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
using test::write_text;

// A 1024-byte MRC header (little endian) with the given sample counts and mode.
std::string mrc_header(std::array<std::int32_t, 3> n, std::int32_t mode) {
  std::string h(1024, '\0');
  auto put = [&h](int word, auto value) { std::memcpy(h.data() + 4 * (word - 1), &value, 4); };
  for (int k = 0; k < 3; ++k) {
    put(1 + k, n[static_cast<std::size_t>(k)]);
    put(8 + k, std::int32_t{1});
    put(11 + k, 1.0f);
    put(17 + k, std::int32_t{k + 1});
  }
  put(4, mode);
  h[4 * 53] = 0x44;
  h[4 * 53 + 1] = 0x44;
  return h;
}

TEST(ReaderRobustness, MrcSampleCountOverflowIsRefusedNotWrapped) {
  // 2^22 * 2^21 * 2^21 = 2^64 wraps to 0 in size_t: the size check passed, then Grid::at
  // wrote past an empty vector.
  const std::string bytes = mrc_header({1 << 22, 1 << 21, 1 << 21}, 0) + std::string(64, '\0');
  expect_input_error([&] { parse_mrc(bytes, "big.mrc"); }, {"big.mrc", "truncated"});
  const std::string mode2 = mrc_header({1 << 21, 1 << 21, 1 << 20}, 2);  // 2^62 * 4 bytes
  expect_input_error([&] { parse_mrc(mode2, "big2.mrc"); }, {"big2.mrc", "more than 2^64"});
}

TEST(ReaderRobustness, DxCountsAreCheckedAgainstTheFileBeforeAllocating) {
  // 8e9 values (64 GB) announced by a 250-byte file: bad_alloc (exit 70) before; now the
  // read stops where the file does.
  const std::string dx =
      "object 1 class gridpositions counts 2000 2000 2000\norigin 0 0 0\n"
      "delta 1 0 0\ndelta 0 1 0\ndelta 0 0 1\n"
      "object 3 class array type double rank 0 items 8000000000 data follows\n1 2 3\n";
  expect_input_error([&] { parse_dx(dx, "big.dx"); },
                     {"big.dx:7:", "file ends after 3 of 8000000000 values"});
}

// Counts of 2^63 threw length_error and 1e11 bad_alloc from reserve (exit 70); memory is now
// reserved for no more items than the file can hold and the short file is reported.
TEST(ReaderRobustness, MeshCountsAreCheckedAgainstTheFileBeforeAllocating) {
  for (const char* count : {"9223372036854775807", "100000000000"}) {
    SCOPED_TRACE(count);
    expect_input_error([&] { parse_off("OFF\n" + std::string(count) + " 1 0\n0 0 0\n", "c.off"); },
                       {"c.off:3:", "file ends after 1 of " + std::string(count) + " vertices"});
    expect_input_error(
        [&] { parse_off("OFF\n3 " + std::string(count) + " 0\n0 0 0\n0 1 0\n1 0 0\n", "f.off"); },
        {"f.off:5:", "file ends after 0 of " + std::string(count) + " faces"});
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      const std::string ply = "ply\nformat " + std::string(format) + " 1.0\nelement vertex " +
                              count +
                              "\nproperty float x\nproperty float y\nproperty float z\n"
                              "end_header\n0 0 0\n";
      expect_input_error([&] { parse_ply(ply, "c.ply"); }, {"c.ply", "ends"});
    }
  }
  // A face element announcing more faces than bytes, after a valid vertex element.
  const std::string faces =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 100000000000\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_input_error([&] { parse_ply(faces, "f.ply"); }, {"f.ply:14:", "ends before"});
  // MCSF: 2^31 vertices announced by a 100-byte file.
  const auto mcsf = write_text("c.m",
                               "mcsf_begin=1;\ndim=3;\ndimii=3;\nvertices=2147483648;\n"
                               "simplices=1;\nvert=[\n0 0 0 0 0\n];\n");
  expect_input_error([&] { read_mcsf(mcsf); }, {"c.m:5:", "more than the file"});
}

TEST(ReaderRobustness, PlyPropertiesWithoutValuesCannotLoopForever) {
  // 2^62 items of an element without properties used to be "read" one by one.
  const std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
      "property float y\nproperty float z\nelement junk 4611686018427387904\nend_header\n";
  expect_input_error([&] { parse_ply(ply, "j.ply"); }, {"j.ply:7:", "no properties"});
}

TEST(ReaderRobustness, PlyIndicesAndMarkersMustBeIntegersInRange) {
  // A float marker of 1e30 (or NaN) converted to int is undefined behaviour.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nproperty float marker\nend_header\n";
  const float values[4] = {0.0f, 0.0f, 0.0f, 1e30f};
  ply.append(reinterpret_cast<const char*>(values), sizeof values);
  expect_input_error([&] { parse_ply(ply, "m.ply"); }, {"m.ply", "marker", "not an integer"});
}

TEST(ReaderRobustness, PlyHasOneVertexAndOneFaceElement) {
  // A second vertex element, with a marker where the first had none, gave 2 points and 1
  // vertex marker (fuzz inputs tests/fuzz/crashes/ply/ply-second-vertex-element-*).
  const std::string vertices =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nproperty int marker\nend_header\n0 0 0\n1 0 0 7\n";
  expect_input_error([&] { parse_ply(vertices, "v.ply"); },
                     {"v.ply:7:", "second 'vertex' element", "line 3"});
  const std::string faces =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property int marker\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4\n3 0 2 1\n";
  expect_input_error([&] { parse_ply(faces, "f.ply"); },
                     {"f.ply:10:", "second 'face' element", "line 7"});
}

TEST(ReaderRobustness, NonFiniteValuesAreErrorsInEveryReader) {
  const std::string dx =
      "object 1 class gridpositions counts 2 2 2\norigin 0 0 0\n"
      "delta 1 0 0\ndelta 0 1 0\ndelta 0 0 1\n"
      "object 3 class array type double rank 0 items 8 data follows\n"
      "1 2 3\n4 nan 6\n7 8\n";
  expect_input_error([&] { parse_dx(dx, "n.dx"); }, {"n.dx:8:", "'nan' is not a finite number"});
  std::string inf = dx;
  inf.replace(inf.find("nan"), 3, "-inf");
  expect_input_error([&] { parse_dx(inf, "i.dx"); }, {"i.dx:8:", "'-inf'"});
  // An all-NaN potential (as in --potential) names the file and the line.
  const auto all_nan = write_text(
      "phi.dx",
      "object 1 class gridpositions counts 2 2 2\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n"
      "delta 0 0 1\nobject 3 class array type double rank 0 items 8 data follows\n"
      "nan nan nan\nnan nan nan\nnan nan\n");
  expect_input_error([&] { read_volume(all_nan); }, {"phi.dx:7:", "'nan' is not a finite number"});
  // MSMS vertices: "nan" was taken as a coordinate.
  write_text("m.vert", "# v\n3 0 0 0\nnan 0 0\n1 0 0\n0 1 0\n");
  write_text("m.face", "# f\n1 0 0 0\n1 2 3\n");
  expect_input_error([&] { read_msms(testing::test_dir() / "m.vert"); },
                     {"m.vert:3:", "'nan' is not a finite number"});
  expect_input_error([] { parse_off("OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "n.off"); },
                     {"n.off:4:", "'inf'"});
  expect_input_error(
      [] {
        parse_ply(
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nproperty int marker\nend_header\n0 0 0 nan\n",
            "n.ply");
      },
      {"n.ply:9:", "'nan'"});
}

TEST(ReaderRobustness, NulByteInAPdbRecordIsAnErrorNotADroppedRecord) {
  // gemmi ended the record at the NUL and lost the next one (exit 0 with one atom short).
  std::string pdb =
      "ATOM      1  N   ALA A   1       0.000   0.000   0.000  1.00  0.00           N\n"
      "ATOM      2  CA  ALA A   1       1.500   0.000   0.000  1.00  0.00           C\n"
      "ATOM      3  C   ALA A   1       2.000   1.400   0.000  1.00  0.00           C\n";
  pdb[pdb.find('\n') + 1 + 70] = '\0';  // inside record 2, after its coordinates
  const auto path = write_text("nul.pdb", pdb);
  expect_input_error([&] { read_atoms(path); }, {"nul.pdb:2:", "NUL byte"});
  expect_input_error([&] { parse_pqr(std::string("ATOM 1 C ALA 1 0 0 0 0 1.5\0\n", 28), "n.pqr"); },
                     {"n.pqr:1:", "NUL byte"});
}

TEST(ReaderRobustness, MmcifErrorsHaveFileAndLine) {
  expect_input_error(
      [] { read_atoms(write_text("bad.cif", "data_x\nloop_\n_a.b\n'unterminated\n")); },
      {"bad.cif:4:", "cannot parse as mmCIF"});
  // An empty .cif said "vector::_M_range_check ...".
  expect_input_error([] { read_atoms(write_text("empty.cif", "")); }, {"empty.cif: empty file"});
  // Blank by io_detail::is_blank, the set split_fields uses too (issue 18).
  expect_input_error([] { read_atoms(write_text("blank.cif", "\f\v\r\n \t\f\n")); },
                     {"blank.cif: empty file: no mmCIF data"});
  expect_input_error([] { read_atoms(write_text("blank.pdb", "\v\n\f\r\n")); },
                     {"blank.pdb: empty file: no ATOM records"});
  expect_input_error([] { read_atoms(write_text("comment.cif", "# only a comment\n")); },
                     {"comment.cif", "no data_ block"});
}

TEST(ReaderRobustness, MessagesShowControlBytesInsteadOfCuttingAtThem) {
  // A NUL cut what() short; a CR rewound the terminal line, an escape sequence cleared it.
  // A CR is a blank since issue 18 (io_detail::is_blank), so the field carries an ESC.
  const std::string off = "OFF\n1 0 0\n0 x\x1b[2Jy 0\n";
  try {
    parse_off(off, "esc.off");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\x1b'), std::string::npos) << what;
    EXPECT_NE(what.find("esc.off:3: coordinate 'x\\x1b[2Jy'"), std::string::npos) << what;
  }
}

TEST(ReaderRobustness, AsciiStlWithoutEndsolidIsTruncated) {
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
      "endfacet\n";
  EXPECT_EQ(parse_stl("solid a\n" + facet + "endsolid a\n", "ok.stl").triangles.size(), 1u);
  // Two solids in one file are fine.
  EXPECT_EQ(
      parse_stl("solid a\n" + facet + "endsolid a\nsolid b\n" + facet + "endsolid b\n", "2.stl")
          .triangles.size(),
      2u);
  expect_input_error([&] { parse_stl("solid a\n" + facet + facet, "cut.stl"); },
                     {"cut.stl:15:", "without 'endsolid'"});
  expect_input_error([&] { parse_stl("solid a\n" + facet + "endsolid a\n" + facet, "after.stl"); },
                     {"after.stl:10:", "outside solid"});
}

// Real APBS examples (Debian's apbs-data): tab-separated fields and columns shifted right.
TEST(ReaderRobustness, PdbWithTabsOrShiftedColumnsIsReadWithAWarning) {
  const std::filesystem::path root = "/usr/share/apbs/examples";
  ASSERT_TRUE(std::filesystem::is_directory(root)) << "install apbs-data";
  struct Case {
    const char* file;
    std::size_t atoms;
    Vec3 first, last;
  };
  for (const Case& c : {Case{"ion-pmf/ion-pmf.pdb", 2, Vec3(-3, 0, 0), Vec3(1, 0, 0)},
                        Case{"geoflow/gly.pdb", 10, Vec3(0, 0, 0), Vec3(5.186, -2.375, 1.547)}}) {
    SCOPED_TRACE(c.file);
    std::string warning;
    Reporter reporter;
    reporter.on_warning = [&](std::string_view m) { warning += std::string(m) + "\n"; };
    const Atoms atoms = read_atoms(root / c.file, {}, reporter);
    ASSERT_GE(atoms.size(), c.atoms);
    EXPECT_LT((atoms.front().center - c.first).norm(), 1e-9);
    EXPECT_NE(warning.find("whitespace-separated fields"), std::string::npos) << warning;
    EXPECT_NE(warning.find("first at line 1"), std::string::npos) << warning;
    if (std::string(c.file) == "ion-pmf/ion-pmf.pdb") {
      EXPECT_EQ(atoms.size(), 2u);
      EXPECT_LT((atoms.back().center - c.last).norm(), 1e-9);
    } else {
      EXPECT_LT((atoms[6].center - c.last).norm(), 1e-9);
    }
  }
  // Precision kept: a tab-separated record with more decimals than PDB's usual three.
  const auto path =
      write_text("tab.pdb", "ATOM\t1\tCA\tALA\tA\t1\t1.23456\t-2.5\t3.0\t1.00\t0.00\tC\n");
  const Atoms atoms = read_atoms(path);
  ASSERT_EQ(atoms.size(), 1u);
  EXPECT_DOUBLE_EQ(atoms[0].center.x(), 1.23456);  // fits the 8 columns as written
  EXPECT_EQ(atoms[0].element, "C");
  // A record that is neither layout is still refused at its line.
  expect_input_error(
      [] { read_atoms(write_text("junk.pdb", "ATOM\t1\tCA\tALA\tA\t1\tx\ty\tz\n")); },
      {"junk.pdb:1:"});
}

}  // namespace
}  // namespace molmesh
