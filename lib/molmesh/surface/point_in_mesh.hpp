#pragma once
// Inside/outside queries against a closed, oriented triangle surface (e.g. "is every atom
// centre inside the molecular surface?", region markers). Built once, queried many times.
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

class PointInMesh {
 public:
  explicit PointInMesh(const SurfaceMesh& mesh);

  // Winding number of the surface around p: 1 inside a closed outward-oriented surface,
  // 0 outside, -1 inside a cavity's boundary only, etc. Counted along a ray in +x with
  // signed crossings; a ray through an edge or vertex is nudged deterministically.
  int winding_number(const Vec3& p) const;
  bool inside(const Vec3& p) const { return winding_number(p) > 0; }

 private:
  int count_crossings(double y, double z, double x) const;

  const SurfaceMesh* mesh_;
  double y0_ = 0.0, z0_ = 0.0, cell_ = 1.0;
  int ny_ = 0, nz_ = 0;
  std::vector<int> start_;  // bucket (iy, iz) -> range in items_
  std::vector<int> items_;  // triangle indices whose yz bounding box touches the bucket
};

}  // namespace molmesh
