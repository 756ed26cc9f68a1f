// MSMS .vert/.face pairs: a hand-written pair in MSMS's own layout, a round trip of a real
// molecular surface, and the errors a user gets for broken pairs.
#include "molmesh/io/msms.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// A tetrahedron as MSMS 2.6 lays it out (two comment lines, a count line, then rows of
// x y z nx ny nz face# sphere# type and v1 v2 v3 type sphere#).
void write_tetrahedron(const std::filesystem::path& stem) {
  write_text(stem.string() + ".vert",
             "# MSMS solvent excluded surface vertices for tetra.xyzr\n"
             "#vertex #sphere density probe_r\n"
             "      4       1  3.00  1.50\n"
             "     0.000     0.000     0.000    -0.577    -0.577    -0.577       0      1  2\n"
             "     1.000     0.000     0.000     0.577    -0.577    -0.577       0      1  2\n"
             "     0.000     1.000     0.000    -0.577     0.577    -0.577       0      1  2\n"
             "     0.000     0.000     1.000    -0.577    -0.577     0.577       0      1  2\n");
  write_text(stem.string() + ".face",
             "# MSMS solvent excluded surface faces for tetra.xyzr\n"
             "#faces  #sphere density probe_r\n"
             "      4       1  3.00  1.50\n"
             "      1      3      2  1      1\n"
             "      1      2      4  1      1\n"
             "      1      4      3  1      1\n"
             "      2      3      4  1      1\n");
}

TEST(Msms, ReadsTheMsmsLayout) {
  const auto stem = testing::test_dir() / "tetra";
  write_tetrahedron(stem);
  for (const auto& p : {stem, std::filesystem::path(stem.string() + ".vert"),
                        std::filesystem::path(stem.string() + ".face")}) {
    const SurfaceMesh m = read_msms(p);
    ASSERT_EQ(m.points.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 4u);
    EXPECT_EQ(m.points[3], Vec3(0.0, 0.0, 1.0));
    EXPECT_EQ(m.triangles[0], (Triangle{0, 2, 1}));
    EXPECT_EQ(m.triangles[3], (Triangle{1, 2, 3}));
  }
  EXPECT_TRUE(is_msms_path("x.vert"));
  EXPECT_TRUE(is_msms_path("x.FACE"));
  EXPECT_FALSE(is_msms_path("x.off"));
}

TEST(Msms, RoundTripsAMolecularSurface) {
  const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
  const SurfaceMesh m = marching_cubes(blur_atoms(atoms, BlurOptions{}), 1.0);
  const auto stem = testing::test_dir() / "1a1p";
  write_msms(stem, m);
  const SurfaceMesh back = read_msms(stem.string() + ".face");
  ASSERT_EQ(back.points.size(), m.points.size());
  EXPECT_EQ(back.triangles, m.triangles);
  double worst = 0.0;
  for (std::size_t v = 0; v < m.points.size(); ++v)
    worst = std::max(worst, (back.points[v] - m.points[v]).norm());
  EXPECT_LT(worst, 1e-6);  // six decimals, as MSMS-style fixed columns allow
}

TEST(Msms, ErrorsNameTheFileAndLine) {
  const auto stem = testing::test_dir() / "broken";
  write_tetrahedron(stem);
  write_text(stem.string() + ".face",
             "# faces\n#faces  #sphere density probe_r\n 2 1 3.00 1.50\n 1 2 3 1 1\n 1 2 9 1 1\n");
  try {
    read_msms(stem);
    FAIL() << "an index past the vertex count was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5u);
    EXPECT_NE(std::string(e.what()).find("broken.face"), std::string::npos) << e.what();
  }
  write_text(stem.string() + ".face", "# faces\n#faces\n 3 1 3.00 1.50\n 1 2 3 1 1\n");
  EXPECT_THROW(read_msms(stem), InputError);  // fewer faces than announced
  std::filesystem::remove(stem.string() + ".face");
  EXPECT_THROW(read_msms(stem.string() + ".vert"), InputError);  // the pair is incomplete
}

// A line of form feeds and vertical tabs has no fields, so it is a blank line; the reader
// used to take the first field of its empty field list (fuzz input
// tests/fuzz/crashes/msms/).
TEST(Msms, FormFeedLinesAreBlank) {
  const auto stem = testing::test_dir() / "formfeed";
  write_tetrahedron(stem);
  write_text(stem.string() + ".vert",
             "\f\v\n# vertices\n\f\n 4 1 3.00 1.50\n\v\n 0 0 0\n 1 0 0\n 0 1 0\n 0 0 1\n");
  EXPECT_EQ(read_msms(stem).points.size(), 4u);
  write_text(stem.string() + ".vert", "\f\n 2 1 3.00 1.50\n\f\v\n 0 0 0\n 1 x 0\n");
  try {
    read_msms(stem);
    FAIL() << "a vertex with a non-number was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5u) << e.what();
    EXPECT_NE(std::string(e.what()).find("formfeed.vert:5:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace molmesh
