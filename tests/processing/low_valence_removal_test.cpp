#include "molmesh/processing/low_valence_removal.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "processing/molecule_surfaces.hpp"
#include "processing/synthetic_meshes.hpp"

namespace molmesh {
namespace {

// Splits face f of `mesh` at its centroid pushed `height` along the face normal: a new
// vertex of valence 3.
int split_face(SurfaceMesh& mesh, std::size_t f, double height) {
  const Triangle t = mesh.triangles[f];
  const Vec3& a = mesh.points[t[0]];
  const Vec3& b = mesh.points[t[1]];
  const Vec3& c = mesh.points[t[2]];
  const Vec3 n = (b - a).cross(c - a).normalized();
  mesh.points.push_back((a + b + c) / 3.0 + height * n);
  const int v = static_cast<int>(mesh.points.size()) - 1;
  mesh.triangles[f] = {t[0], t[1], v};
  mesh.triangles.push_back({t[1], t[2], v});
  mesh.triangles.push_back({t[2], t[0], v});
  return v;
}

long valence_deviation(const HalfedgeMesh& mesh) {
  long sum = 0;
  for (int v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.vertex_alive(v)) sum += (mesh.valence(v) - 6) * (mesh.valence(v) - 6);
  return sum;
}

TEST(LowValenceRemoval, RemovesAFlatValenceThreeVertexAndNothingElse) {
  // A gridded box has valences 4 to 8 on its ridges but flat faces of valence-6 vertices.
  SurfaceMesh box = test::gridded_box(6, 3.0);
  const std::size_t before = box.points.size();
  const int added = split_face(box, 40, 0.0);
  HalfedgeMesh mesh(box);
  ASSERT_EQ(mesh.valence(added), 3);
  LowValenceRemovalOptions options;
  remove_low_valence_vertices(mesh, options);
  EXPECT_FALSE(mesh.vertex_alive(added));
  EXPECT_NO_THROW(mesh.validate());
  // The box's corners (valence 3 to 6 on 90° ridges) carry the shape and stay.
  const SurfaceStats after = compute_surface_stats(mesh.to_surface_mesh().mesh);
  EXPECT_NEAR(after.volume, 27.0, 1e-9);
  EXPECT_LE(after.vertices, before);
}

TEST(LowValenceRemoval, KeepsASpikeAndAVertexInsideAKeepSphere) {
  SurfaceMesh box = test::gridded_box(6, 3.0);
  const int spike = split_face(box, 40, 0.3);  // far above its face: the shape needs it
  const int flat = split_face(box, 100, 0.0);
  {
    HalfedgeMesh mesh(box);
    remove_low_valence_vertices(mesh);
    EXPECT_TRUE(mesh.vertex_alive(spike));
    EXPECT_FALSE(mesh.vertex_alive(flat));
  }
  HalfedgeMesh mesh(box);
  const Sphere keep{box.points[flat], 0.01};
  LowValenceRemovalOptions options;
  options.keep_spheres = std::span<const Sphere>(&keep, 1);
  remove_low_valence_vertices(mesh, options);
  EXPECT_TRUE(mesh.vertex_alive(flat));
}

// On a real molecule's processed surface (without the removal) every removal lowers the
// valence deviation, keeps the mesh valid and moves no surviving vertex.
TEST(LowValenceRemoval, LowersTheValenceDeviationOfAProcessedMolecule) {
  ProcessingOptions without;
  without.remove_low_valence = false;
  const SurfaceMesh processed =
      process_surface(improve_test::raw_surface("fas2.pqr"), without).mesh;
  HalfedgeMesh mesh(processed);
  int low = 0;
  for (int v = 0; v < mesh.vertex_capacity(); ++v) low += mesh.valence(v) <= 4;
  const long deviation_before = valence_deviation(mesh);
  const std::size_t removed = remove_low_valence_vertices(mesh);
  EXPECT_GT(removed, 0u);
  EXPECT_LE(removed, static_cast<std::size_t>(low));
  EXPECT_LT(valence_deviation(mesh), deviation_before);
  EXPECT_NO_THROW(mesh.validate());
  for (int v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.vertex_alive(v)) continue;
    EXPECT_EQ(mesh.position(v), processed.points[v]);
  }
  const SurfaceStats before = compute_surface_stats(processed);
  const SurfaceStats after = compute_surface_stats(mesh.to_surface_mesh().mesh);
  EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
  EXPECT_NEAR(after.volume, before.volume, 1e-3 * before.volume);
}

}  // namespace
}  // namespace molmesh
