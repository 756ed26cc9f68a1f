#include "support/structured_meshes.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/hierarchy/transfer.hpp"

namespace molmesh::testing {
namespace {

int vertex_id(int n, int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); }

double orientation(const TetMesh& m, const Tetrahedron& t) {
  const auto P = [&](int k) -> const Vec3& { return m.points[static_cast<std::size_t>(t[k])]; };
  return orient3d(P(0), P(1), P(2), P(3));
}

}  // namespace

TetMesh structured_cube(int n, double lo, double hi) {
  TetMesh mesh;
  const double h = (hi - lo) / n;
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        mesh.points.emplace_back(lo + i * h, lo + j * h, lo + k * h);
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
        mesh.vertex_markers.push_back(boundary ? 2 : 0);
      }
    }
  }
  std::array<int, 3> axes{0, 1, 2};
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        std::sort(axes.begin(), axes.end());
        do {
          std::array<int, 3> c{i, j, k};
          Tetrahedron t{};
          t[0] = vertex_id(n, c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[static_cast<std::size_t>(axes[static_cast<std::size_t>(s)])];
            t[static_cast<std::size_t>(s) + 1] = vertex_id(n, c[0], c[1], c[2]);
          }
          if (orientation(mesh, t) < 0) std::swap(t[2], t[3]);
          mesh.tetrahedra.push_back(t);
          mesh.cell_markers.push_back(2);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
    }
  }
  // Boundary faces: outward faces of a positively oriented tet that occur once.
  mesh.boundary_faces = tet_mesh_boundary(mesh);
  mesh.boundary_face_markers.assign(mesh.boundary_faces.size(), 2);
  return mesh;
}

SurfaceMesh structured_cube_surface(int n, double lo, double hi) {
  const TetMesh cube = structured_cube(n, lo, hi);
  SurfaceMesh surface;
  std::map<int, int> index;
  for (const auto& f : cube.boundary_faces) {
    Triangle t{};
    for (std::size_t c = 0; c < 3; ++c) {
      auto [it, inserted] = index.emplace(f[c], static_cast<int>(surface.points.size()));
      if (inserted) surface.points.push_back(cube.points[static_cast<std::size_t>(f[c])]);
      t[c] = it->second;
    }
    surface.triangles.push_back(t);
  }
  surface.vertex_markers.assign(surface.points.size(), 1);
  surface.face_markers.assign(surface.triangles.size(), 1);
  return surface;
}

void append_surface(SurfaceMesh& mesh, const SurfaceMesh& part) {
  const std::size_t points = mesh.points.size();
  const std::size_t triangles = mesh.triangles.size();
  const int offset = static_cast<int>(points);
  mesh.points.insert(mesh.points.end(), part.points.begin(), part.points.end());
  for (const Triangle& t : part.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const auto join = [](auto& markers, std::size_t count, const auto& more, std::size_t more_count) {
    if (markers.size() == count && more.size() == more_count)
      markers.insert(markers.end(), more.begin(), more.end());
    else
      markers.clear();
  };
  join(mesh.vertex_markers, points, part.vertex_markers, part.points.size());
  join(mesh.face_markers, triangles, part.face_markers, part.triangles.size());
}

}  // namespace molmesh::testing
