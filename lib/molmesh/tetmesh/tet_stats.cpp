#include "molmesh/tetmesh/tet_stats.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "molmesh/geometry/predicates.hpp"
namespace molmesh {

TetStats compute_tet_stats(const TetMesh& mesh) {
  TetStats s;
  s.vertices = mesh.points.size();
  s.tetrahedra = mesh.tetrahedra.size();
  s.boundary_faces = mesh.boundary_faces.size();
  for (int m : mesh.cell_markers) ++s.tets_per_region[m];
  for (int m : mesh.boundary_face_markers) ++s.faces_per_marker[m];
  for (int m : mesh.vertex_markers) ++s.vertices_per_marker[m];
  if (mesh.tetrahedra.empty()) return s;

  constexpr double kInf = std::numeric_limits<double>::infinity();
  s.min_dihedral_deg = kInf;
  s.max_dihedral_deg = -kInf;
  s.min_volume = kInf;
  s.max_volume = -kInf;
  s.min_radius_edge = kInf;
  s.max_radius_edge = -kInf;
  double sum_radius_edge = 0.0;
  const double to_deg = 180.0 / std::numbers::pi;

  for (const auto& t : mesh.tetrahedra) {
    const Vec3& a = mesh.points[t[0]];
    const Vec3& b = mesh.points[t[1]];
    const Vec3& c = mesh.points[t[2]];
    const Vec3& d = mesh.points[t[3]];
    const double vol = signed_volume(a, b, c, d);
    s.min_volume = std::min(s.min_volume, vol);
    s.max_volume = std::max(s.max_volume, vol);
    if (vol <= 0.0) ++s.inverted_or_flat;

    // Outward face normals (face k is opposite vertex k); the dihedral angle along the
    // edge shared by faces k and l is pi minus the angle between their normals.
    const std::array<Vec3, 4> p{a, b, c, d};
    std::array<Vec3, 4> n;
    for (int k = 0; k < 4; ++k) {
      const Vec3& q0 = p[(k + 1) % 4];
      const Vec3& q1 = p[(k + 2) % 4];
      const Vec3& q2 = p[(k + 3) % 4];
      Vec3 nk = (q1 - q0).cross(q2 - q0);
      if (nk.dot(p[k] - q0) > 0.0) nk = -nk;
      const double len = nk.norm();
      n[k] = len > 0.0 ? Vec3(nk / len) : Vec3::Zero();
    }
    for (int k = 0; k < 4; ++k) {
      for (int l = k + 1; l < 4; ++l) {
        const double cosang = std::clamp(n[k].dot(n[l]), -1.0, 1.0);
        const double dihedral = 180.0 - std::acos(cosang) * to_deg;
        s.min_dihedral_deg = std::min(s.min_dihedral_deg, dihedral);
        s.max_dihedral_deg = std::max(s.max_dihedral_deg, dihedral);
        const auto bin =
            std::min<std::size_t>(17, static_cast<std::size_t>(std::max(0.0, dihedral) / 10.0));
        ++s.dihedral_histogram[bin];
      }
    }

    const Vec3 u = b - a, v = c - a, w = d - a;
    const double denom = 2.0 * u.dot(v.cross(w));
    double shortest =
        std::min({u.norm(), v.norm(), w.norm(), (c - b).norm(), (d - b).norm(), (d - c).norm()});
    double ratio = kInf;
    if (denom != 0.0 && shortest > 0.0) {
      const Vec3 centre = (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) +
                           w.squaredNorm() * u.cross(v)) /
                          denom;
      ratio = centre.norm() / shortest;
    }
    s.min_radius_edge = std::min(s.min_radius_edge, ratio);
    s.max_radius_edge = std::max(s.max_radius_edge, ratio);
    sum_radius_edge += ratio;
    std::size_t bin = 0;
    while (bin + 1 < TetStats::kRadiusEdgeBins.size() &&
           ratio >= TetStats::kRadiusEdgeBins[bin + 1])
      ++bin;
    ++s.radius_edge_histogram[bin];
  }
  s.mean_radius_edge = sum_radius_edge / static_cast<double>(mesh.tetrahedra.size());
  return s;
}

}  // namespace molmesh
