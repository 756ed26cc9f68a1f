#pragma once
// Small analytic meshes with known answers for the improve/smoothing/dislocation tests.
#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"  // icosphere

namespace molmesh::improve_test {

// Regular planar fan: centre vertex 0 at the origin, `m` rim vertices on the unit circle in
// the z = 0 plane, triangles (0, i, i+1) facing +z.
inline SurfaceMesh planar_fan(int m) {
  SurfaceMesh mesh;
  mesh.points.push_back(Vec3::Zero());
  for (int i = 0; i < m; ++i) {
    const double a = 2 * std::numbers::pi * i / m;
    mesh.points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  for (int i = 0; i < m; ++i) mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % m});
  return mesh;
}

// n×n grid of squares of side h in z = 0, each split along a diagonal, facing +z.
inline SurfaceMesh planar_grid(int n, double h = 1.0) {
  SurfaceMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.points.emplace_back(i * h, j * h, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

// Signed volume enclosed by a closed, outward-oriented mesh.
inline double enclosed_volume(const SurfaceMesh& m) {
  return molmesh::enclosed_volume(m.points, m.triangles);
}

}  // namespace molmesh::improve_test
