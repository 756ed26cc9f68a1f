// Volume-mesh writers: MCSF round trip and malformed files, VTU and Gmsh read back by
// meshio (python3-meshio), the APBS example mesh read by read_mcsf.
#include "molmesh/io/mcsf.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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
  const auto path = testing::test_dir() / "ext.m";
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
  const auto path = testing::test_dir() / "full.m";
  write_volume_mesh(path, mesh);
  const TetMesh back = read_volume_mesh(path);
  // Only the outer sphere is a boundary in MCSF terms; materials are the regions.
  const auto faces = count(back.boundary_face_markers);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces.begin()->first, markers::kOuterSphere);
  EXPECT_EQ(faces.begin()->second, icosphere(Vec3::Zero(), 12.0, 2).triangles.size());
  EXPECT_EQ(count(back.cell_markers), count(mesh.cell_markers));
  EXPECT_EQ(count(back.cell_markers).size(), 2u);
  const std::string text = testing::slurp(path);
  EXPECT_EQ(text.find("mcsf_begin=1;"), text.find("mcsf_begin"));
  EXPECT_NE(text.find("mcsf_end=1;"), std::string::npos);
}

// A block of n^3 cubes, six tets each (Kuhn: every path from corner 000 to 111), so half
// the tets are negatively oriented; 13^3 = 2197 points, more than the writer's first-level
// buckets (at most ~1024) hold one vertex each. One extra tet on an interior face makes a
// face that three tets share.
TetMesh kuhn_block(int n) {
  TetMesh m;
  const auto id = [n](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) m.points.emplace_back(i, j, k);
  const std::array<std::array<int, 3>, 6> paths{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& path : paths) {
          std::array<int, 3> c{i, j, k};
          Tetrahedron t;
          t[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step) {
            ++c[static_cast<std::size_t>(path[static_cast<std::size_t>(step)])];
            t[step + 1] = id(c[0], c[1], c[2]);
          }
          m.tetrahedra.push_back(t);
        }
  m.points.emplace_back(0.5, 0.5, -3.0);
  const Tetrahedron& inner = m.tetrahedra[6 * (n * n + n + 1) + 2];
  m.tetrahedra.push_back({inner[0], inner[1], inner[2], static_cast<int>(m.points.size()) - 1});
  return m;
}

TEST(Mcsf, FaceTypesArePerFaceAndIndependentOfTheThreadCount) {
  TetMesh mesh = kuhn_block(12);
  std::map<std::array<int, 3>, int> uses;
  const auto sorted = [](std::array<int, 3> f) {
    std::sort(f.begin(), f.end());
    return f;
  };
  for (const auto& t : mesh.tetrahedra)
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f{};
      for (int c = 0, j = 0; c < 4; ++c)
        if (c != k) f[static_cast<std::size_t>(j++)] = t[c];
      ++uses[sorted(f)];
    }
  ASSERT_EQ(std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 3; }),
            1);
  // Boundary faces at x = 0 are the active site, at x = 12 the outer sphere, the rest are
  // unmarked; one interior face carries a marker too (as the molecular surface of a full
  // mesh does) and must stay interior.
  std::map<std::array<int, 3>, int> marker;
  for (const auto& [face, n] : uses) {
    const std::array<int, 3>& f = face;  // clang 14 cannot capture a structured binding
    const auto x = [&](std::size_t c) { return mesh.points[f[c]].x(); };
    int m = -1;
    if (n == 1 && x(0) == 0 && x(1) == 0 && x(2) == 0) m = markers::kActiveSite;
    if (n == 1 && x(0) == 12 && x(1) == 12 && x(2) == 12) m = markers::kOuterSphere;
    if (n == 2 && marker.empty()) m = markers::kMolecularSurface;
    if (m < 0) continue;
    marker[f] = m;
    mesh.boundary_faces.push_back({f[0], f[1], f[2]});
    mesh.boundary_face_markers.push_back(m);
  }
  const McsfFaceTypes types;
  const auto path = testing::test_dir() / "kuhn.m";
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    write_mcsf(path, mesh, types);
  }
  const std::string serial = testing::slurp(path);
  write_mcsf(path, mesh, types);
  EXPECT_EQ(testing::slurp(path), serial);

  std::istringstream in(serial.substr(serial.find("simp=[")));
  std::string line;
  std::getline(in, line);
  std::size_t lines = 0;
  std::map<int, std::size_t> seen;
  while (std::getline(in, line) && line != "];") {
    if (line.empty() || line[0] == '%') continue;
    std::istringstream fields(line);
    int id = 0, group = 0, material = 0;
    std::array<int, 4> type{}, v{};
    fields >> id >> group >> material >> type[0] >> type[1] >> type[2] >> type[3] >> v[0] >> v[1] >>
        v[2] >> v[3];
    ASSERT_TRUE(fields) << line;
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f{};
      for (int c = 0, j = 0; c < 4; ++c)
        if (c != k) f[static_cast<std::size_t>(j++)] = v[static_cast<std::size_t>(c)];
      f = sorted(f);
      const auto it = marker.find(f);
      const int want = uses.at(f) >= 2                      ? 0
                       : it == marker.end()                 ? types.other
                       : it->second == markers::kActiveSite ? types.active_site
                                                            : types.outer_sphere;
      ASSERT_EQ(type[static_cast<std::size_t>(k)], want) << line << " face " << k;
      ++seen[want];
    }
    ++lines;
  }
  EXPECT_EQ(lines, mesh.tetrahedra.size());
  EXPECT_EQ(seen[types.active_site], 2u * 12 * 12);
  EXPECT_EQ(seen[types.outer_sphere], 2u * 12 * 12);
  EXPECT_EQ(seen[types.other], 4u * 2 * 12 * 12 + 3);
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
  test::expect_input_error([&] { read_mcsf(testing::test_dir() / "missing.m"); }, {"missing.m"});
  EXPECT_THROW(write_volume_mesh(testing::test_dir() / "x.xyz", full_ion_mesh()), Error);
}

TEST(VolumeMeshIo, MeshioReadsVtuAndGmshWithRegionsAndMarkers) {
  const TetMesh mesh = full_ion_mesh();
  const auto dir = testing::test_dir();
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
