// TetMeshOptions::surface_size_ratio sets the size field at the molecular surface (in mean
// edge lengths of each vertex's star). Inside the molecule nothing else sizes the mesh, so
// a smaller ratio must refine the interior and the tetrahedra along the surface. (In the
// solvent of a small ion the far-field law, 0.09 r there, is finer than either ratio.)
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {
namespace {

// Mean edge length of the tetrahedra with a vertex on the ion's surface (|p| = 3 Å).
double mean_edge_at_surface(const TetMesh& mesh) {
  double total = 0.0;
  std::size_t count = 0;
  for (const auto& tet : mesh.tetrahedra) {
    const bool touches = std::any_of(tet.begin(), tet.end(), [&](auto v) {
      return std::abs(mesh.points[static_cast<std::size_t>(v)].norm() - 3.0) < 1e-6;
    });
    if (!touches) continue;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        total += (mesh.points[static_cast<std::size_t>(tet[a])] -
                  mesh.points[static_cast<std::size_t>(tet[b])])
                     .norm();
        ++count;
      }
  }
  return total / static_cast<double>(count);
}

TEST(SurfaceSizeRatio, SmallerRatioRefinesAlongTheSurface) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 3);
  TetMeshOptions options;
  options.domain = Domain::interior;
  const TetMesh coarse = tetrahedralize(ion, {}, options);
  options.surface_size_ratio = 0.6;
  const TetMesh fine = tetrahedralize(ion, {}, options);
  EXPECT_GT(fine.tetrahedra.size(), 3 * coarse.tetrahedra.size());
  EXPECT_LT(mean_edge_at_surface(fine), 0.85 * mean_edge_at_surface(coarse));
}

}  // namespace
}  // namespace molmesh
