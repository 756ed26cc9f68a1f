#pragma once
// What a reader hands back must be usable downstream: finite numbers, indices in range,
// marker arrays empty or one per item. A violation is a silent misread: abort.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh::fuzz {

inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: reader returned bad data: %s\n", what);
  std::abort();
}

template <class Cells>
void check_cells(const Cells& cells, std::size_t points) {
  for (const auto& c : cells)
    for (const int v : c) require(v >= 0 && static_cast<std::size_t>(v) < points, "index range");
}

inline void check_points(const std::vector<Vec3>& points) {
  for (const Vec3& p : points) require(p.allFinite(), "finite point");
}

inline void check(const SurfaceMesh& m) {
  check_points(m.points);
  check_cells(m.triangles, m.points.size());
  require(m.vertex_markers.empty() || m.vertex_markers.size() == m.points.size(), "vertex markers");
  require(m.face_markers.empty() || m.face_markers.size() == m.triangles.size(), "face markers");
}

inline void check(const TetMesh& m) {
  check_points(m.points);
  check_cells(m.tetrahedra, m.points.size());
  check_cells(m.boundary_faces, m.points.size());
  require(m.cell_markers.empty() || m.cell_markers.size() == m.tetrahedra.size(), "cell markers");
  require(m.vertex_markers.empty() || m.vertex_markers.size() == m.points.size(), "vertex markers");
  require(m.boundary_face_markers.size() == m.boundary_faces.size(), "face markers");
}

inline void check(const Grid& g) {
  require(g.dims[0] > 0 && g.dims[1] > 0 && g.dims[2] > 0, "grid dims");
  require(g.values.size() == g.size(), "grid size");
  require(g.origin.allFinite() && g.spacing.allFinite(), "grid geometry");
  for (const double v : g.values) require(std::isfinite(v), "finite grid value");
}

inline void check(const Atoms& atoms) {
  for (const Atom& a : atoms) {
    require(a.center.allFinite(), "finite atom centre");
    require(std::isfinite(a.charge), "finite charge");
    require(std::isfinite(a.radius) && a.radius >= 0.0, "radius");
  }
}

}  // namespace molmesh::fuzz
