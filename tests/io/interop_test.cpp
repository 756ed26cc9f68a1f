// Our files read by independent programs, and theirs read by us: meshio (Debian
// python3-meshio) for surface meshes, gemmi's CCP4 reader for maps.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gemmi/ccp4.hpp>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "io/io_test_support.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"
#include "support/files.hpp"
#include "support/process.hpp"

namespace molmesh {
namespace {

// The system interpreter: the one Debian's python3-meshio is installed for.
const char* kPython = "/usr/bin/python3";

std::string run_python(const std::string& script) {
  const auto dir = testing::test_dir();
  const auto script_path = dir / "script.py";
  std::ofstream(script_path) << script;
  const testing::CommandRun run = testing::run_command(std::string(kPython) + " " +
                                                       testing::shell_quoted(script_path.string()));
  EXPECT_EQ(run.exit_code, 0) << run.output();
  return run.output();
}

// Without markers: meshio 5.0 cannot read binary PLY faces that carry a property besides
// the index list (our marker property is tested by our own reader in surface_mesh_io_test).
SurfaceMesh torus_mesh() {
  // A closed torus: every vertex shared by six triangles, coordinates non-trivial.
  SurfaceMesh m;
  const int nu = 24, nv = 12;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.points.emplace_back((5 + 1.5 * std::cos(v)) * std::cos(u),
                            (5 + 1.5 * std::cos(v)) * std::sin(u), 1.5 * std::sin(v) + 0.1);
    }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

TEST(Interop, MeshioReadsOurSurfaceFiles) {
  const SurfaceMesh mesh = torus_mesh();
  double sum = 0.0;
  for (const Vec3& p : mesh.points) sum += p.x() + 2 * p.y() + 3 * p.z();
  std::string files;
  for (const char* ext : {"off", "ply", "obj", "stl"}) {
    const auto path = testing::test_dir() / (std::string("torus.") + ext);
    write_surface_mesh(path, mesh);
    files.append("'").append(path.string()).append("',");
  }
  const std::string out = run_python(
      "import meshio, numpy as np\n"
      "for f in [" +
      files +
      "]:\n"
      "    m = meshio.read(f)\n"
      "    tri = sum(len(c.data) for c in m.cells if c.type == 'triangle')\n"
      "    p = np.unique(m.points, axis=0) if f.endswith('stl') else m.points\n"
      "    s = float((p[:,0] + 2*p[:,1] + 3*p[:,2]).sum())\n"
      "    print(f.split('.')[-1], len(p), tri, repr(s))\n");
  std::map<std::string, std::tuple<std::size_t, std::size_t, double>> seen;
  std::istringstream lines(out);
  std::string ext;
  std::size_t points = 0, triangles = 0;
  double s = 0.0;
  while (lines >> ext >> points >> triangles >> s) seen[ext] = {points, triangles, s};
  ASSERT_EQ(seen.size(), 4u) << out;
  for (const auto& [format, values] : seen) {
    EXPECT_EQ(std::get<0>(values), mesh.points.size()) << format;
    EXPECT_EQ(std::get<1>(values), mesh.triangles.size()) << format;
    EXPECT_NEAR(std::get<2>(values), sum, format == "stl" ? 1e-3 : 1e-9) << format;
  }
}

TEST(Interop, WeReadMeshioSurfaceFiles) {
  const auto dir = testing::test_dir();
  run_python(
      "import meshio, numpy as np\n"
      "pts = np.array([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], dtype=float) * 1.25 + 0.5\n"
      "tri = np.array([[0,2,1],[0,1,3],[0,3,2],[1,2,3]])\n"
      "m = meshio.Mesh(pts, [('triangle', tri)])\n"
      "d = '" +
      dir.string() +
      "/'\n"
      "meshio.write(d + 'm_bin.ply', m, binary=True)\n"
      "meshio.write(d + 'm_asc.ply', m, binary=False)\n"
      "meshio.write(d + 'm_asc.stl', m, binary=False)\n"
      "meshio.write(d + 'm_bin.stl', m, binary=True)\n"
      "meshio.write(d + 'm.off', m)\n"
      "meshio.write(d + 'm.obj', m)\n");
  for (const char* file : {"m_bin.ply", "m_asc.ply", "m_asc.stl", "m_bin.stl", "m.off", "m.obj"}) {
    const SurfaceMesh m = read_surface_mesh(dir / file);
    ASSERT_EQ(m.points.size(), 4u) << file;
    ASSERT_EQ(m.triangles.size(), 4u) << file;
    // closed and consistently oriented: |signed volume| = 1.25^3 / 6
    const double volume = enclosed_volume(m.points, m.triangles);
    EXPECT_NEAR(std::abs(volume), 1.25 * 1.25 * 1.25 / 6.0, 1e-6) << file;
  }
}

TEST(Interop, GemmiReadsOurMrc) {
  Grid g;
  g.origin = Vec3(-3.5, 2.0, 10.25);
  g.spacing = Vec3(0.5, 0.5, 0.5);
  g.dims = {6, 5, 4};
  g.values.resize(g.size());
  for (std::size_t i = 0; i < g.values.size(); ++i)
    g.values[i] = std::sin(0.37 * static_cast<double>(i));
  const auto path = testing::test_dir() / "g.mrc";
  write_volume(path, g);
  gemmi::Ccp4<float> map;
  map.read_ccp4_file(path.string());
  EXPECT_EQ(map.grid.nu, 6);
  EXPECT_EQ(map.grid.nv, 5);
  EXPECT_EQ(map.grid.nw, 4);
  EXPECT_FLOAT_EQ(static_cast<float>(map.grid.unit_cell.a), 3.0f);
  EXPECT_FLOAT_EQ(static_cast<float>(map.grid.unit_cell.c), 2.0f);
  EXPECT_FLOAT_EQ(map.header_float(50), -3.5f);
  EXPECT_FLOAT_EQ(map.header_float(52), 10.25f);
  ASSERT_EQ(map.grid.data.size(), g.values.size());
  for (std::size_t i = 0; i < g.values.size(); ++i)
    ASSERT_FLOAT_EQ(map.grid.data[i], static_cast<float>(g.values[i])) << i;
  EXPECT_NEAR(map.hstats.dmax, 1.0, 1e-2);
}

TEST(Interop, WeReadApbsPotentialMaps) {
  // APBS (Debian apbs) solves the linearised PB equation for one ion at (3, 0, 0) on a grid
  // centred at the origin and writes the potential as OpenDX. The grid is symmetric in y
  // and z, the ion is not at the centre in x: a reader that got the z-fastest value order
  // wrong would put the maximum elsewhere and break the symmetries.
  const auto dir = testing::test_dir();
  std::ofstream(dir / "ion.pqr")
      << "ATOM      1  I   ION     1       3.000   0.000  0.000  1.00  2.00\n";
  std::ofstream(dir / "apbs.in")
      << "read\n  mol pqr ion.pqr\nend\n"
         "elec name solv\n  mg-manual\n  dime 33 17 17\n  grid 0.5 0.5 0.5\n"
         "  gcent 0.0 0.0 0.0\n  mol 1\n  lpbe\n  bcfl mdh\n  pdie 1.0\n"
         "  sdie 78.54\n  chgm spl2\n  srfm mol\n  srad 1.4\n  swin 0.3\n"
         "  sdens 10.0\n  temp 298.15\n  calcenergy no\n  calcforce no\n"
         "  write pot dx pot\nend\nquit\n";
  const testing::CommandRun apbs =
      testing::run_command("cd " + testing::shell_quoted(dir.string()) + " && apbs apbs.in");
  ASSERT_EQ(apbs.exit_code, 0) << apbs.output();
  const Grid g = read_volume(dir / "pot-PE0.dx");
  ASSERT_EQ(g.dims, (std::array<int, 3>{33, 17, 17}));
  EXPECT_EQ(g.origin, Vec3(-8, -4, -4));
  EXPECT_EQ(g.spacing, Vec3(0.5, 0.5, 0.5));
  std::size_t best = 0;
  for (std::size_t i = 1; i < g.values.size(); ++i)
    if (g.values[i] > g.values[best]) best = i;
  EXPECT_EQ(best, g.index(22, 8, 8));  // x = -8 + 22 * 0.5 = 3
  for (int i = 0; i < 33; i += 4)
    for (int j = 0; j < 17; ++j)
      for (int k = 0; k < 17; ++k) {
        const double v = g.at(i, j, k);
        ASSERT_NEAR(g.at(i, 16 - j, k), v, 1e-3 * std::abs(v) + 1e-6) << i << " " << j << " " << k;
        ASSERT_NEAR(g.at(i, k, j), v, 1e-3 * std::abs(v) + 1e-6) << i << " " << j << " " << k;
      }
  EXPECT_GT(g.at(22, 8, 8), 2.0 * g.at(10, 8, 8));  // the ion side is clearly higher
}

}  // namespace
}  // namespace molmesh
