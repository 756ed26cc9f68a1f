// Reads a closed surface and prints its size and enclosed volume.
#include <cstdio>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/io/surface_mesh_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const molmesh::SurfaceMesh mesh = molmesh::read_surface_mesh(argv[1]);
  std::printf("%zu vertices, %zu triangles, volume %.6f\n", mesh.points.size(),
              mesh.triangles.size(), molmesh::enclosed_volume(mesh.points, mesh.triangles));
  return 0;
}
