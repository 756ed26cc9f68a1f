#include "molmesh/processing/poor_triangle_collapse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "molmesh/geometry/sphere_union.hpp"
#include "molmesh/processing/surface_fidelity.hpp"

namespace molmesh {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

struct AngleRange {
  double smallest = 0.0;  // degrees
  double largest = 0.0;
};

AngleRange angle_range(const Vec3& a, const Vec3& b, const Vec3& c) {
  // atan2 stays accurate near 0° and 180°, where acos of a cosine does not.
  auto at = [](const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 u = q - p, v = r - p;
    return degrees(std::atan2(u.cross(v).norm(), u.dot(v)));
  };
  const double x = at(a, b, c), y = at(b, c, a), z = 180.0 - x - y;
  return {std::min({x, y, z}), std::max({x, y, z})};
}

// One number for a triangle's worst angle: its smallest angle, or half of what its largest
// leaves to 180°, whichever is worse (so 120° counts like 30°).
double quality(const AngleRange& r) { return std::min(r.smallest, (180.0 - r.largest) / 2.0); }

bool is_poor(const AngleRange& r, const PoorTriangleCollapseOptions& options) {
  return r.smallest < options.min_angle_deg || r.largest > options.max_angle_deg;
}

// A planned collapse of u into v: the fan from v that fills u's hole.
struct Collapse {
  int u = -1;
  int v = -1;
  double new_quality = -std::numeric_limits<double>::infinity();
  std::vector<Triangle> fan;
};

class Planner {
 public:
  Planner(const HalfedgeMesh& mesh, const std::vector<int>& valence,
          const PoorTriangleCollapseOptions& options, double mesh_edge)
      : mesh_(mesh),
        valence_(valence),
        options_(options),
        cos_turn_(std::cos(radians(options.max_normal_turn_deg))),
        mesh_edge_(mesh_edge) {}

  // Fills `out` and returns true if collapsing u into v passes every test and raises the
  // quality of u's star by at least min_gain_deg.
  bool plan(int u, int v, Collapse& out) {
    if (in_any(options_.keep_spheres, mesh_.position(u))) return false;
    mesh_.one_ring(u, ring_);
    mesh_.incident_faces(u, faces_);
    const int m = static_cast<int>(ring_.size());
    const int k = static_cast<int>(std::find(ring_.begin(), ring_.end(), v) - ring_.begin());
    if (k == m) return false;
    // Topology: the two vertices opposite the edge lose their edge to u; v gains the other
    // ring vertices (none of which may be its neighbour already) and loses u.
    const int before_v = ring_[(k + m - 1) % m], after_v = ring_[(k + 1) % m];
    if (valence_[before_v] < 4 || valence_[after_v] < 4 || valence_[v] + m - 4 < 3) return false;
    for (int j = 2; j <= m - 2; ++j)
      if (mesh_.has_edge(v, ring_[(k + j) % m])) return false;

    const Vec3& pu = mesh_.position(u);
    const Vec3& pv = mesh_.position(v);
    double mean_edge = 0.0;
    for (int r : ring_) mean_edge += (mesh_.position(r) - pu).norm();
    mean_edge /= m;
    if ((pv - pu).norm() > options_.max_edge_ratio * mean_edge) return false;
    // A tiny star (a sliver's) has a tiny mean edge; the surface may still move by the
    // mesh's own scale, as much as anywhere else.
    const double height_limit = options_.max_height_ratio * std::max(mean_edge, mesh_edge_);

    double old_quality = std::numeric_limits<double>::infinity();
    for (int f : faces_) {
      const Triangle t = mesh_.face_vertices(f);
      old_quality = std::min(
          old_quality,
          quality(angle_range(mesh_.position(t[0]), mesh_.position(t[1]), mesh_.position(t[2]))));
    }
    fan_.clear();
    double new_quality = std::numeric_limits<double>::infinity();
    for (int j = 1; j <= m - 2; ++j) {
      const int a = ring_[(k + j) % m], b = ring_[(k + j + 1) % m];
      const Vec3& pa = mesh_.position(a);
      const Vec3& pb = mesh_.position(b);
      const Vec3 n = (pa - pv).cross(pb - pv);
      const double length = n.norm();
      // The face it replaces is (u, a, b), face (k + j) of u's star.
      const Vec3 old_n = mesh_.face_area_vector(faces_[static_cast<std::size_t>((k + j) % m)]);
      if (!(length > 0) || n.dot(old_n) < cos_turn_ * length * old_n.norm()) return false;
      if (std::abs(n.dot(pu - pv)) / length > height_limit) return false;
      new_quality = std::min(new_quality, quality(angle_range(pv, pa, pb)));
      fan_.push_back({v, a, b});
    }
    if (new_quality < old_quality + options_.min_gain_deg) return false;
    if (new_quality <= out.new_quality) return false;  // a better plan exists already
    if (!centroids_stay_on_surface(mesh_, fan_, options_.project, options_.max_centroid_distance))
      return false;
    out.u = u;
    out.v = v;
    out.new_quality = new_quality;
    out.fan = fan_;
    return true;
  }

 private:
  const HalfedgeMesh& mesh_;
  const std::vector<int>& valence_;
  const PoorTriangleCollapseOptions& options_;
  double cos_turn_;
  double mesh_edge_;  // mean edge length of the whole mesh
  std::vector<int> ring_, faces_;
  std::vector<Triangle> fan_;
};

}  // namespace

bool has_poor_triangle(const SurfaceMesh& mesh, const PoorTriangleCollapseOptions& options) {
  for (const Triangle& t : mesh.triangles) {
    if (is_poor(angle_range(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]), options))
      return true;
  }
  return false;
}

std::size_t collapse_poor_triangles(HalfedgeMesh& mesh,
                                    const PoorTriangleCollapseOptions& options) {
  std::vector<int> valence(static_cast<std::size_t>(mesh.vertex_capacity()), 0);
  for (int v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.vertex_alive(v)) valence[v] = mesh.valence(v);
  // Mean edge length of the mesh (each edge once: the halfedge from the smaller vertex).
  double edge_sum = 0.0;
  long edges = 0;
  for (int f = 0; f < mesh.face_capacity(); ++f) {
    if (!mesh.face_alive(f)) continue;
    const Triangle t = mesh.face_vertices(f);
    for (int i = 0; i < 3; ++i) {
      if (t[i] > t[(i + 1) % 3]) continue;
      edge_sum += (mesh.position(t[i]) - mesh.position(t[(i + 1) % 3])).norm();
      ++edges;
    }
  }
  Planner planner(mesh, valence, options, edges > 0 ? edge_sum / static_cast<double>(edges) : 0.0);
  std::size_t collapsed = 0;
  for (int f = 0; f < mesh.face_capacity(); ++f) {
    // A tetrahedron is the smallest closed mesh; nothing may collapse below it.
    if (mesh.vertex_count() <= 4) break;
    if (!mesh.face_alive(f)) continue;
    const Triangle t = mesh.face_vertices(f);
    if (!is_poor(angle_range(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2])),
                 options))
      continue;
    // Of the six collapses along the triangle's edges, the one that leaves the best star.
    Collapse best;
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      planner.plan(a, b, best);
      planner.plan(b, a, best);
    }
    if (best.u < 0) continue;
    std::vector<int> ring;
    mesh.one_ring(best.u, ring);
    const int m = static_cast<int>(ring.size());
    const int k = static_cast<int>(std::find(ring.begin(), ring.end(), best.v) - ring.begin());
    mesh.remove_vertex(best.u, best.fan);
    // Every ring vertex lost u; all but the two opposite the edge gained v instead.
    --valence[ring[(k + m - 1) % m]];
    --valence[ring[(k + 1) % m]];
    valence[best.v] += m - 4;
    valence[best.u] = 0;
    ++collapsed;
  }
  return collapsed;
}

}  // namespace molmesh
