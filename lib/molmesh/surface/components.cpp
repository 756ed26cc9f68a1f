#include "molmesh/surface/components.hpp"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>

#include "molmesh/geometry/predicates.hpp"

namespace molmesh {
namespace {

SurfaceMesh keep_triangles(const SurfaceMesh& mesh, const std::vector<char>& keep) {
  SurfaceMesh out;
  const bool face_markers = mesh.face_markers.size() == mesh.triangles.size();
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!keep[f]) continue;
    out.triangles.push_back(mesh.triangles[f]);
    if (face_markers) out.face_markers.push_back(mesh.face_markers[f]);
  }
  out.points = mesh.points;
  if (mesh.vertex_markers.size() == mesh.points.size()) out.vertex_markers = mesh.vertex_markers;
  return remove_unreferenced_points(out);
}

}  // namespace

std::vector<SurfaceComponent> surface_components(const SurfaceMesh& mesh) {
  boost::disjoint_sets_with_storage<> sets(mesh.points.size());
  for (const Triangle& t : mesh.triangles) {
    sets.union_set(t[0], t[1]);
    sets.union_set(t[0], t[2]);
  }
  Vec3 ref = Vec3::Zero();
  if (!mesh.points.empty()) {
    Vec3 lo = mesh.points[0], hi = mesh.points[0];
    for (const Vec3& p : mesh.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    ref = 0.5 * (lo + hi);
  }
  std::vector<int> component_of_root(mesh.points.size(), -1);
  std::vector<SurfaceComponent> components;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const int root = sets.find_set(t[0]);
    int& c = component_of_root[static_cast<std::size_t>(root)];
    if (c < 0) {
      c = static_cast<int>(components.size());
      components.emplace_back();
    }
    SurfaceComponent& comp = components[static_cast<std::size_t>(c)];
    comp.triangles.push_back(static_cast<int>(f));
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& d = mesh.points[static_cast<std::size_t>(t[2])];
    comp.area += 0.5 * (b - a).cross(d - a).norm();
    comp.signed_volume += signed_volume(ref, a, b, d);
  }
  return components;
}

SurfaceMesh drop_small_cavities(const SurfaceMesh& mesh, double min_volume, std::size_t* removed) {
  std::size_t dropped = 0;
  std::vector<char> keep(mesh.triangles.size(), 1);
  if (min_volume > 0.0) {
    for (const SurfaceComponent& c : surface_components(mesh)) {
      if (!c.is_cavity() || -c.signed_volume >= min_volume) continue;
      ++dropped;
      for (int f : c.triangles) keep[static_cast<std::size_t>(f)] = 0;
    }
  }
  if (removed) *removed = dropped;
  if (dropped == 0) return mesh;
  return keep_triangles(mesh, keep);
}

SurfaceMesh remove_unreferenced_points(const SurfaceMesh& mesh) {
  std::vector<int> new_index(mesh.points.size(), -1);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) new_index[static_cast<std::size_t>(v)] = 0;
  SurfaceMesh out;
  const bool vertex_markers = mesh.vertex_markers.size() == mesh.points.size();
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (new_index[v] < 0) continue;
    new_index[v] = static_cast<int>(out.points.size());
    out.points.push_back(mesh.points[v]);
    if (vertex_markers) out.vertex_markers.push_back(mesh.vertex_markers[v]);
  }
  out.triangles = mesh.triangles;
  for (Triangle& t : out.triangles)
    for (int& v : t) v = new_index[static_cast<std::size_t>(v)];
  out.face_markers = mesh.face_markers;
  return out;
}

}  // namespace molmesh
