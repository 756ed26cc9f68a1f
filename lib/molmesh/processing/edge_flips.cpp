#include "molmesh/processing/edge_flips.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace molmesh {
namespace {

struct Quad {
  int a, b, c, d;  // edge a-b, opposite corners c (left of a->b) and d (right)
};

Quad quad_of(const HalfedgeMesh& mesh, int h) {
  return {mesh.tail(h), mesh.head(h), mesh.head(HalfedgeMesh::next(h)),
          mesh.head(HalfedgeMesh::next(mesh.twin(h)))};
}

// Smaller minimum angle of the pair before (a,b,c)+(b,a,d) and after (a,d,c)+(d,b,c).
std::pair<double, double> pair_min_angles(const HalfedgeMesh& mesh, const Quad& q) {
  const Vec3& a = mesh.position(q.a);
  const Vec3& b = mesh.position(q.b);
  const Vec3& c = mesh.position(q.c);
  const Vec3& d = mesh.position(q.d);
  return {std::min(triangle_min_angle(a, b, c), triangle_min_angle(b, a, d)),
          std::min(triangle_min_angle(a, d, c), triangle_min_angle(d, b, c))};
}

bool touches_frozen(const Quad& q, std::span<const std::uint8_t> frozen) {
  if (frozen.empty()) return false;
  return frozen[q.a] || frozen[q.b] || frozen[q.c] || frozen[q.d];
}

// Runs sweeps over all edges (each once, from its lower-index halfedge) and flips where
// `wants` says so, calling flipped(q) after each flip; deterministic because slots are
// visited in index order.
template <class Wants, class Flipped>
std::size_t sweep(HalfedgeMesh& mesh, const FlipOptions& options,
                  std::span<const std::uint8_t> frozen, Wants wants, Flipped flipped) {
  std::size_t total = 0;
  for (int pass = 0; pass < options.max_passes; ++pass) {
    std::size_t flips = 0;
    for (int f = 0; f < mesh.face_capacity(); ++f) {
      for (int c = 0; c < 3; ++c) {
        if (!mesh.face_alive(f)) break;
        const int h = 3 * f + c;
        if (mesh.twin(h) < h) continue;
        const Quad q = quad_of(mesh, h);
        if (touches_frozen(q, frozen)) continue;
        if (!wants(q)) continue;
        if (!flip_is_geometrically_safe(mesh, h, options.max_dihedral_deg)) continue;
        mesh.flip_edge(h);
        flipped(q);
        ++flips;
      }
    }
    total += flips;
    if (flips == 0) break;
  }
  return total;
}

}  // namespace

// The smallest angle lies opposite the shortest edge and is at most 60°, so it is
// asin(2·area / (product of the two other edges)): one asin instead of three atan2.
double triangle_min_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const double twice_area = (b - a).cross(c - a).norm();
  double adjacent;
  if (ab <= bc && ab <= ca) {
    adjacent = bc * ca;
  } else if (bc <= ca) {
    adjacent = ab * ca;
  } else {
    adjacent = ab * bc;
  }
  if (!(adjacent > 0)) return 0.0;
  return std::asin(std::min(1.0, twice_area / std::sqrt(adjacent)));
}

bool flip_is_geometrically_safe(const HalfedgeMesh& mesh, int h, double max_dihedral_deg) {
  if (!mesh.can_flip(h)) return false;
  const Quad q = quad_of(mesh, h);
  const Vec3& a = mesh.position(q.a);
  const Vec3& b = mesh.position(q.b);
  const Vec3& c = mesh.position(q.c);
  const Vec3& d = mesh.position(q.d);
  const Vec3 n0 = (b - a).cross(c - a);
  const Vec3 n1 = (a - b).cross(d - b);
  const Vec3 m0 = (d - a).cross(c - a);
  const Vec3 m1 = (b - d).cross(c - d);
  const double l0 = n0.norm(), l1 = n1.norm(), k0 = m0.norm(), k1 = m1.norm();
  const double scale = std::max({(a - b).squaredNorm(), (c - d).squaredNorm()});
  // A new triangle with (almost) no area is a sliver, never an improvement.
  if (!(k0 > 1e-10 * scale && k1 > 1e-10 * scale && l0 > 0 && l1 > 0)) return false;
  const double cos_max = std::cos(max_dihedral_deg * std::numbers::pi / 180.0);
  if (n0.dot(n1) < cos_max * l0 * l1) return false;  // ridge or valley: keep the edge
  if (m0.dot(m1) < cos_max * k0 * k1) return false;
  // The new pair must face the same way as the old one, or the flip folds the surface.
  const Vec3 mean = n0 / l0 + n1 / l1;
  return m0.dot(mean) > 0 && m1.dot(mean) > 0;
}

std::size_t flip_edges_for_angles(HalfedgeMesh& mesh, const FlipOptions& options,
                                  std::span<const std::uint8_t> frozen) {
  const double gain = options.min_gain_deg * std::numbers::pi / 180.0;
  return sweep(
      mesh, options, frozen,
      [&](const Quad& q) {
        const auto [before, after] = pair_min_angles(mesh, q);
        return after > before + gain;
      },
      [](const Quad&) {});
}

std::size_t flip_edges_for_angles(SurfaceMesh& mesh, const FlipOptions& options) {
  HalfedgeMesh editable(mesh);
  const std::size_t flips = flip_edges_for_angles(editable, options);
  // Flips never remove vertices, but unused input vertices are dropped by compaction; map
  // back so the caller's vertex indices stay valid.
  HalfedgeMesh::Compacted compact = editable.to_surface_mesh();
  for (Triangle& t : compact.mesh.triangles) {
    for (int& v : t) v = compact.new_to_old[v];
  }
  mesh.triangles = std::move(compact.mesh.triangles);
  if (!mesh.face_markers.empty()) mesh.face_markers = std::move(compact.mesh.face_markers);
  return flips;
}

std::size_t flip_edges_for_valence(HalfedgeMesh& mesh, const FlipOptions& options,
                                   double min_angle_deg, std::span<const std::uint8_t> frozen) {
  const double floor_angle = min_angle_deg * std::numbers::pi / 180.0;
  // Valences are kept up to date across flips instead of walking four stars per edge
  // (a flip of a-b into c-d takes one edge from a and b and gives one to c and d).
  std::vector<int> valence(static_cast<std::size_t>(mesh.vertex_capacity()), 0);
  for (int v = 0; v < mesh.vertex_capacity(); ++v)
    if (mesh.vertex_alive(v)) valence[v] = mesh.valence(v);
  return sweep(
      mesh, options, frozen,
      [&](const Quad& q) {
        const int va = valence[q.a], vb = valence[q.b];
        const int vc = valence[q.c], vd = valence[q.d];
        auto sq = [](int x) { return (x - 6) * (x - 6); };
        const int before = sq(va) + sq(vb) + sq(vc) + sq(vd);
        const int after = sq(va - 1) + sq(vb - 1) + sq(vc + 1) + sq(vd + 1);
        if (after >= before) return false;
        const auto [angle_before, angle_after] = pair_min_angles(mesh, q);
        return angle_after >= std::min(floor_angle, angle_before);
      },
      [&](const Quad& q) {
        --valence[q.a];
        --valence[q.b];
        ++valence[q.c];
        ++valence[q.d];
      });
}

}  // namespace molmesh
