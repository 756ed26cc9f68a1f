#include "molmesh/processing/halfedge_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "molmesh/core/error.hpp"
#include "processing/synthetic_meshes.hpp"

namespace molmesh {
namespace {

TEST(HalfedgeMesh, BuildsAndRoundTripsAnIcosphere) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 2);
  HalfedgeMesh mesh(sphere);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_EQ(mesh.vertex_count(), 162);
  EXPECT_EQ(mesh.face_count(), 320);
  const auto compact = mesh.to_surface_mesh();
  EXPECT_EQ(compact.mesh.points.size(), sphere.points.size());
  ASSERT_EQ(compact.mesh.triangles.size(), sphere.triangles.size());
  for (std::size_t f = 0; f < sphere.triangles.size(); ++f) {
    EXPECT_EQ(compact.mesh.triangles[f], sphere.triangles[f]);
  }
}

TEST(HalfedgeMesh, OneRingIsOrderedCounterClockwise) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 1);
  HalfedgeMesh mesh(sphere);
  std::vector<int> ring;
  for (int v = 0; v < mesh.vertex_capacity(); ++v) {
    mesh.one_ring(v, ring);
    ASSERT_GE(ring.size(), 5u);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec3 a = mesh.position(ring[i]) - mesh.position(v);
      const Vec3 b = mesh.position(ring[(i + 1) % ring.size()]) - mesh.position(v);
      // Counter-clockwise seen from outside: the fan normal points away from the centre.
      EXPECT_GT(a.cross(b).dot(mesh.position(v)), 0.0);
    }
  }
}

TEST(HalfedgeMesh, KRingGrowsByDistance) {
  HalfedgeMesh mesh(icosphere(Vec3::Zero(), 1.0, 3));
  RingScratch scratch;
  std::vector<int> one, two;
  mesh.k_ring(0, 1, scratch, one);
  mesh.k_ring(0, 2, scratch, two);
  EXPECT_EQ(one.size(), 6u);   // vertex 0 is an original icosahedron corner: valence 5
  EXPECT_EQ(two.size(), 16u);  // 1 + 5 + 10
  EXPECT_EQ(two.front(), 0);
  EXPECT_TRUE(std::equal(one.begin(), one.end(), two.begin()));
}

TEST(HalfedgeMesh, RejectsOpenAndNonManifoldInput) {
  SurfaceMesh open = icosphere(Vec3::Zero(), 1.0, 1);
  open.triangles.pop_back();
  EXPECT_THROW(HalfedgeMesh{open}, Error);

  SurfaceMesh flipped = icosphere(Vec3::Zero(), 1.0, 1);
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_THROW(HalfedgeMesh{flipped}, Error);

  // Two tetrahedra sharing one vertex: a pinched (non-manifold) vertex.
  SurfaceMesh pinched;
  pinched.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  pinched.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                       {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
  EXPECT_THROW(HalfedgeMesh{pinched}, Error);

  SurfaceMesh bad_index = icosphere(Vec3::Zero(), 1.0, 0);
  bad_index.triangles[0][0] = 99;
  EXPECT_THROW(HalfedgeMesh{bad_index}, Error);
}

TEST(HalfedgeMesh, FlipKeepsInvariantsAndRefusesDuplicateEdges) {
  HalfedgeMesh mesh(icosphere(Vec3::Zero(), 1.0, 2));
  const int h = 0;
  const int c = mesh.head(HalfedgeMesh::next(h));
  const int d = mesh.head(HalfedgeMesh::next(mesh.twin(h)));
  ASSERT_TRUE(mesh.can_flip(h));
  mesh.flip_edge(h);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_TRUE(mesh.has_edge(c, d));
  EXPECT_EQ(mesh.face_count(), 320);
  // Flipping the new edge restores the old one; flipping it twice more is still valid.
  const int back = mesh.find_halfedge(c, d);
  mesh.flip_edge(back);
  EXPECT_NO_THROW(mesh.validate());

  // On a tetrahedron every flip would duplicate an edge (and drop a valence to 2).
  SurfaceMesh tetra;
  tetra.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  HalfedgeMesh small(tetra);
  for (int e = 0; e < 12; ++e) {
    EXPECT_FALSE(small.can_flip(e));
    EXPECT_THROW(small.flip_edge(e), Error);
  }
  EXPECT_NO_THROW(small.validate());
}

TEST(HalfedgeMesh, RemoveVertexFillsTheHoleAndCompacts) {
  const SurfaceMesh sphere = icosphere(Vec3::Zero(), 1.0, 2);
  HalfedgeMesh mesh(sphere);
  const int v = 100;
  std::vector<int> ring;
  mesh.one_ring(v, ring);
  ASSERT_EQ(ring.size(), 6u);
  // Fan triangulation from ring[0]: (r0, ri, ri+1).
  std::vector<Triangle> fill;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) fill.push_back({ring[0], ring[i], ring[i + 1]});
  mesh.remove_vertex(v, fill);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_EQ(mesh.vertex_count(), 161);
  EXPECT_EQ(mesh.face_count(), 318);
  const auto compact = mesh.to_surface_mesh();
  EXPECT_EQ(compact.old_to_new[v], -1);
  EXPECT_EQ(compact.new_to_old.size(), 161u);
  for (std::size_t i = 0; i < compact.new_to_old.size(); ++i) {
    EXPECT_EQ(compact.mesh.points[i], sphere.points[compact.new_to_old[i]]);
  }
  EXPECT_EQ(test::euler_characteristic(compact.mesh), 2);

  // A filling that reuses an existing edge (or a wrong count) is refused, mesh unchanged.
  const int w = 120;
  mesh.one_ring(w, ring);
  std::vector<Triangle> wrong(fill.begin(), fill.begin() + 1);
  EXPECT_THROW(mesh.remove_vertex(w, wrong), Error);
  EXPECT_NO_THROW(mesh.validate());
  EXPECT_EQ(mesh.vertex_count(), 161);
}

}  // namespace
}  // namespace molmesh
