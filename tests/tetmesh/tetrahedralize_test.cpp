// TetGen meshing of closed surfaces: a sphere standing in for an ion (one atom at its
// centre), nested spheres for a cavity, two disjoint spheres for a two-part molecule.
#include "molmesh/tetmesh/tetrahedralize.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh {
namespace {

using namespace markers;

Atoms atoms_at(std::initializer_list<Vec3> centres, double radius = 1.5) {
  Atoms atoms;
  for (const auto& c : centres) {
    Atom a;
    a.center = c;
    a.radius = radius;
    atoms.push_back(a);
  }
  return atoms;
}

double total_volume(const TetMesh& m, int region = -1) {
  double v = 0.0;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    if (region >= 0 && m.cell_markers[t] != region) continue;
    const auto& tet = m.tetrahedra[t];
    v += signed_volume(m.points[tet[0]], m.points[tet[1]], m.points[tet[2]], m.points[tet[3]]);
  }
  return v;
}

// Volume enclosed by a closed, outward-oriented triangle surface (divergence theorem).
double enclosed_volume(const SurfaceMesh& s) {
  return molmesh::enclosed_volume(s.points, s.triangles);
}

// Every face of every tet is shared by exactly one other tet or is listed as a boundary
// face (conformity), and listed boundary faces point away from their tet.
void expect_conforming(const TetMesh& m) {
  std::map<std::array<int, 3>, int> count;
  for (const auto& t : m.tetrahedra) {
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  }
  std::size_t single = 0;
  for (const auto& [f, c] : count) {
    ASSERT_LE(c, 2);
    if (c == 1) ++single;
  }
  std::size_t listed_single = 0;
  for (const auto& f : m.boundary_faces) {
    std::array<int, 3> s{f[0], f[1], f[2]};
    std::sort(s.begin(), s.end());
    ASSERT_TRUE(count.count(s)) << "boundary face is not a tet face";
    if (count[s] == 1) ++listed_single;
  }
  EXPECT_EQ(single, listed_single) << "every outer face must be listed once";
}

TEST(Tetrahedralize, InteriorOfIonHasAtomAsNodeAndKeepsSurface) {
  const SurfaceMesh ion = icosphere(Vec3(1, 2, 3), 3.0, 2);
  const Atoms atoms = atoms_at({Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(2, 2, 3)});
  TetMeshOptions o;
  o.domain = Domain::interior;
  TetMeshReport r;
  const TetMesh m = tetrahedralize(ion, atoms, o, {}, &r);
  EXPECT_EQ(r.atoms_given, 3u);
  EXPECT_EQ(r.coincident_atoms, 1u);
  EXPECT_EQ(r.atoms_as_nodes, 2u);
  EXPECT_EQ(r.atoms_outside, 0u);
  EXPECT_EQ(r.surface_steiner_points, 0u);
  EXPECT_EQ(r.outer_radius, 0.0);
  ASSERT_FALSE(m.tetrahedra.empty());
  for (int c : m.cell_markers) EXPECT_EQ(c, kMoleculeRegion);
  EXPECT_EQ(m.boundary_faces.size(), ion.triangles.size());
  for (int f : m.boundary_face_markers) EXPECT_EQ(f, kMolecularSurface);
  EXPECT_NEAR(total_volume(m), enclosed_volume(ion), 1e-9 * enclosed_volume(ion));
  const TetStats s = compute_tet_stats(m);
  EXPECT_GT(s.min_volume, 0.0);
  EXPECT_EQ(s.inverted_or_flat, 0u);
  EXPECT_EQ(s.vertices_per_marker.at(kMolecularSurface), ion.points.size());
  expect_conforming(m);
  bool found = false;
  for (const auto& p : m.points) found = found || p == Vec3(2, 2, 3);
  EXPECT_TRUE(found);
  // Boundary faces point away from the centre (outward from the molecule).
  for (const auto& f : m.boundary_faces) {
    const Vec3 n = (m.points[f[1]] - m.points[f[0]]).cross(m.points[f[2]] - m.points[f[0]]);
    EXPECT_GT(n.dot(m.points[f[0]] - Vec3(1, 2, 3)), 0.0);
  }
}

TEST(Tetrahedralize, ExteriorFillsTheShellToTheOuterSphere) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o;
  o.domain = Domain::exterior;
  o.outer_radius = 20.0;
  TetMeshReport r;
  const TetMesh m = tetrahedralize(ion, atoms_at({Vec3::Zero()}), o, {}, &r);
  EXPECT_EQ(r.outer_radius, 20.0);
  EXPECT_EQ(r.atoms_as_nodes, 0u);  // the molecule is not meshed
  for (int c : m.cell_markers) EXPECT_EQ(c, kSolventRegion);
  const SurfaceMesh outer = icosphere(Vec3::Zero(), 20.0, o.outer_sphere_subdivisions);
  EXPECT_NEAR(total_volume(m), enclosed_volume(outer) - enclosed_volume(ion), 1e-6);
  std::map<int, std::size_t> per_marker;
  for (int f : m.boundary_face_markers) ++per_marker[f];
  EXPECT_EQ(per_marker[kMolecularSurface], ion.triangles.size());
  EXPECT_EQ(per_marker[kOuterSphere], outer.triangles.size());
  EXPECT_EQ(per_marker.size(), 2u);
  expect_conforming(m);
  // Molecular-surface faces of the solvent point into the molecule (out of the solvent).
  for (std::size_t i = 0; i < m.boundary_faces.size(); ++i) {
    const auto& f = m.boundary_faces[i];
    const Vec3 n = (m.points[f[1]] - m.points[f[0]]).cross(m.points[f[2]] - m.points[f[0]]);
    const double radial = n.dot(m.points[f[0]]);
    if (m.boundary_face_markers[i] == kMolecularSurface) {
      EXPECT_LT(radial, 0.0);
    } else {
      EXPECT_GT(radial, 0.0);
    }
  }
}

TEST(Tetrahedralize, FullMeshHasBothRegionsAndAnInterface) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o;
  o.outer_radius = 20.0;
  o.active_site = {Sphere{Vec3(3, 0, 0), 1.6}};
  TetMeshReport r;
  const TetMesh m = tetrahedralize(ion, atoms_at({Vec3::Zero()}), o, {}, &r);
  EXPECT_EQ(r.atoms_as_nodes, 1u);
  const SurfaceMesh outer = icosphere(Vec3::Zero(), 20.0, o.outer_sphere_subdivisions);
  EXPECT_NEAR(total_volume(m, kMoleculeRegion), enclosed_volume(ion), 1e-9);
  EXPECT_NEAR(total_volume(m, kSolventRegion), enclosed_volume(outer) - enclosed_volume(ion), 1e-6);
  std::map<int, std::size_t> per_marker;
  for (int f : m.boundary_face_markers) ++per_marker[f];
  EXPECT_GT(per_marker[kActiveSite], 0u);
  EXPECT_EQ(per_marker[kMolecularSurface] + per_marker[kActiveSite], ion.triangles.size());
  EXPECT_EQ(per_marker[kOuterSphere], outer.triangles.size());
  EXPECT_EQ(per_marker.count(kNoMarker), 0u);
  for (std::size_t i = 0; i < m.boundary_faces.size(); ++i) {
    if (m.boundary_face_markers[i] != kActiveSite) continue;
    for (int v : m.boundary_faces[i]) {
      EXPECT_TRUE(o.active_site[0].contains(m.points[v]));
      EXPECT_EQ(m.vertex_markers[v], kActiveSite);
    }
  }
  expect_conforming(m);
}

TEST(Tetrahedralize, CavityIsSolventNotMolecule) {
  // A hollow ball: outer surface outward, cavity surface pointing into the cavity.
  SurfaceMesh shell = icosphere(Vec3::Zero(), 6.0, 2);
  SurfaceMesh cavity = icosphere(Vec3::Zero(), 2.5, 1);
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);  // facing into the cavity
  testing::append_surface(shell, cavity);
  const Atoms atoms = atoms_at({Vec3(4.2, 0, 0), Vec3(-4.2, 0, 0), Vec3(0, 0, 0)});

  TetMeshOptions o;
  o.domain = Domain::interior;
  TetMeshReport r;
  const TetMesh inner = tetrahedralize(shell, atoms, o, {}, &r);
  EXPECT_NEAR(total_volume(inner), enclosed_volume(shell), 1e-9);
  EXPECT_EQ(r.atoms_as_nodes, 2u);
  EXPECT_EQ(r.atoms_outside, 1u);  // the one in the cavity
  EXPECT_EQ(inner.boundary_faces.size(), shell.triangles.size());

  o.domain = Domain::full;
  o.outer_radius = 30.0;
  const TetMesh full = tetrahedralize(shell, atoms, o, {}, &r);
  EXPECT_NEAR(total_volume(full, kMoleculeRegion), enclosed_volume(shell), 1e-9);
  EXPECT_NEAR(total_volume(full, kSolventRegion),
              enclosed_volume(icosphere(Vec3::Zero(), 30.0, 3)) - enclosed_volume(shell), 1e-6);
  expect_conforming(full);
}

TEST(Tetrahedralize, TwoSeparateSpheresAreBothMolecule) {
  SurfaceMesh two = icosphere(Vec3(-5, 0, 0), 2.0, 2);
  testing::append_surface(two, icosphere(Vec3(5, 0, 0), 2.0, 2));
  TetMeshOptions o;
  o.sphere_ratio = 4.0;  // size 5 Å (atoms at ±5) → radius 20 Å
  TetMeshReport r;
  const TetMesh m = tetrahedralize(two, atoms_at({Vec3(-5, 0, 0), Vec3(5, 0, 0)}), o, {}, &r);
  EXPECT_DOUBLE_EQ(r.molecule_size, 5.0);
  EXPECT_DOUBLE_EQ(r.outer_radius, 20.0);
  EXPECT_EQ(r.atoms_as_nodes, 2u);
  EXPECT_NEAR(total_volume(m, kMoleculeRegion), enclosed_volume(two), 1e-9);
}

TEST(Tetrahedralize, RejectsBadInputWithActionableErrors) {
  SurfaceMesh open = icosphere(Vec3::Zero(), 3.0, 1);
  open.triangles.pop_back();
  TetMeshOptions o;
  o.domain = Domain::interior;
  EXPECT_THROW(tetrahedralize(open, {}, o), Error);
  EXPECT_THROW(tetrahedralize(SurfaceMesh{}, {}, o), Error);

  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 1);
  o.domain = Domain::exterior;
  // A single atom has size 0: the ratio cannot size the sphere.
  try {
    tetrahedralize(ion, atoms_at({Vec3::Zero()}), o);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    // The library's own option name; the CLI says --outer-radius (option_spelling.cpp).
    EXPECT_NE(std::string(e.what()).find("`outer_radius`"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
  o.outer_radius = 2.0;  // inside the ion surface
  EXPECT_THROW(tetrahedralize(ion, atoms_at({Vec3::Zero()}), o), Error);
}

// surface_size_ratio sets the size field at the molecular surface, in mean edge lengths of
// each vertex's star. Inside the molecule nothing else sizes the mesh, so a smaller ratio
// must refine the interior and the tetrahedra along the surface. (In a small ion's solvent
// the far-field law, 0.09 r there, is finer than either ratio.)
TEST(Tetrahedralize, SurfaceSizeRatioRefinesAlongTheSurface) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 3);
  auto mean_edge_at_surface = [](const TetMesh& mesh) {
    double total = 0.0;
    std::size_t count = 0;
    for (const auto& t : mesh.tetrahedra) {
      bool touches_surface = false;
      for (int v : t) touches_surface = touches_surface || mesh.vertex_markers[v] != kNoMarker;
      if (!touches_surface) continue;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b, ++count)
          total += (mesh.points[t[a]] - mesh.points[t[b]]).norm();
    }
    return total / static_cast<double>(count);
  };
  TetMeshOptions o;
  o.domain = Domain::interior;
  const TetMesh coarse = tetrahedralize(ion, {}, o);
  o.surface_size_ratio = 0.6;
  const TetMesh fine = tetrahedralize(ion, {}, o);
  EXPECT_GT(fine.tetrahedra.size(), 3 * coarse.tetrahedra.size());
  EXPECT_LT(mean_edge_at_surface(fine), 0.85 * mean_edge_at_surface(coarse));
}

TEST(Tetrahedralize, VolumeBoundAndExpertSwitches) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o;
  o.domain = Domain::interior;
  const TetMesh coarse = tetrahedralize(ion, {}, o);
  o.max_volume = 0.05;
  TetMeshReport r;
  const TetMesh fine = tetrahedralize(ion, {}, o, {}, &r);
  EXPECT_NE(r.tetgen_switches.find("a0.05"), std::string::npos);
  EXPECT_GT(fine.tetrahedra.size(), coarse.tetrahedra.size());
  // With Y, tets touching the preserved surface may stay above the bound; the rest obey (TetGen's
  // final smoothing may push a few slightly over).
  std::size_t over = 0;
  for (const auto& t : fine.tetrahedra) {
    bool touches_surface = false;
    for (int v : t) touches_surface = touches_surface || fine.vertex_markers[v] != kNoMarker;
    if (!touches_surface && signed_volume(fine.points[t[0]], fine.points[t[1]], fine.points[t[2]],
                                          fine.points[t[3]]) > 0.05 * (1 + 1e-9))
      ++over;
  }
  EXPECT_LE(over, fine.tetrahedra.size() / 100) << over << " of " << fine.tetrahedra.size();
  EXPECT_EQ(r.surface_steiner_points, 0u);

  o = {};
  o.domain = Domain::interior;
  o.tetgen_switches = "pYq1.2";
  const TetMesh expert = tetrahedralize(ion, {}, o, {}, &r);
  EXPECT_EQ(r.tetgen_switches.substr(0, 6), "pYq1.2");
  EXPECT_NEAR(total_volume(expert), enclosed_volume(ion), 1e-9);
  EXPECT_LE(compute_tet_stats(expert).max_radius_edge, 1.2 * 1.05);
}

}  // namespace
}  // namespace molmesh
