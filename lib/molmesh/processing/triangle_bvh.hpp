#pragma once
// The triangles of a surface in the geometry kernel's box index: nearest-point queries (the
// dislocation metric) and box-overlap queries (the self-intersection check). Built once,
// read-only afterwards, so queries may run concurrently.
#include <functional>

#include "molmesh/core/geometry.hpp"
#include "molmesh/geometry/box_index.hpp"
#include "molmesh/geometry/closest_point.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

class TriangleBvh {
 public:
  // Keeps a reference to `mesh`, which must outlive the BVH and not change.
  explicit TriangleBvh(const SurfaceMesh& mesh);

  struct Nearest {
    double distance = 0;
    int triangle = -1;
    Vec3 point = Vec3::Zero();
  };
  // The closest point of the surface to p (triangle -1 for an empty mesh); ties go to the
  // lower triangle index.
  Nearest nearest(const Vec3& p) const;

  // Calls visit(triangle) for every triangle whose bounding box overlaps `box`.
  void overlapping(const Box3& box, const std::function<void(int)>& visit) const {
    index_.overlapping(box, visit);
  }

  const SurfaceMesh& mesh() const { return mesh_; }

 private:
  Vec3 closest(int triangle, const Vec3& p) const;

  const SurfaceMesh& mesh_;
  BoxIndex index_;
};

}  // namespace molmesh
