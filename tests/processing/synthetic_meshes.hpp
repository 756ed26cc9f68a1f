#pragma once
// Small closed meshes built in code for the processing tests: an icosphere (smooth, uniform)
// and a finely gridded box (flat faces meeting at sharp 90° ridges).
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh::test {

inline SurfaceMesh icosphere(int subdivisions, double radius = 1.0) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  SurfaceMesh m;
  m.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.points.push_back(0.5 * (m.points[a] + m.points[b]));
      const int id = static_cast<int>(m.points.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<Triangle> next;
    for (const Triangle& tri : m.triangles) {
      const int a = midpoint(tri[0], tri[1]);
      const int b = midpoint(tri[1], tri[2]);
      const int c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  for (Vec3& p : m.points) p = radius * p.normalized();
  return m;
}

// Axis-aligned box [0,size]^3 with every face an n×n grid of squares split into two
// triangles, alternating the diagonal so valences stay near 6. Outward orientation.
inline SurfaceMesh gridded_box(int n, double size) {
  SurfaceMesh m;
  std::map<std::tuple<long, long, long>, int> ids;
  auto vertex = [&](const Vec3& p) {
    const auto key = std::make_tuple(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6),
                                     std::lround(p.z() * 1e6));
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    m.points.push_back(p);
    const int id = static_cast<int>(m.points.size()) - 1;
    ids.emplace(key, id);
    return id;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = side ? 1.0 : -1.0;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            Vec3 p = Vec3::Zero();
            p[axis] = side * size;
            p[u] = size * a / n;
            p[w] = size * b / n;
            return vertex(p);
          };
          const int p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
          std::array<Triangle, 2> tris =
              ((i + j) % 2 == 0)
                  ? std::array<Triangle, 2>{Triangle{p00, p10, p11}, Triangle{p00, p11, p01}}
                  : std::array<Triangle, 2>{Triangle{p00, p10, p01}, Triangle{p10, p11, p01}};
          for (Triangle tri : tris) {
            const Vec3 nrm =
                (m.points[tri[1]] - m.points[tri[0]]).cross(m.points[tri[2]] - m.points[tri[0]]);
            if (nrm.dot(normal) < 0) std::swap(tri[1], tri[2]);
            m.triangles.push_back(tri);
          }
        }
      }
    }
  }
  return m;
}

inline int euler_characteristic(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const Triangle& t : m.triangles) {
    for (int i = 0; i < 3; ++i) edges[std::minmax(t[i], t[(i + 1) % 3])]++;
  }
  return static_cast<int>(m.points.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(m.triangles.size());
}

}  // namespace molmesh::test
