// Volume-mesh writers: MCSF round trip and malformed files, VTU and Gmsh read back by
// meshio (python3-meshio), the APBS example mesh read by read_mcsf.
#include "molmesh/io/mcsf.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "io_test_support.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/io/volume_mesh_io.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "support/files.hpp"
#include "support/process.hpp"

namespace molmesh {
namespace {

TetMesh exterior_ion_mesh() {
  TetMeshOptions o;
  o.domain = Domain::exterior;
  o.outer_radius = 12.0;
  o.outer_sphere_subdivisions = 2;
  o.active_site = {Sphere{Vec3(0, 0, 3), 1.6}};
  return tetrahedralize(icosphere(Vec3::Zero(), 3.0, 2), {}, o);
}

TetMesh full_ion_mesh() {
  TetMeshOptions o;
  o.outer_radius = 12.0;
  o.outer_sphere_subdivisions = 2;
  Atom a;
  a.radius = 3.0;
  return tetrahedralize(icosphere(Vec3::Zero(), 3.0, 2), {a}, o);
}

std::map<int, std::size_t> count(const std::vector<int>& v) {
  std::map<int, std::size_t> m;
  for (int x : v) ++m[x];
  return m;
}

TEST(Mcsf, RoundTripKeepsMeshAndBoundaryMarkers) {
  const TetMesh mesh = exterior_ion_mesh();
  const auto path = test::scratch_dir() / "ext.m";
  write_mcsf(path, mesh);
  const TetMesh back = read_mcsf(path);
  ASSERT_EQ(back.points.size(), mesh.points.size());
  ASSERT_EQ(back.tetrahedra, mesh.tetrahedra);
  EXPECT_EQ(back.cell_markers, mesh.cell_markers);
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    EXPECT_LT((back.points[i] - mesh.points[i]).norm(), 1e-8);
  EXPECT_EQ(count(back.boundary_face_markers), count(mesh.boundary_face_markers));
  EXPECT_EQ(count(back.vertex_markers), count(mesh.vertex_markers));
  EXPECT_GT(count(mesh.boundary_face_markers)[markers::kActiveSite], 0u);
  EXPECT_EQ(compute_tet_stats(back).inverted_or_flat, 0u);
}

TEST(Mcsf, FullMeshMolecularSurfaceIsInteriorFaceType) {
  const TetMesh mesh = full_ion_mesh();
  const auto path = test::scratch_dir() / "full.m";
  write_volume_mesh(path, mesh);
  const TetMesh back = read_volume_mesh(path);
  // Only the outer sphere is a boundary in MCSF terms; materials are the regions.
  const auto faces = count(back.boundary_face_markers);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces.begin()->first, markers::kOuterSphere);
  EXPECT_EQ(faces.begin()->second, icosphere(Vec3::Zero(), 12.0, 2).triangles.size());
  EXPECT_EQ(count(back.cell_markers), count(mesh.cell_markers));
  EXPECT_EQ(count(back.cell_markers).size(), 2u);
  const std::string text = test::slurp(path);
  EXPECT_EQ(text.find("mcsf_begin=1;"), text.find("mcsf_begin"));
  EXPECT_NE(text.find("mcsf_end=1;"), std::string::npos);
}

TEST(Mcsf, ReadsApbsExampleMesh) {
  const std::filesystem::path example = "/usr/share/apbs/examples/born/mesh.m";
  ASSERT_TRUE(std::filesystem::exists(example)) << "apbs-data is not installed";
  const TetMesh m = read_mcsf(example);
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.tetrahedra.size(), 6u);
  double volume = 0.0;
  for (const auto& t : m.tetrahedra)
    volume += signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  EXPECT_NEAR(volume, 12.0 * 12.0 * 12.0, 1e-9);
  EXPECT_FALSE(m.boundary_faces.empty());
}

TEST(Mcsf, MalformedFilesGiveFileAndLine) {
  const std::string good =
      "mcsf_begin=1;\ndim=3;\ndimii=3;\nvertices=4;\nsimplices=1;\nvert=[\n"
      "0 0 0 0 0\n1 0 1 0 0\n2 0 0 1 0\n3 0 0 0 1\n];\n"
      "simp=[\n0 0 1 1 1 1 1 0 1 2 3\n];\nmcsf_end=1;\n";
  EXPECT_EQ(read_mcsf(test::write_text("good.m", good)).tetrahedra.size(), 1u);
  std::string bad_vertex = good;
  bad_vertex.replace(bad_vertex.find("0 1 2 3"), 7, "0 1 2 9");
  test::expect_input_error([&] { read_mcsf(test::write_text("v.m", bad_vertex)); },
                           {"v.m:13:", "out of range"});
  std::string truncated = good.substr(0, good.find("simp=["));
  test::expect_input_error([&] { read_mcsf(test::write_text("t.m", truncated)); }, {"t.m", "simp"});
  std::string bad_number = good;
  bad_number.replace(bad_number.find("1 0 1 0 0"), 9, "1 0 1 x 0");
  test::expect_input_error([&] { read_mcsf(test::write_text("n.m", bad_number)); },
                           {"n.m:8:", "coordinate"});
  test::expect_input_error([&] { read_mcsf(test::scratch_dir() / "missing.m"); }, {"missing.m"});
  EXPECT_THROW(write_volume_mesh(test::scratch_dir() / "x.xyz", full_ion_mesh()), Error);
}

TEST(VolumeMeshIo, MeshioReadsVtuAndGmshWithRegionsAndMarkers) {
  const TetMesh mesh = full_ion_mesh();
  const auto dir = test::scratch_dir();
  std::vector<double> radius;
  for (const auto& p : mesh.points) radius.push_back(p.norm());
  write_volume_mesh(dir / "full.vtu", mesh, {{"radius", radius}});
  write_volume_mesh(dir / "full.msh", mesh);
  write_volume_mesh(dir / "full.msh4", mesh);
  std::filesystem::copy_file(dir / "full.msh4", dir / "full41.msh",
                             std::filesystem::copy_options::overwrite_existing);
  const auto regions = count(mesh.cell_markers);
  const auto faces = count(mesh.boundary_face_markers);
  const std::string script = dir.string() + "/check.py";
  {
    std::ofstream py(script);
    py << "import sys, collections, meshio\n"
       << "d = sys.argv[1]\n"
       << "m = meshio.read(d + '/full.vtu')\n"
       << "tets = sum(len(c.data) for c in m.cells if c.type == 'tetra')\n"
       << "assert tets == " << mesh.tetrahedra.size() << ", tets\n"
       << "assert len(m.points) == " << mesh.points.size() << "\n"
       << "assert 'radius' in m.point_data and 'marker' in m.point_data\n"
       << "reg = collections.Counter()\n"
       << "for c, r in zip(m.cells, m.cell_data['region']):\n"
       << "    if c.type == 'tetra': reg.update(int(x) for x in r)\n"
       << "assert reg[1] == " << regions.at(1) << " and reg[2] == " << regions.at(2) << ", reg\n"
       << "for name in ('full.msh', 'full41.msh'):\n"
       << "    g = meshio.read(d + '/' + name)\n"
       << "    phys = collections.Counter()\n"
       << "    for c, p in zip(g.cells, g.cell_data['gmsh:physical']):\n"
       << "        phys.update((c.type, int(x)) for x in p)\n"
       << "    assert phys[('tetra', 1)] == " << regions.at(1) << ", (name, phys)\n"
       << "    assert phys[('tetra', 2)] == " << regions.at(2) << ", (name, phys)\n"
       << "    assert phys[('triangle', 1)] == " << faces.at(markers::kMolecularSurface)
       << ", (name, phys)\n"
       << "    assert phys[('triangle', 2)] == " << faces.at(markers::kOuterSphere)
       << ", (name, phys)\n"
       << "    assert 'molecule' in g.field_data and 'outer_sphere' in g.field_data, g.field_data\n"
       << "print('ok')\n";
  }
  const testing::CommandRun check =
      testing::run_command("/usr/bin/python3 " + testing::shell_quoted(script) + " " +
                           testing::shell_quoted(dir.string()));
  EXPECT_EQ(check.exit_code, 0) << check.output();
}

}  // namespace
}  // namespace molmesh
