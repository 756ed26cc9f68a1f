#include "molmesh/surface/surface_stats.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "molmesh/geometry/predicates.hpp"

namespace molmesh {
namespace {

double angle_deg(const Vec3& at, const Vec3& p, const Vec3& q) {
  const Vec3 u = p - at;
  const Vec3 v = q - at;
  // atan2 stays accurate for angles near 0 and 180 degrees, where acos does not.
  return std::atan2(u.cross(v).norm(), u.dot(v)) * (180.0 / M_PI);
}

// Area, volume (about the bounding-box centre, to limit cancellation) and the angle
// statistics.
void measure_geometry(const SurfaceMesh& mesh, SurfaceStats& s) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 ref = !mesh.points.empty() ? Vec3(0.5 * (lo + hi)) : Vec3(Vec3::Zero());
  std::array<std::size_t, 18> bins{};
  std::size_t in_40_80 = 0;
  s.min_angle_deg = mesh.triangles.empty() ? 0.0 : 180.0;
  s.max_angle_deg = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
    s.area += 0.5 * (b - a).cross(c - a).norm();
    s.volume += signed_volume(ref, a, b, c);
    const double angles[3] = {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)};
    for (double x : angles) {
      s.min_angle_deg = std::min(s.min_angle_deg, x);
      s.max_angle_deg = std::max(s.max_angle_deg, x);
      ++bins[std::min<std::size_t>(17, static_cast<std::size_t>(std::max(0.0, x) / 10.0))];
      if (x >= 40.0 && x <= 80.0) ++in_40_80;
    }
  }
  const double n_angles = 3.0 * static_cast<double>(mesh.triangles.size());
  if (n_angles > 0) {
    for (std::size_t b = 0; b < 18; ++b)
      s.angle_histogram_percent[b] = 100.0 * static_cast<double>(bins[b]) / n_angles;
    s.fraction_angles_40_80 = static_cast<double>(in_40_80) / n_angles;
  }
}

// Edges: sorted (min, max, direction) keys; a closed oriented manifold has every edge exactly
// twice, once in each direction. Returns the number of distinct edges.
std::size_t check_edges(const SurfaceMesh& mesh, bool& closed, bool& manifold) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(t[k]);
      const auto b = static_cast<std::uint64_t>(t[(k + 1) % 3]);
      const std::uint64_t lo_v = std::min(a, b), hi_v = std::max(a, b);
      edges.push_back((lo_v << 33) | (hi_v << 1) | (a < b ? 0u : 1u));
    }
  std::sort(edges.begin(), edges.end());
  closed = !mesh.triangles.empty();
  manifold = true;
  std::size_t n_edges = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && (edges[j] >> 1) == (edges[i] >> 1)) ++j;
    const std::size_t count = j - i;
    ++n_edges;
    if (count != 2) closed = false;
    if (count > 2 || (count == 2 && (edges[i] & 1u) == (edges[i + 1] & 1u))) manifold = false;
    if ((edges[i] >> 33) == ((edges[i] >> 1) & 0xffffffffu)) manifold = false;  // a == b
    i = j;
  }
  return n_edges;
}

// Vertex umbrellas: a vertex is manifold when the edges opposite to it in its triangles
// form one fan (path or cycle): one connected set of link vertices.
bool every_vertex_is_one_fan(const SurfaceMesh& mesh, const std::vector<int>& degree) {
  const std::size_t n_points = mesh.points.size();
  std::vector<std::size_t> start(n_points + 1, 0);
  for (std::size_t v = 0; v < n_points; ++v) start[v + 1] = start[v] + degree[v];
  std::vector<int> incident(start.back());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (int v : mesh.triangles[f])
        incident[fill[static_cast<std::size_t>(v)]++] = static_cast<int>(f);
  }
  std::vector<int> link_vertex;
  std::vector<std::pair<int, int>> link_edges;
  for (std::size_t v = 0; v < n_points; ++v) {
    link_vertex.clear();
    link_edges.clear();
    auto local = [&](int w) {
      for (std::size_t q = 0; q < link_vertex.size(); ++q)
        if (link_vertex[q] == w) return static_cast<int>(q);
      link_vertex.push_back(w);
      return static_cast<int>(link_vertex.size() - 1);
    };
    for (std::size_t q = start[v]; q < start[v + 1]; ++q) {
      const Triangle& t = mesh.triangles[static_cast<std::size_t>(incident[q])];
      int others[2], n = 0;
      for (int w : t)
        if (w != static_cast<int>(v) && n < 2) others[n++] = w;
      if (n < 2) continue;
      const int a = local(others[0]);
      link_edges.emplace_back(a, local(others[1]));
    }
    boost::disjoint_sets_with_storage<> fans(link_vertex.size());
    for (const auto& [a, b] : link_edges) fans.union_set(a, b);
    std::size_t fan_count = 0;
    for (std::size_t q = 0; q < link_vertex.size(); ++q)
      if (fans.find_set(q) == q) ++fan_count;
    if (fan_count > 1) return false;
  }
  return true;
}

// Vertex-connected components among the vertices that triangles use.
int count_components(const SurfaceMesh& mesh, const std::vector<int>& degree) {
  const std::size_t n_points = mesh.points.size();
  boost::disjoint_sets_with_storage<> sets(n_points);
  for (const Triangle& t : mesh.triangles) {
    sets.union_set(t[0], t[1]);
    sets.union_set(t[0], t[2]);
  }
  int components = 0;
  for (std::size_t v = 0; v < n_points; ++v)
    if (degree[v] > 0 && sets.find_set(v) == v) ++components;
  return components;
}

}  // namespace

SurfaceStats compute_surface_stats(const SurfaceMesh& mesh) {
  SurfaceStats s;
  s.triangles = mesh.triangles.size();
  std::vector<int> degree(mesh.points.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) ++degree[static_cast<std::size_t>(v)];
  s.vertices = static_cast<std::size_t>(
      std::count_if(degree.begin(), degree.end(), [](int d) { return d > 0; }));
  measure_geometry(mesh, s);
  bool closed = false, manifold = false;
  const std::size_t n_edges = check_edges(mesh, closed, manifold);
  manifold = manifold && every_vertex_is_one_fan(mesh, degree);
  s.closed = closed && manifold;
  s.manifold = manifold;
  s.components = count_components(mesh, degree);
  s.euler_characteristic =
      static_cast<long>(s.vertices) - static_cast<long>(n_edges) + static_cast<long>(s.triangles);
  return s;
}

}  // namespace molmesh
