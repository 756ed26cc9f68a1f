#include "molmesh/processing/improve_angles.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "molmesh/processing/structure_tensor.hpp"
#include "molmesh/processing/vertex_moves.hpp"
#include "molmesh/processing/vertex_normals.hpp"
#include "molmesh/processing/vertex_rings.hpp"

namespace molmesh {
namespace {

// Eq. 4: weighted mean of the projections of x onto the bisecting planes of the angles
// ∠(v_{i-1}, v_i, v_{i+1}); weight d_i + 1 with d_i the cosine of that angle, so sharp
// angles (most sensitive to x) count more.
Vec3 bisector_target(const Vec3& x, std::span<const std::int32_t> ring,
                     const std::vector<Vec3>& points) {
  const std::size_t m = ring.size();
  Vec3 sum = Vec3::Zero();
  double weights = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& vi = points[ring[i]];
    const Vec3 u1 = (points[ring[(i + m - 1) % m]] - vi).normalized();
    const Vec3 u2 = (points[ring[(i + 1) % m]] - vi).normalized();
    // The bisecting plane contains the bisector of the angle and the normal of its plane,
    // so its normal is the direction u1 - u2.
    const Vec3 diff = u1 - u2;
    const double len = diff.norm();
    if (!(len > 1e-12)) continue;
    const Vec3 normal = diff / len;
    const Vec3 projection = x - ((x - vi).dot(normal)) * normal;
    const double w = u1.dot(u2) + 1.0;
    sum += w * projection;
    weights += w;
  }
  return weights > 0 ? Vec3(sum / weights) : x;
}

}  // namespace

void improve_angles(SurfaceMesh& mesh, const ImproveOptions& options, const Reporter& reporter) {
  if (mesh.points.empty() || mesh.triangles.empty() || options.sweeps <= 0) return;
  const VertexAdjacency faces = vertex_faces(mesh);
  const VertexAdjacency rings = ordered_one_rings(mesh, faces);
  const VertexAdjacency neighbours = vertex_neighbours(mesh, faces);
  const auto colours = colour_classes(neighbours);
  const VertexAdjacency tensor_rings = k_rings(mesh, neighbours, std::max(1, options.rings));
  const bool has_frozen = options.frozen.size() == mesh.points.size();

  double mean_edge = 0;
  for (const Triangle& t : mesh.triangles)
    mean_edge += (mesh.points[t[0]] - mesh.points[t[1]]).norm();
  mean_edge /= static_cast<double>(mesh.triangles.size());
  const double tiny_move = 1e-3 * mean_edge;

  MoveLimits limits;
  limits.max_normal_turn_deg = options.max_normal_turn_deg;
  limits.max_halvings = options.max_halvings;
  limits.require_quality = options.require_quality;

  const std::size_t n = mesh.points.size();
  std::vector<std::uint8_t> active(n, 1), moved(n, 0);
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    reporter.progress("improve", static_cast<double>(sweep) / options.sweeps);
    // The tensor is taken at the positions of the sweep start ("at the old position").
    const auto only =
        options.worklist ? std::span<const std::uint8_t>(active) : std::span<const std::uint8_t>();
    const std::vector<StructureTensor> tensors = structure_tensors(mesh, tensor_rings, only);
    const std::vector<Vec3> before = mesh.points;
    sweep_vertices(mesh.points, rings, colours, [&](std::size_t v) -> std::optional<Vec3> {
      if (has_frozen && options.frozen[v]) return std::nullopt;
      if (!active[v]) return std::nullopt;
      const Vec3& x = mesh.points[v];
      const auto ring = rings.of(v);
      const Vec3 delta = bisector_target(x, ring, mesh.points) - x;
      // Eq. 5: filter the move through the tensor's eigenbasis.
      const StructureTensor& t = tensors[v];
      Vec3 filtered = Vec3::Zero();
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = t.eigenvectors.col(k);
        filtered += delta.dot(e) / (1.0 + options.feature_weight * t.eigenvalues[k]) * e;
      }
      if (!(filtered.squaredNorm() > 0)) return std::nullopt;
      return accept_move(x, x + filtered, ring, mesh.points, limits);
    });
    std::size_t significant = 0;
    for (std::size_t v = 0; v < n; ++v) {
      moved[v] = (mesh.points[v] - before[v]).norm() > tiny_move ? 1 : 0;
      significant += moved[v];
    }
    if (options.worklist) {
      for (std::size_t v = 0; v < n; ++v) {
        std::uint8_t a = moved[v];
        for (std::int32_t u : neighbours.of(v)) a |= moved[u];
        active[v] = a;
      }
    }
    if (static_cast<double>(significant) <
        options.converged_fraction * static_cast<double>(mesh.points.size())) {
      break;
    }
  }
  reporter.progress("improve", 1.0);
}

}  // namespace molmesh
