#include "molmesh/io/surface_mesh_io.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>

#include "io/io_test_support.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
using test::write_text;

// A closed octahedron refined twice and pushed onto a sphere of radius 10 with an off-grid
// centre, so coordinates have full double precision; markers vary per vertex and face.
SurfaceMesh sphere_mesh() {
  SurfaceMesh m;
  m.points = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
              Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      m.points.push_back((m.points[a] + m.points[b]).normalized());
      return mid[key] = static_cast<int>(m.points.size()) - 1;
    };
    std::vector<Triangle> next;
    for (const auto& t : m.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    m.triangles = next;
  }
  for (auto& p : m.points) p = Vec3(0.1234567, -7.654321, 3.3333333) + 10.0 * p.normalized();
  for (std::size_t i = 0; i < m.points.size(); ++i)
    m.vertex_markers.push_back(static_cast<int>(i % 4));
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    m.face_markers.push_back(static_cast<int>(i % 3) + 1);
  return m;
}

void expect_same_geometry(const SurfaceMesh& a, const SurfaceMesh& b, double tolerance) {
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    ASSERT_LE((a.points[i] - b.points[i]).norm(), tolerance) << i;
  for (std::size_t i = 0; i < a.triangles.size(); ++i)
    ASSERT_EQ(a.triangles[i], b.triangles[i]) << i;
}

TEST(SurfaceMeshIo, ExactRoundTrips) {
  const SurfaceMesh mesh = sphere_mesh();
  for (const char* file : {"m.off", "m.obj", "m.ply"}) {
    const auto path = testing::test_dir() / file;
    write_surface_mesh(path, mesh);
    const SurfaceMesh back = read_surface_mesh(path);
    expect_same_geometry(mesh, back, 0.0);
    if (std::string(file) == "m.ply") {
      EXPECT_EQ(back.vertex_markers, mesh.vertex_markers);
      EXPECT_EQ(back.face_markers, mesh.face_markers);
    }
  }
}

TEST(SurfaceMeshIo, StlRoundTripRestoresConnectivity) {
  const SurfaceMesh mesh = sphere_mesh();
  const auto path = testing::test_dir() / "m.stl";
  write_surface_mesh(path, mesh);
  EXPECT_EQ(std::filesystem::file_size(path), 84 + 50 * mesh.triangles.size());
  const SurfaceMesh back = read_surface_mesh(path);
  ASSERT_EQ(back.points.size(), mesh.points.size());  // corners merged back into shared vertices
  ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int c = 0; c < 3; ++c)
      ASSERT_LE((back.points[back.triangles[f][c]] - mesh.points[mesh.triangles[f][c]]).norm(),
                1e-5);
}

TEST(SurfaceMeshIo, AsciiStl) {
  const auto path = write_text("a.stl",
                               "solid test\n"
                               "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n"
                               "  vertex 0 1 0\n endloop\nendfacet\n"
                               "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 0\n"
                               "  vertex 0 1 0\n endloop\nendfacet\nendsolid test\n");
  const SurfaceMesh m = read_surface_mesh(path);
  EXPECT_EQ(m.points.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], (Triangle{1, 3, 2}));
}

TEST(SurfaceMeshIo, ObjCornerFormsPolygonsAndRelativeIndices) {
  const auto path = write_text("q.obj",
                               "# quad and triangle\nmtllib x.mtl\no thing\n"
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                               "usemtl red\ns off\n"
                               "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
                               "f -4//1 -2//1 -1//1\n"
                               "f 1/1 2/1 4/1\n");
  const SurfaceMesh m = read_surface_mesh(path);
  ASSERT_EQ(m.points.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[3], (Triangle{0, 1, 3}));
}

TEST(SurfaceMeshIo, OffVariants) {
  const auto path = write_text("v.off",
                               "OFF 4 2 0\n# comment\n0 0 0\n1 0 0 \n1 1 0\n\n0 1 0\n"
                               "4 0 1 2 3 255 0 0\n");
  // Counts on the header line; a quad with a colour is split into two triangles... but the
  // header announced 2 faces and the file has one: that is an error.
  expect_input_error([&] { read_surface_mesh(path); }, {"v.off:8:", "1 of 2 faces"});
  const auto ok =
      write_text("ok.off", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n");
  const SurfaceMesh m = read_surface_mesh(ok);
  EXPECT_EQ(m.points.size(), 3u);
  EXPECT_EQ(m.triangles.size(), 1u);
}

// Builds a binary PLY in either byte order with float coordinates and uchar/uint indices,
// an extra per-vertex property and an extra element, as other programs write them.
std::string binary_ply(bool big_endian) {
  std::string s =
      std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\ncomment made by a test\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nelement face 1\n"
      "property list uchar uint vertex_indices\nproperty int marker\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  auto put = [&](const void* p, std::size_t n) {
    std::string raw(static_cast<const char*>(p), n);
    if (big_endian) std::reverse(raw.begin(), raw.end());
    s += raw;
  };
  const float xyz[3][3] = {{0.5f, 0, 0}, {1, 0, 0}, {0, 1, -2.25f}};
  for (const auto& p : xyz) {
    for (float v : p) put(&v, 4);
    const unsigned char red = 7;
    put(&red, 1);
  }
  const unsigned char three = 3;
  put(&three, 1);
  for (std::uint32_t i : {2u, 1u, 0u}) put(&i, 4);
  const std::int32_t marker = 3;
  put(&marker, 4);
  for (std::int32_t i : {0, 1}) put(&i, 4);
  return s;
}

TEST(SurfaceMeshIo, PlyEncodings) {
  for (bool big : {false, true}) {
    const SurfaceMesh m = read_surface_mesh(write_text(big ? "b.ply" : "l.ply", binary_ply(big)));
    ASSERT_EQ(m.points.size(), 3u);
    EXPECT_DOUBLE_EQ(m.points[0].x(), 0.5);
    EXPECT_DOUBLE_EQ(m.points[2].z(), -2.25);
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], (Triangle{2, 1, 0}));
    EXPECT_EQ(m.face_markers, std::vector<int>{3});
    EXPECT_TRUE(m.vertex_markers.empty());
  }
  const SurfaceMesh a = read_surface_mesh(write_text(
      "a.ply",
      "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty double x\r\nproperty double y\r\n"
      "property double z\r\nproperty int marker\r\nelement face 1\r\n"
      "property list uchar int vertex_index\r\nend_header\r\n"
      "0 0 0 1\r\n1 0 0 1\r\n1 1 0 2\r\n0 1 0 2\r\n4 0 1 2 3\r\n"));
  EXPECT_EQ(a.triangles.size(), 2u);
  EXPECT_EQ(a.vertex_markers, (std::vector<int>{1, 1, 2, 2}));
}

TEST(SurfaceMeshIo, MalformedFilesNameTheLine) {
  expect_input_error(
      [] { read_surface_mesh(write_text("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")); },
      {"a.off:6:", "vertex index 3 out of range"});
  expect_input_error([] { read_surface_mesh(write_text("b.off", "OFF\n3 1 0\n0 0 0\n1 x 0\n")); },
                     {"b.off:4:", "'x'"});
  expect_input_error([] { read_surface_mesh(write_text("c.off", "PLY\n")); },
                     {"c.off:1:", "not an OFF"});
  expect_input_error([] { read_surface_mesh(write_text("d.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n")); },
                     {"d.off", "2 of 3 vertices"});
  expect_input_error(
      [] { read_surface_mesh(write_text("e.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n")); },
      {"e.off:6:", "at least 3"});
  expect_input_error(
      [] { read_surface_mesh(write_text("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")); },
      {"a.obj:4:", "vertex 4 does not exist"});
  expect_input_error([] { read_surface_mesh(write_text("b.obj", "v 0 0\n")); },
                     {"b.obj:1:", "v x y z"});
  expect_input_error([] { read_surface_mesh(write_text("c.obj", "v 0 0 0\nf 1 2\n")); },
                     {"c.obj:2:", "corners"});
  expect_input_error([] { read_surface_mesh(write_text("d.obj", "v 0 0 0\nf a b c\n")); },
                     {"d.obj:2:", "'a'"});
  expect_input_error([] { read_surface_mesh(write_text("e.obj", "v 0 nan 0\n")); },
                     {"e.obj:1:", "finite"});
  expect_input_error(
      [] {
        read_surface_mesh(write_text(
            "a.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0\n"));
      },
      {"a.ply", "ends before"});
  expect_input_error(
      [] {
        read_surface_mesh(write_text(
            "b.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n3 0 0 5\n"));
      },
      {"b.ply:11:", "out of range"});
  expect_input_error(
      [] { read_surface_mesh(write_text("c.ply", "ply\nformat ascii 1.0\nelement vertex 1\n")); },
      {"c.ply", "end_header"});
  expect_input_error(
      [] { read_surface_mesh(write_text("d.ply", "ply\nformat ascii 1.0\nbogus\nend_header\n")); },
      {"d.ply:3:", "bogus"});
  {
    std::string cut = binary_ply(false);
    cut.resize(cut.size() - 6);
    expect_input_error([&] { read_surface_mesh(write_text("e.ply", cut)); },
                       {"e.ply", "truncated"});
  }
  expect_input_error([] { read_surface_mesh(write_text("a.stl", std::string(90, 'x'))); },
                     {"a.stl", "STL"});
  expect_input_error(
      [] {
        read_surface_mesh(write_text("b.stl",
                                     "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 "
                                     "0\nvertex 1 0 0\nendloop\nendfacet\n"));
      },
      {"b.stl:2:", "2 vertices"});
  expect_input_error(
      [] { read_surface_mesh(write_text("c.stl", "solid x\nfacet normal 0 0 1\nvertex 0 0\n")); },
      {"c.stl:3:", "vertex x y z"});
  expect_input_error([] { read_surface_mesh(write_text("mesh.vtk", "")); },
                     {"mesh.vtk", "unknown surface mesh format"});
  expect_input_error([] { read_surface_mesh(testing::test_dir() / "absent.off"); },
                     {"absent.off", "no such file"});
}

TEST(SurfaceMeshIo, WriterRefusesInconsistentMeshesAndKeepsOldFile) {
  SurfaceMesh bad = sphere_mesh();
  const auto path = testing::test_dir() / "keep.ply";
  write_surface_mesh(path, bad);
  const auto size = std::filesystem::file_size(path);
  bad.face_markers.pop_back();
  EXPECT_THROW(write_surface_mesh(path, bad), OutputError);
  bad = sphere_mesh();
  bad.triangles[0][1] = 100000;
  EXPECT_THROW(write_surface_mesh(path, bad), OutputError);
  EXPECT_THROW(write_surface_mesh(testing::test_dir() / "x.vtk", sphere_mesh()), OutputError);
  EXPECT_EQ(std::filesystem::file_size(path), size);
}

}  // namespace
}  // namespace molmesh
