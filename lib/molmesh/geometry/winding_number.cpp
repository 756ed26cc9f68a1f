#include "molmesh/geometry/winding_number.hpp"

#include <cmath>
#include <numbers>

namespace molmesh {

double solid_angle(const Vec3& a_in, const Vec3& b_in, const Vec3& c_in, const Vec3& q) {
  const Vec3 a = a_in - q, b = b_in - q, c = c_in - q;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double num = a.dot(b.cross(c));
  const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2.0 * std::atan2(num, den);
}

double winding_number(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                      const Vec3& q) {
  double total = 0.0;
  for (const Triangle& t : triangles)
    total += solid_angle(points[t[0]], points[t[1]], points[t[2]], q);
  return total / (4.0 * std::numbers::pi);
}

double winding_number(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                      const std::vector<int>& faces, const Vec3& q) {
  double total = 0.0;
  for (int f : faces) {
    const Triangle& t = triangles[static_cast<std::size_t>(f)];
    total += solid_angle(points[t[0]], points[t[1]], points[t[2]], q);
  }
  return total / (4.0 * std::numbers::pi);
}

}  // namespace molmesh
