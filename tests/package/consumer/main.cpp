// Reads a closed surface (OFF), reports its size and enclosed volume, and locates its
// centroid in a one-tetrahedron mesh with the solvers' point locator: enough to need
// headers from include/molmesh/ (library and solvers) and to link the installed archives.
#include <cstdio>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "solvers/fem/point_locator.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const molmesh::SurfaceMesh mesh = molmesh::read_surface_mesh(argv[1]);
  const double volume = molmesh::enclosed_volume(mesh.points, mesh.triangles);

  molmesh::TetMesh tet;
  tet.points = mesh.points;
  tet.tetrahedra = {{0, 1, 2, 3}};
  const molmesh::solvers::PointLocator locator(tet);
  const auto at =
      locator.locate((mesh.points[0] + mesh.points[1] + mesh.points[2] + mesh.points[3]) / 4.0);
  std::printf("%zu vertices, %zu triangles, volume %.6f, centroid in tetrahedron %d\n",
              mesh.points.size(), mesh.triangles.size(), volume, at ? at->tetrahedron : -1);
  return 0;
}
