#include "molmesh/processing/vertex_moves.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

namespace molmesh {

std::vector<std::vector<std::int32_t>> colour_classes(const VertexAdjacency& neighbours) {
  const std::size_t n = neighbours.vertex_count();
  std::vector<int> colour(n, -1);
  std::vector<std::vector<std::int32_t>> classes;
  std::vector<char> used;
  for (std::size_t v = 0; v < n; ++v) {
    used.assign(classes.size() + 1, 0);
    for (std::int32_t u : neighbours.of(v)) {
      if (colour[u] >= 0) used[colour[u]] = 1;
    }
    int c = 0;
    while (used[c]) ++c;
    colour[v] = c;
    if (static_cast<std::size_t>(c) == classes.size()) classes.emplace_back();
    classes[c].push_back(static_cast<std::int32_t>(v));
  }
  return classes;
}

AngleCosines triangle_angle_cosines(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const double lab2 = ab.squaredNorm(), lbc2 = bc.squaredNorm(), lca2 = ca.squaredNorm();
  if (!(lab2 > 0 && lbc2 > 0 && lca2 > 0)) return {1.0, 1.0};
  const double ca_ = -ca.dot(ab) / std::sqrt(lca2 * lab2);  // cosine of the angle at a
  const double cb = -ab.dot(bc) / std::sqrt(lab2 * lbc2);   // at b
  const double cc = -bc.dot(ca) / std::sqrt(lbc2 * lca2);   // at c
  return {std::clamp(std::max({ca_, cb, cc}), -1.0, 1.0),
          std::clamp(std::min({ca_, cb, cc}), -1.0, 1.0)};
}

double triangle_quality_cos(const Vec3& a, const Vec3& b, const Vec3& c) {
  const AngleCosines cosines = triangle_angle_cosines(a, b, c);
  if (cosines.largest == 1.0) return 1.0;  // degenerate
  // (180° - θmax)/2 has cosine sqrt((1 - cos θmax)/2) (half-angle formula), so the quality
  // min(θmin, (180° - θmax)/2) is the arccosine of the larger of the two cosines.
  return std::max(cosines.smallest, std::sqrt(0.5 * (1.0 - cosines.largest)));
}

double triangle_quality_deg(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::acos(triangle_quality_cos(a, b, c)) * 180.0 / std::numbers::pi;
}

double star_quality_cos(const Vec3& x, std::span<const std::int32_t> ring,
                        const std::vector<Vec3>& points) {
  double q = -1.0;
  const std::size_t m = ring.size();
  for (std::size_t i = 0; i < m; ++i) {
    q = std::max(q, triangle_quality_cos(x, points[ring[i]], points[ring[(i + 1) % m]]));
  }
  return q;
}

double star_quality_deg(const Vec3& x, std::span<const std::int32_t> ring,
                        const std::vector<Vec3>& points) {
  return std::acos(star_quality_cos(x, ring, points)) * 180.0 / std::numbers::pi;
}

namespace {

// What the move test needs of the star before the move; independent of the trial position,
// so computed once for all halvings of one move.
struct StarBefore {
  Vec3 mean = Vec3::Zero();  // the star's mean normal: new triangles must face its side
  struct Face {
    Vec3 normal;    // (a - x) x (b - x)
    double length;  // its norm
    bool sliver;    // height below a tenth of the base: its normal is noise
  };
  std::vector<Face> faces;
};

void describe_star(const Vec3& x, std::span<const std::int32_t> ring,
                   const std::vector<Vec3>& points, StarBefore& star) {
  const std::size_t m = ring.size();
  star.mean = Vec3::Zero();
  for (std::size_t i = 0; i < m; ++i) {
    star.mean += (points[ring[i]] - x).cross(points[ring[(i + 1) % m]] - x);
  }
  star.faces.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& a = points[ring[i]];
    const Vec3& b = points[ring[(i + 1) % m]];
    StarBefore::Face& face = star.faces[i];
    face.normal = (a - x).cross(b - x);
    face.length = face.normal.norm();
    const double base2 =
        std::max({(a - x).squaredNorm(), (b - x).squaredNorm(), (b - a).squaredNorm()});
    face.sliver = face.length < 0.1 * base2;
  }
}

// No triangle of the star degenerates, turns away from the star's mean normal (folds), or,
// unless it was a sliver, turns its normal by more than the limit.
bool star_valid(const StarBefore& star, const Vec3& y, std::span<const std::int32_t> ring,
                const std::vector<Vec3>& points, double cos_turn, double min_area_ratio) {
  const std::size_t m = ring.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3& a = points[ring[i]];
    const Vec3& b = points[ring[(i + 1) % m]];
    const StarBefore::Face& before = star.faces[i];
    const Vec3 after = (a - y).cross(b - y);
    const double la = after.norm();
    if (!(la > min_area_ratio * before.length) || !(la > 0)) return false;
    if (after.dot(star.mean) <= 0) return false;
    if (!before.sliver && after.dot(before.normal) < cos_turn * la * before.length) return false;
  }
  return true;
}

}  // namespace

std::optional<Vec3> accept_move(const Vec3& x, const Vec3& target,
                                std::span<const std::int32_t> ring, const std::vector<Vec3>& points,
                                const MoveLimits& limits) {
  const double cos_turn = std::cos(limits.max_normal_turn_deg * std::numbers::pi / 180.0);
  const double q_old = limits.require_quality ? star_quality_cos(x, ring, points) : 1.0;
  thread_local StarBefore star;
  describe_star(x, ring, points, star);
  Vec3 step = target - x;
  for (int attempt = 0; attempt <= limits.max_halvings; ++attempt, step *= 0.5) {
    const Vec3 y = x + step;
    if (!star_valid(star, y, ring, points, cos_turn, limits.min_area_ratio)) continue;
    if (limits.require_quality && star_quality_cos(y, ring, points) > q_old) continue;
    return y;
  }
  return std::nullopt;
}

std::size_t sweep_vertices(std::vector<Vec3>& points, const VertexAdjacency& rings,
                           const std::vector<std::vector<std::int32_t>>& colours,
                           const std::function<std::optional<Vec3>(std::size_t)>& move) {
  std::atomic<std::size_t> moved{0};
  for (const auto& members : colours) {
    tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t k) {
      const auto v = static_cast<std::size_t>(members[k]);
      if (rings.of(v).size() < 3) return;
      if (const auto y = move(v)) {
        points[v] = *y;
        moved.fetch_add(1, std::memory_order_relaxed);
      }
    });
  }
  return moved.load();
}

}  // namespace molmesh
