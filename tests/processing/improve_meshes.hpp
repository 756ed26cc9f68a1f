#pragma once
// Small analytic meshes with known answers for the improve/smoothing/dislocation tests.
#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh::improve_test {

// Icosphere of radius r after `levels` 4:1 subdivisions, points projected on the sphere.
inline SurfaceMesh icosphere(int levels, double r = 1.0, Vec3 center = Vec3::Zero()) {
  SurfaceMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : base) m.points.push_back(Vec3(p[0], p[1], p[2]).normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.points.push_back((m.points[a] + m.points[b]).normalized());
      const int id = static_cast<int>(m.points.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<Triangle> next;
    for (const Triangle& tr : m.triangles) {
      const int a = midpoint(tr[0], tr[1]), b = midpoint(tr[1], tr[2]), c = midpoint(tr[2], tr[0]);
      next.push_back({tr[0], a, c});
      next.push_back({tr[1], b, a});
      next.push_back({tr[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  for (Vec3& p : m.points) p = center + r * p;
  return m;
}

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
