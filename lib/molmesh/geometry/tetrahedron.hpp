#pragma once
// Tetrahedron vocabulary (the geometry kernel; docs/architecture.md): the face table and
// point location by barycentric coordinates, with the one inside tolerance.
#include <Eigen/Core>
#include <array>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Outward faces of a positively oriented tetrahedron, face k opposite vertex k.
inline constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// A point counts as inside a tetrahedron when its smallest barycentric coordinate is at
// least -kInsideTolerance (dimensionless): on shared faces the coordinates never reach
// exactly zero in floating point.
inline constexpr double kInsideTolerance = 1e-9;

// Barycentric coordinates of p in tetrahedron (a, b, c, d) (weights of a, b, c, d; sum 1),
// solved with a partially pivoted LU of the edge matrix.
Eigen::Vector4d tet_barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                                const Vec3& p);

}  // namespace molmesh
