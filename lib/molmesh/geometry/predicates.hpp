#pragma once
// Orientation and intersection predicates on plain points (the geometry kernel; see
// docs/architecture.md, "Geometry kernel"). Floating point, no exact arithmetic: each
// predicate states how it treats touching and near-degenerate contacts.
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Six times the signed volume of tetrahedron (a, b, c, d): > 0 when d lies on the side
// of triangle (a, b, c) its counter-clockwise normal points away from, i.e. when the
// tetrahedron is positively oriented. Computed as (b - a) · ((c - a) × (d - a)).
double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Signed volume of tetrahedron (a, b, c, d) in Å³ (orient3d / 6).
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Volume enclosed by a closed, outward-oriented triangle surface (sum of the signed
// volumes of the tetrahedra from the origin to each triangle); negative for a cavity.
double enclosed_volume(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

// How a segment–triangle test treats contacts that are not proper crossings.
enum class SegmentContact {
  // Only a proper crossing of the open segment through the open triangle counts; touching
  // and coplanar contacts do not (exact signs of orient3d, no tolerance). Used by
  // coarsening, whose caller handles shared vertices and edges itself.
  kProperCrossing,
  // The closed segment against the closed triangle (Möller–Trumbore); a segment within
  // 1e-12 (relative) of parallel to the triangle's plane counts as missing. Used by the
  // self-intersection report.
  kClosed,
};

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                 const Vec3& c, SegmentContact contact);

// Do triangles s and t (vertex indices into `points`) intersect other than along what they
// share? Triangles sharing an edge (two or more vertices) are never reported: a fold
// across an edge is a dihedral-angle question, not an intersection. Triangles sharing one
// vertex intersect when an edge opposite the shared vertex meets the other triangle;
// otherwise when any of the six edges meets the other triangle.
bool triangles_intersect(const std::vector<Vec3>& points, const Triangle& s, const Triangle& t,
                         SegmentContact contact);

}  // namespace molmesh
