#pragma once
// An MCSF file as FETK's own MC reader (Gem_read, the code APBS and SMOL use) sees it:
// counts, orientation, face types and materials.
#include <mc/gem.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <map>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct FetkMesh {
  int vertices = 0;
  int simplices = 0;
  std::map<int, int> boundary_face_types;  // type -> count of (simplex, face) pairs
  std::map<int, int> materials;            // SS_type -> count
  int negative = 0;
  bool read_ok = false;
};

inline FetkMesh read_with_fetk(const std::filesystem::path& path) {
  FetkMesh r;
  Vio_start();
  Gem* gem = Gem_ctor(VNULL, VNULL);
  Vio* sock = Vio_ctor("FILE", "ASC", VNULL, path.c_str(), "r");
  if (sock && Vio_accept(sock, 0) >= 0) {
    r.read_ok = Gem_read(gem, 0, sock) == 1;
    Vio_acceptFree(sock);
  }
  if (sock) Vio_dtor(&sock);
  r.vertices = Gem_numVV(gem);
  r.simplices = Gem_numSS(gem);
  for (int s = 0; s < r.simplices; ++s) {
    SS* simplex = Gem_SS(gem, s);
    ++r.materials[static_cast<int>(SS_type(simplex))];
    for (int f = 0; f < 4; ++f) {
      const int type = static_cast<int>(SS_faceType(simplex, f));
      if (type != 0) ++r.boundary_face_types[type];
    }
    Vec3 p[4];
    for (int v = 0; v < 4; ++v)
      for (int d = 0; d < 3; ++d) p[v][d] = VV_coord(SS_vertex(simplex, v), d);
    if ((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) <= 0.0) ++r.negative;
  }
  Gem_dtor(&gem);
  return r;
}

}  // namespace molmesh
