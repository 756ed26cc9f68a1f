// The paper's floors on real molecules: interior and full meshes of the processed
// surfaces of 1a1p, fas2 and mAChE succeed with the surface untouched (no Steiner points,
// every surface triangle a mesh face) and every atom centre a node of the molecule.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <iostream>
#include <set>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh {
namespace {

using Key = std::array<long long, 3>;
Key key(const Vec3& p) {
  return {std::llround(p.x() * 1e6), std::llround(p.y() * 1e6), std::llround(p.z() * 1e6)};
}

class Molecule : public ::testing::TestWithParam<const char*> {};

TEST_P(Molecule, InteriorAndFullMeshesKeepSurfaceAndAtoms) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + GetParam());
  BlurOptions blur;  // the paper's parameters: B = -0.5, 0.5 Å, isovalue 1
  const SurfaceMesh raw = marching_cubes(blur_atoms(atoms, blur), 1.0);
  const SurfaceMesh surface = process_surface(raw, ProcessingOptions{}).mesh;
  std::set<Key> distinct_atoms;
  for (const auto& a : atoms) distinct_atoms.insert(key(a.center));

  for (Domain domain : {Domain::interior, Domain::full}) {
    TetMeshOptions o;
    o.domain = domain;
    TetMeshReport r;
    const TetMesh m = tetrahedralize(surface, atoms, o, {}, &r);
    const TetStats s = compute_tet_stats(m);
    std::cout << GetParam() << (domain == Domain::interior ? " interior" : " full") << ": surface "
              << surface.points.size() << " vertices, mesh " << s.vertices << " vertices, "
              << s.tetrahedra << " tets, TetGen " << r.seconds << " s, dihedral ["
              << s.min_dihedral_deg << ", " << s.max_dihedral_deg << "]\n";
    EXPECT_EQ(r.surface_steiner_points, 0u);
    EXPECT_EQ(r.atoms_outside, 0u);
    EXPECT_EQ(r.atoms_as_nodes + r.coincident_atoms, atoms.size());
    EXPECT_EQ(r.atoms_as_nodes, distinct_atoms.size());
    EXPECT_GT(s.min_volume, 0.0);
    EXPECT_EQ(s.inverted_or_flat, 0u);
    // Every atom centre is a node (checked independently of the report).
    std::set<Key> nodes;
    for (const auto& p : m.points) nodes.insert(key(p));
    for (const auto& k : distinct_atoms) ASSERT_TRUE(nodes.count(k));
    // The molecular surface is exactly the set of molecule-bounding faces.
    std::size_t surface_faces = 0;
    for (int marker : m.boundary_face_markers)
      if (marker == markers::kMolecularSurface) ++surface_faces;
    EXPECT_EQ(surface_faces, surface.triangles.size());
    EXPECT_EQ(s.tets_per_region.count(markers::kMoleculeRegion), 1u);
    if (domain == Domain::full) {
      EXPECT_EQ(s.tets_per_region.count(markers::kSolventRegion), 1u);
      EXPECT_GT(s.faces_per_marker.at(markers::kOuterSphere), 0u);
    } else {
      EXPECT_EQ(s.tets_per_region.size(), 1u);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RealMolecules, Molecule,
                         ::testing::Values("1a1p.pqr", "fas2.pqr", "mache.pqr"),
                         [](const auto& param_info) {
                           std::string n = param_info.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace molmesh
