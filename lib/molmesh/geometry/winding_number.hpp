#pragma once
// Generalised winding number (the geometry kernel's one inside/outside test; see
// docs/architecture.md, "Geometry kernel").
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Solid angle of triangle (a, b, c) seen from q, in steradians, signed by the triangle's
// orientation (Van Oosterom & Strackee).
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q);

// Winding number at q of the triangles (sum of solid angles / 4π): 1 inside a closed
// outward-oriented surface, 0 outside, -1 inside a cavity's (inward-facing) boundary only;
// fractional near an open boundary. Inside means > 0.5.
double winding_number(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                      const Vec3& q);
// The same over the subset `faces` (indices into `triangles`).
double winding_number(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                      const std::vector<int>& faces, const Vec3& q);

}  // namespace molmesh
