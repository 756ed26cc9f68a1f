// Locates the centroid of the unit tetrahedron with the solvers' point locator.
#include <cstdio>

#include "solvers/fem/point_locator.hpp"

int main() {
  molmesh::TetMesh tet;
  tet.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.tetrahedra = {{0, 1, 2, 3}};
  const molmesh::solvers::PointLocator locator(tet);
  const auto at = locator.locate({0.25, 0.25, 0.25});
  std::printf("centroid in tetrahedron %d\n", at ? at->tetrahedron : -1);
  return 0;
}
