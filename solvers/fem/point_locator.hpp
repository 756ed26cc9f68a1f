#pragma once
// Finds the tetrahedron containing a point, with its barycentric coordinates: point loads
// (charges) and point evaluation of P1 fields. The cells' bounding boxes go into the
// geometry kernel's box index (a bulk-loaded Boost.Geometry R-tree), so a query tests only
// the few cells whose boxes contain the point, however strongly the mesh is graded. (A uniform bucket grid, the
// first version, put thousands of the small cells near a molecule into each bucket of a
// full mesh that reaches 40 molecule sizes out: 3.5 s for fas2's 906 charges.)
#include <array>
#include <memory>
#include <optional>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::solvers {

struct PointLocation {
  int tetrahedron = -1;
  std::array<double, 4> barycentric{};  // weights of the tetrahedron's four vertices
};

class PointLocator {
 public:
  // `mesh` must outlive the locator.
  explicit PointLocator(const TetMesh& mesh);
  ~PointLocator();
  PointLocator(PointLocator&&) noexcept;
  PointLocator& operator=(PointLocator&&) noexcept;

  // The containing cell (points on shared faces or at vertices get one of their cells),
  // or nothing when the point is outside the mesh by more than a rounding tolerance.
  std::optional<PointLocation> locate(const Vec3& p) const;

 private:
  struct Index;
  const TetMesh* mesh_;
  std::unique_ptr<Index> index_;
};

}  // namespace molmesh::solvers
