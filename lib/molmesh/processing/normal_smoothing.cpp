#include "molmesh/processing/normal_smoothing.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <cmath>

#include "molmesh/geometry/predicates.hpp"
#include "molmesh/processing/vertex_moves.hpp"
#include "molmesh/processing/vertex_normals.hpp"
#include "molmesh/processing/vertex_rings.hpp"

namespace molmesh {

void smooth_normals(SurfaceMesh& mesh, const NormalSmoothingOptions& options,
                    const Reporter& reporter) {
  if (mesh.points.empty() || mesh.triangles.empty()) return;
  const std::size_t nf = mesh.triangles.size();
  const VertexAdjacency faces = vertex_faces(mesh);
  const VertexAdjacency rings = ordered_one_rings(mesh, faces);
  const auto colours = colour_classes(vertex_neighbours(mesh, faces));
  const bool has_frozen = options.frozen.size() == mesh.points.size();
  const double volume_before = enclosed_volume(mesh.points, mesh.triangles);

  // Face areas and normals of the input.
  std::vector<Vec3> normals(nf);
  std::vector<double> areas(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 c =
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]);
    areas[f] = 0.5 * c.norm();
    normals[f] = areas[f] > 0 ? Vec3(c.normalized()) : Vec3::Zero();
  }

  reporter.progress("smooth", 0.0);
  // Anisotropic diffusion of the face normals (Jacobi: each iteration reads the previous).
  const double inv_sigma2 = 1.0 / (options.sigma * options.sigma);
  std::vector<Vec3> next(nf);
  for (int it = 0; it < options.normal_iterations; ++it) {
    tbb::parallel_for(std::size_t{0}, nf, [&](std::size_t f) {
      const Vec3& nfv = normals[f];
      Vec3 sum = areas[f] * nfv;
      for (int v : mesh.triangles[f]) {
        for (std::int32_t g : faces.of(static_cast<std::size_t>(v))) {
          if (static_cast<std::size_t>(g) == f) continue;
          const double d = 1.0 - nfv.dot(normals[g]);
          sum += areas[g] * std::exp(-d * d * inv_sigma2) * normals[g];
        }
      }
      // Faces sharing two vertices with f are visited twice: they share an edge and so
      // rightly weigh more than those touching a corner only.
      const double len = sum.norm();
      next[f] = len > 0 ? Vec3(sum / len) : nfv;
    });
    normals.swap(next);
  }

  // Vertex update towards the smoothed normals; guarded like angle improvement but allowed
  // to lower the angle quality (improve_angles runs next in the pipeline).
  MoveLimits limits;
  limits.max_normal_turn_deg = options.max_normal_turn_deg;
  limits.require_quality = false;
  for (int it = 0; it < options.vertex_iterations; ++it) {
    reporter.progress("smooth", 0.2 + 0.7 * it / std::max(1, options.vertex_iterations));
    sweep_vertices(mesh.points, rings, colours, [&](std::size_t v) -> std::optional<Vec3> {
      if (has_frozen && options.frozen[v]) return std::nullopt;
      const Vec3& x = mesh.points[v];
      Vec3 move = Vec3::Zero();
      double weight = 0;
      for (std::int32_t f : faces.of(v)) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 centroid = (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]]) / 3.0;
        const double a = areas[f] > 0 ? areas[f] : 1e-30;
        move += a * normals[f] * normals[f].dot(centroid - x);
        weight += a;
      }
      if (!(weight > 0)) return std::nullopt;
      return accept_move(x, x + move / weight, rings.of(v), mesh.points, limits);
    });
  }

  if (options.restore_volume) {
    // A uniform offset δ along the unit vertex normals changes the volume by ≈ δ·area.
    for (int it = 0; it < 2; ++it) {
      const double volume = enclosed_volume(mesh.points, mesh.triangles);
      double area = 0;
      for (const Triangle& t : mesh.triangles) {
        area += 0.5 * (mesh.points[t[1]] - mesh.points[t[0]])
                          .cross(mesh.points[t[2]] - mesh.points[t[0]])
                          .norm();
      }
      if (!(area > 0)) break;
      const double delta = (volume_before - volume) / area;
      const std::vector<Vec3> vn = vertex_normals(mesh);
      for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        if (has_frozen && options.frozen[v]) continue;
        mesh.points[v] += delta * vn[v];
      }
    }
  }
  reporter.progress("smooth", 1.0);
}

}  // namespace molmesh
