#pragma once
// Finds the tetrahedron containing a point, with its barycentric coordinates: point loads
// (charges) and point evaluation of P1 fields. A uniform bucket grid over the cells'
// bounding boxes keeps each query to a handful of containment tests.
#include <array>
#include <optional>
#include <vector>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::solvers {

struct PointLocation {
  int tetrahedron = -1;
  std::array<double, 4> barycentric{};  // weights of the tetrahedron's four vertices
};

class PointLocator {
 public:
  explicit PointLocator(const TetMesh& mesh);
  // The containing cell (points on shared faces or at vertices get one of their cells),
  // or nothing when the point is outside the mesh by more than a rounding tolerance.
  std::optional<PointLocation> locate(const Vec3& p) const;

 private:
  const TetMesh* mesh_;
  Vec3 lower_ = Vec3::Zero();
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_;  // CSR over buckets
  std::vector<int> cells_;
};

}  // namespace molmesh::solvers
