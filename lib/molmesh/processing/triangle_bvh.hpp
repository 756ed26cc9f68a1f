#pragma once
// A bounding-volume hierarchy over the triangles of a surface: nearest-point queries (the
// dislocation metric) and box-overlap queries (the self-intersection check). Built once,
// read-only afterwards, so queries may run concurrently.
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/geometry/closest_point.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

using Box3 = Eigen::AlignedBox3d;

class TriangleBvh {
 public:
  // Keeps a reference to `mesh`, which must outlive the BVH and not change.
  explicit TriangleBvh(const SurfaceMesh& mesh);

  struct Nearest {
    double distance = 0;
    int triangle = -1;
    Vec3 point = Vec3::Zero();
  };
  // The closest point of the surface to p (triangle -1 for an empty mesh).
  Nearest nearest(const Vec3& p) const;

  // Calls visit(triangle) for every triangle whose bounding box overlaps `box`.
  void overlapping(const Box3& box, const std::function<void(int)>& visit) const;

  const SurfaceMesh& mesh() const { return mesh_; }

 private:
  struct Node {
    Box3 box;
    std::int32_t first = 0;  // leaf: range in order_; inner: index of the left child
    std::int32_t count = 0;  // > 0 for a leaf
  };
  std::int32_t build(std::int32_t begin, std::int32_t end, std::vector<Vec3>& centroids);

  const SurfaceMesh& mesh_;
  std::vector<Node> nodes_;
  std::vector<std::int32_t> order_;
};

}  // namespace molmesh
