#include "molmesh/processing/low_valence_removal.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "molmesh/geometry/sphere_union.hpp"
#include "molmesh/processing/edge_flips.hpp"
#include "molmesh/processing/surface_fidelity.hpp"

namespace molmesh {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

int deviation(int valence) { return (valence - 6) * (valence - 6); }

struct Candidate {
  std::array<Triangle, 2> triangles;
  int count = 0;  // 1 for valence 3, 2 for valence 4
  int gain = 0;   // decrease of the sum of squared valence deviations
  double min_angle = 0.0;
};

// Whether the re-triangulation `triangles` of v's hole keeps the surface where it was: every
// new triangle faces like the star, is no sliver, v stays close to its plane and, with a
// projection, its centroid stays close to the surface. The projections come last: they are
// the expensive test.
bool keeps_shape(const HalfedgeMesh& mesh, int v, const Candidate& c, const Vec3& star_normal,
                 double mean_edge, const LowValenceRemovalOptions& options, double& min_angle) {
  const double cos_limit = std::cos(radians(options.max_normal_deviation_deg));
  min_angle = std::numbers::pi;
  for (int i = 0; i < c.count; ++i) {
    const Triangle& t = c.triangles[i];
    const Vec3& a = mesh.position(t[0]);
    const Vec3& b = mesh.position(t[1]);
    const Vec3& d = mesh.position(t[2]);
    const Vec3 n = (b - a).cross(d - a);
    const double length = n.norm();
    if (!(length > 0) || n.dot(star_normal) < cos_limit * length) return false;
    const double height = std::abs(n.dot(mesh.position(v) - a)) / length;
    if (height > options.max_height_ratio * mean_edge) return false;
    min_angle = std::min(min_angle, triangle_min_angle(a, b, d));
  }
  if (min_angle < radians(options.min_new_angle_deg)) return false;
  return centroids_stay_on_surface(mesh, std::span<const Triangle>(c.triangles.data(), c.count),
                                   options.project, options.max_centroid_distance);
}

}  // namespace

std::size_t remove_low_valence_vertices(HalfedgeMesh& mesh,
                                        const LowValenceRemovalOptions& options) {
  std::vector<int> valence(static_cast<std::size_t>(mesh.vertex_capacity()), 0);
  for (int v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.vertex_alive(v)) valence[v] = mesh.valence(v);
  const double cos_limit = std::cos(radians(options.max_normal_deviation_deg));

  std::vector<int> ring, faces;
  std::size_t removed = 0;
  for (int v = 0; v < mesh.vertex_capacity(); ++v) {
    if (!mesh.vertex_alive(v) || valence[v] > 4) continue;
    if (in_any(options.keep_spheres, mesh.position(v))) continue;
    mesh.one_ring(v, ring);
    mesh.incident_faces(v, faces);
    const int m = static_cast<int>(ring.size());

    // The star must be flat: a vertex on a ridge or at a tip carries the shape.
    Vec3 star_normal = Vec3::Zero();
    for (int f : faces) star_normal += mesh.face_area_vector(f);
    const double star_length = star_normal.norm();
    if (!(star_length > 0)) continue;
    star_normal /= star_length;
    bool flat = true;
    for (int f : faces) {
      const Vec3 n = mesh.face_area_vector(f);
      flat = flat && n.dot(star_normal) >= cos_limit * n.norm();
    }
    if (!flat) continue;
    double mean_edge = 0.0;
    for (int r : ring) mean_edge += (mesh.position(r) - mesh.position(v)).norm();
    mean_edge /= m;

    // The candidate re-triangulations of the hole and what each does to the valences (at
    // most two: no allocation per vertex).
    std::array<Candidate, 2> candidates;
    int candidate_count = 0;
    if (m == 3) {
      if (valence[ring[0]] < 4 || valence[ring[1]] < 4 || valence[ring[2]] < 4) continue;
      Candidate c;
      c.triangles[0] = {ring[0], ring[1], ring[2]};
      c.count = 1;
      int before = deviation(3), after = 0;
      for (int r : ring) {
        before += deviation(valence[r]);
        after += deviation(valence[r] - 1);
      }
      c.gain = before - after;
      candidates[candidate_count++] = c;
    } else {
      for (int k = 0; k < 2; ++k) {
        // Diagonal ring[k]-ring[k+2]; ring[k+1] and ring[k+3] lose their edge to v.
        const int a = ring[k], b = ring[k + 1], c2 = ring[k + 2], d = ring[(k + 3) % 4];
        if (valence[b] < 4 || valence[d] < 4 || mesh.has_edge(a, c2)) continue;
        Candidate c;
        c.triangles[0] = {a, b, c2};
        c.triangles[1] = {a, c2, d};
        c.count = 2;
        const int before = deviation(4) + deviation(valence[b]) + deviation(valence[d]);
        const int after = deviation(valence[b] - 1) + deviation(valence[d] - 1);
        c.gain = before - after;
        candidates[candidate_count++] = c;
      }
    }
    const Candidate* best = nullptr;
    for (int i = 0; i < candidate_count; ++i) {
      Candidate& c = candidates[i];
      if (c.gain <= 0) continue;
      if (!keeps_shape(mesh, v, c, star_normal, mean_edge, options, c.min_angle)) continue;
      if (!best || c.gain > best->gain || (c.gain == best->gain && c.min_angle > best->min_angle))
        best = &c;
    }
    if (!best) continue;
    mesh.remove_vertex(v, std::span<const Triangle>(best->triangles.data(), best->count));
    // Valences after the edit: every ring vertex lost v, a diagonal's ends gained each other.
    for (int r : ring) --valence[r];
    if (best->count == 2) {
      ++valence[best->triangles[0][0]];
      ++valence[best->triangles[0][2]];
    }
    valence[v] = 0;
    ++removed;
  }
  return removed;
}

}  // namespace molmesh
