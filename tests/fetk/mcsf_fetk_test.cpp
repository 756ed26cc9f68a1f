// molmesh's MCSF files read by FETK's own MC reader (Gem_read, the code APBS and SMOL use),
// checking counts, orientation, face types and materials as FETK sees them.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "fetk/fetk_reader.hpp"
#include "molmesh/io/mcsf.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

Atoms one_atom() {
  Atom a;
  a.radius = 3.0;
  a.charge = 1.0;
  return {a};
}

TEST(FetkReader, ReadsMolmeshFullMesh) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o;
  o.outer_radius = 20.0;
  o.active_site = {Sphere{Vec3(0, 0, 3), 1.6}};  // marks faces but they are interior here
  const TetMesh mesh = tetrahedralize(ion, one_atom(), o);
  const auto dir = testing::test_dir();
  const auto path = dir / "full.m";
  write_mcsf(path, mesh);
  FetkMesh fetk = read_with_fetk(path);
  EXPECT_TRUE(fetk.read_ok);
  EXPECT_EQ(fetk.vertices, static_cast<int>(mesh.points.size()));
  EXPECT_EQ(fetk.simplices, static_cast<int>(mesh.tetrahedra.size()));
  EXPECT_EQ(fetk.negative, 0);
  // In a full mesh only the outer sphere is boundary: Dirichlet type 5, one face per
  // sphere triangle.
  ASSERT_EQ(fetk.boundary_face_types.size(), 1u);
  EXPECT_EQ(fetk.boundary_face_types.at(5),
            static_cast<int>(
                icosphere(Vec3::Zero(), 20.0, o.outer_sphere_subdivisions).triangles.size()));
  std::map<int, int> regions;
  for (int c : mesh.cell_markers) ++regions[c];
  EXPECT_EQ(fetk.materials, regions);
  std::filesystem::remove_all(dir);
}

TEST(FetkReader, ReadsMolmeshExteriorMeshWithActiveSite) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o;
  o.domain = Domain::exterior;
  o.outer_radius = 15.0;
  o.active_site = {Sphere{Vec3(0, 0, 3), 1.6}};
  const TetMesh mesh = tetrahedralize(ion, one_atom(), o);
  std::map<int, int> per_marker;
  for (int m : mesh.boundary_face_markers) ++per_marker[m];
  const auto dir = testing::test_dir();
  const auto path = dir / "exterior.m";
  write_mcsf(path, mesh);
  FetkMesh fetk = read_with_fetk(path);
  EXPECT_TRUE(fetk.read_ok);
  EXPECT_EQ(fetk.simplices, static_cast<int>(mesh.tetrahedra.size()));
  EXPECT_EQ(fetk.negative, 0);
  EXPECT_GT(per_marker[markers::kActiveSite], 0);
  EXPECT_EQ(fetk.boundary_face_types[4], per_marker[markers::kMolecularSurface]);
  EXPECT_EQ(fetk.boundary_face_types[3], per_marker[markers::kActiveSite]);
  EXPECT_EQ(fetk.boundary_face_types[5], per_marker[markers::kOuterSphere]);
  EXPECT_EQ(fetk.materials.size(), 1u);
  EXPECT_EQ(fetk.materials.begin()->first, markers::kSolventRegion);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
