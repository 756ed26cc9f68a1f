#include "molmesh/processing/project_vertices.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "molmesh/processing/vertex_moves.hpp"

namespace molmesh {

namespace {

// Triangles around each vertex, as compressed rows.
struct TrianglesAround {
  std::vector<std::size_t> start;
  std::vector<std::size_t> around;
};

TrianglesAround triangles_around(const SurfaceMesh& mesh) {
  const std::size_t n = mesh.points.size();
  TrianglesAround rows;
  rows.start.assign(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) ++rows.start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < n; ++v) rows.start[v + 1] += rows.start[v];
  rows.around.resize(rows.start.back());
  std::vector<std::size_t> fill(rows.start.begin(), rows.start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t]) rows.around[fill[static_cast<std::size_t>(v)]++] = t;
  return rows;
}

// The loop both projections share: targets computed in parallel, moves made in index order,
// a move undone when a triangle turns over or the guard refuses it: guard.before(mesh, star)
// sees the vertex's triangles before the move, guard.accepts(mesh, star) after it.
template <class Guard>
std::size_t project_guarded(SurfaceMesh& mesh, const std::function<Vec3(const Vec3&)>& project,
                            Guard guard) {
  if (!project) return 0;
  const std::size_t n = mesh.points.size();
  std::vector<Vec3> target(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) target[v] = project(mesh.points[v]);
  });
  const TrianglesAround rows = triangles_around(mesh);
  const auto normal = [&](const Triangle& t) {
    return Vec3(
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]));
  };
  std::size_t kept = 0;
  std::vector<Vec3> before;
  for (std::size_t v = 0; v < n; ++v) {
    if (target[v] == mesh.points[v] || !target[v].allFinite()) continue;
    const std::span<const std::size_t> star(rows.around.data() + rows.start[v],
                                            rows.start[v + 1] - rows.start[v]);
    before.clear();
    for (std::size_t t : star) before.push_back(normal(mesh.triangles[t]));
    guard.before(mesh, star);
    const Vec3 old = mesh.points[v];
    mesh.points[v] = target[v];
    bool refused = false;
    for (std::size_t a = 0; a < star.size() && !refused; ++a)
      refused = !(normal(mesh.triangles[star[a]]).dot(before[a]) > 0.0);
    if (!refused) refused = !guard.accepts(mesh, star);
    if (refused) {
      mesh.points[v] = old;
      ++kept;
    }
  }
  return kept;
}

struct NoGuard {
  void before(const SurfaceMesh&, std::span<const std::size_t>) {}
  bool accepts(const SurfaceMesh&, std::span<const std::size_t>) { return true; }
};

// The star's smallest angle may not fall below min(before, floor), its largest not rise above
// max(before, 180° - 2·floor).
struct AngleGuard {
  double floor_small_cos = 0.0;  // cosine of floor_deg
  double floor_large_cos = 0.0;  // cosine of 180° - 2·floor_deg
  AngleCosines allowed;

  static AngleCosines star_cosines(const SurfaceMesh& mesh, std::span<const std::size_t> star) {
    AngleCosines worst{-1.0, 1.0};
    for (std::size_t t : star) {
      const Triangle& tri = mesh.triangles[t];
      const AngleCosines c =
          triangle_angle_cosines(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
      worst.smallest = std::max(worst.smallest, c.smallest);
      worst.largest = std::min(worst.largest, c.largest);
    }
    return worst;
  }
  void before(const SurfaceMesh& mesh, std::span<const std::size_t> star) {
    const AngleCosines now = star_cosines(mesh, star);
    allowed = {std::max(now.smallest, floor_small_cos), std::min(now.largest, floor_large_cos)};
  }
  bool accepts(const SurfaceMesh& mesh, std::span<const std::size_t> star) const {
    const AngleCosines after = star_cosines(mesh, star);
    return after.smallest <= allowed.smallest && after.largest >= allowed.largest;
  }
};

}  // namespace

std::size_t project_vertices(SurfaceMesh& mesh, const std::function<Vec3(const Vec3&)>& project) {
  return project_guarded(mesh, project, NoGuard{});
}

std::size_t project_vertices_keeping_angles(SurfaceMesh& mesh,
                                            const std::function<Vec3(const Vec3&)>& project,
                                            double floor_deg) {
  const double to_rad = std::numbers::pi / 180.0;
  AngleGuard guard;
  guard.floor_small_cos = std::cos(floor_deg * to_rad);
  guard.floor_large_cos = std::cos((180.0 - 2.0 * floor_deg) * to_rad);
  return project_guarded(mesh, project, guard);
}

}  // namespace molmesh
