#include "molmesh/processing/self_intersection.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "molmesh/processing/triangle_bvh.hpp"

namespace molmesh {
namespace {

// Does the closed segment p→q cross the triangle (a, b, c)? Möller–Trumbore with the ray
// parameter limited to the segment; a segment in the triangle's plane counts as missing.
bool segment_hits_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                           const Vec3& c) {
  const Vec3 dir = q - p;
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 h = dir.cross(e2);
  const double det = e1.dot(h);
  const double scale = e1.norm() * e2.norm() * dir.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return false;
  const double inv = 1.0 / det;
  const Vec3 s = p - a;
  const double u = inv * s.dot(h);
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 qv = s.cross(e1);
  const double v = inv * dir.dot(qv);
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = inv * e2.dot(qv);
  return t >= 0.0 && t <= 1.0;
}

bool triangles_intersect(const SurfaceMesh& mesh, const Triangle& s, const Triangle& t) {
  int shared = 0;
  int s_shared = -1, t_shared = -1;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (s[i] == t[j]) {
        ++shared;
        s_shared = i;
        t_shared = j;
      }
    }
  }
  if (shared >= 2) return false;  // neighbours across an edge (or duplicates): not tested
  const auto& P = mesh.points;
  if (shared == 1) {
    const Vec3& s1 = P[s[(s_shared + 1) % 3]];
    const Vec3& s2 = P[s[(s_shared + 2) % 3]];
    const Vec3& t1 = P[t[(t_shared + 1) % 3]];
    const Vec3& t2 = P[t[(t_shared + 2) % 3]];
    return segment_hits_triangle(s1, s2, P[t[0]], P[t[1]], P[t[2]]) ||
           segment_hits_triangle(t1, t2, P[s[0]], P[s[1]], P[s[2]]);
  }
  for (int i = 0; i < 3; ++i) {
    if (segment_hits_triangle(P[s[i]], P[s[(i + 1) % 3]], P[t[0]], P[t[1]], P[t[2]])) return true;
    if (segment_hits_triangle(P[t[i]], P[t[(i + 1) % 3]], P[s[0]], P[s[1]], P[s[2]])) return true;
  }
  return false;
}

}  // namespace

std::vector<std::pair<int, int>> self_intersections(const SurfaceMesh& mesh) {
  const TriangleBvh bvh(mesh);
  const std::size_t n = mesh.triangles.size();
  std::vector<std::vector<int>> hits(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const Triangle& s = mesh.triangles[i];
    Box3 box(mesh.points[s[0]]);
    box.extend(mesh.points[s[1]]);
    box.extend(mesh.points[s[2]]);
    bvh.overlapping(box, [&](int j) {
      if (static_cast<std::size_t>(j) <= i) return;
      if (triangles_intersect(mesh, s, mesh.triangles[j])) hits[i].push_back(j);
    });
    std::sort(hits[i].begin(), hits[i].end());
  });
  std::vector<std::pair<int, int>> result;
  for (std::size_t i = 0; i < n; ++i) {
    for (int j : hits[i]) result.emplace_back(static_cast<int>(i), j);
  }
  return result;
}

}  // namespace molmesh
