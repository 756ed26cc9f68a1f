#include "solvers/fem/p1_assembly.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <string>

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {

TetGeometry tet_geometry(const TetMesh& mesh, std::size_t t) {
  const Tetrahedron& tet = mesh.tetrahedra[t];
  const Vec3& p0 = mesh.points[static_cast<std::size_t>(tet[0])];
  const Vec3 e1 = mesh.points[static_cast<std::size_t>(tet[1])] - p0;
  const Vec3 e2 = mesh.points[static_cast<std::size_t>(tet[2])] - p0;
  const Vec3 e3 = mesh.points[static_cast<std::size_t>(tet[3])] - p0;
  const double det = e1.dot(e2.cross(e3));
  TetGeometry g;
  g.volume = det / 6.0;
  // Rows of the inverse Jacobian are the gradients of barycentric coordinates 1..3.
  g.gradients[1] = e2.cross(e3) / det;
  g.gradients[2] = e3.cross(e1) / det;
  g.gradients[3] = e1.cross(e2) / det;
  g.gradients[0] = -(g.gradients[1] + g.gradients[2] + g.gradients[3]);
  return g;
}

SparseMatrix assemble_stiffness(const TetMesh& mesh, std::span<const double> cell_coefficient) {
  const std::size_t nt = mesh.tetrahedra.size();
  if (cell_coefficient.size() != nt) {
    throw Error("stiffness assembly: " + std::to_string(cell_coefficient.size()) +
                " coefficients for " + std::to_string(nt) + " tetrahedra");
  }
  // Each tetrahedron writes its own 16 slots, so the triplet list (and therefore the
  // summation order inside setFromTriplets) does not depend on the thread count.
  std::vector<Eigen::Triplet<double, int>> triplets(16 * nt);
  std::vector<char> bad(nt, 0);
  tbb::parallel_for(std::size_t{0}, nt, [&](std::size_t t) {
    const TetGeometry g = tet_geometry(mesh, t);
    if (!(g.volume > 0.0) || !std::isfinite(g.volume)) bad[t] = 1;
    const Tetrahedron& tet = mesh.tetrahedra[t];
    const double w = cell_coefficient[t] * g.volume;
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        triplets[16 * t + static_cast<std::size_t>(4 * a + b)] = Eigen::Triplet<double, int>(
            tet[static_cast<std::size_t>(a)], tet[static_cast<std::size_t>(b)],
            w * g.gradients[static_cast<std::size_t>(a)].dot(
                    g.gradients[static_cast<std::size_t>(b)]));
      }
    }
  });
  for (std::size_t t = 0; t < nt; ++t) {
    if (bad[t]) {
      throw Error("stiffness assembly: tetrahedron " + std::to_string(t) +
                  " is inverted or degenerate (non-positive volume); the mesh cannot be used "
                  "for finite elements");
    }
  }
  const auto n = static_cast<int>(mesh.points.size());
  SparseMatrix k(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  return k;
}

std::vector<double> cell_coefficients_by_region(const TetMesh& mesh,
                                                std::span<const std::pair<int, double>> regions) {
  std::vector<double> out(mesh.tetrahedra.size());
  for (std::size_t t = 0; t < out.size(); ++t) {
    const int marker = t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0;
    bool found = false;
    for (const auto& [m, value] : regions) {
      if (m == marker) {
        out[t] = value;
        found = true;
        break;
      }
    }
    if (!found) {
      throw Error("tetrahedron " + std::to_string(t) + " has region marker " +
                  std::to_string(marker) + ", which has no coefficient");
    }
  }
  return out;
}

}  // namespace molmesh::solvers
