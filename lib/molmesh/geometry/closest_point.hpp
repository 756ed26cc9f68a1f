#pragma once
// Closest point of a triangle to a point (the geometry kernel; docs/architecture.md).
#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Closest point of triangle (a, b, c) to p, as barycentric weights (all >= 0, sum 1).
// Voronoi-region walk (Ericson, Real-Time Collision Detection §5.1.5); a zero-area
// triangle gives its nearest corner.
Eigen::Vector3d closest_point_barycentric(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c);

// The closest point itself.
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace molmesh
