#include "molmesh/geometry/predicates.hpp"

#include <cmath>

namespace molmesh {
namespace {

bool proper_crossing(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const double dp = orient3d(a, b, c, p);
  const double dq = orient3d(a, b, c, q);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const double s1 = orient3d(p, q, a, b);
  const double s2 = orient3d(p, q, b, c);
  const double s3 = orient3d(p, q, c, a);
  return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

// Möller–Trumbore with the ray parameter limited to the segment.
bool closed_hit(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
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

}  // namespace

double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a));
}

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return orient3d(a, b, c, d) / 6.0;
}

double enclosed_volume(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
  double v = 0;
  for (const Triangle& t : triangles) v += points[t[0]].dot(points[t[1]].cross(points[t[2]]));
  return v / 6.0;
}

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                 const Vec3& c, SegmentContact contact) {
  return contact == SegmentContact::kProperCrossing ? proper_crossing(p, q, a, b, c)
                                                    : closed_hit(p, q, a, b, c);
}

bool triangles_intersect(const std::vector<Vec3>& points, const Triangle& s, const Triangle& t,
                         SegmentContact contact) {
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
  if (shared >= 2) return false;
  auto P = [&](int v) -> const Vec3& { return points[static_cast<std::size_t>(v)]; };
  auto hits = [&](int u, int v, const Triangle& x) {
    return segment_intersects_triangle(P(u), P(v), P(x[0]), P(x[1]), P(x[2]), contact);
  };
  if (shared == 1) {
    return hits(s[(s_shared + 1) % 3], s[(s_shared + 2) % 3], t) ||
           hits(t[(t_shared + 1) % 3], t[(t_shared + 2) % 3], s);
  }
  for (int i = 0; i < 3; ++i) {
    if (hits(s[i], s[(i + 1) % 3], t)) return true;
    if (hits(t[i], t[(i + 1) % 3], s)) return true;
  }
  return false;
}

}  // namespace molmesh
