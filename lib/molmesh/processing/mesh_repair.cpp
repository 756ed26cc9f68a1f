#include "molmesh/processing/mesh_repair.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/processing/mesh_repair_steps.hpp"

namespace molmesh {
namespace {

std::string format_point(const Vec3& p) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return out.str();
}

std::string format_examples(const std::vector<Vec3>& examples) {
  std::string s;
  for (std::size_t i = 0; i < examples.size(); ++i)
    s += (i ? ", " : "") + format_point(examples[i]);
  return s;
}

}  // namespace

std::string MeshRepairReport::problems() const {
  std::string s;
  if (non_manifold_edges > 0) {
    s += std::to_string(non_manifold_edges) +
         " non-manifold edges (shared by three or more triangles), e.g. at " +
         format_examples(non_manifold_edge_examples) + "; ";
  }
  if (boundary_edges > 0) {
    s += std::to_string(holes) + " holes (" + std::to_string(boundary_edges) +
         " edges used by only one triangle), e.g. at " + format_examples(hole_examples) + "; ";
  }
  if (non_orientable_components > 0) {
    s += std::to_string(non_orientable_components) +
         " pieces that cannot be oriented consistently (Möbius-like), e.g. at " +
         format_examples(non_orientable_examples) + "; ";
  }
  return s;
}

std::string MeshRepairReport::repairs() const {
  std::vector<std::string> parts;
  auto add = [&](std::size_t n, const char* what) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + what);
  };
  add(merged_vertices, "duplicate vertices merged");
  add(unreferenced_vertices, "unused vertices removed");
  add(collapsed_faces, "collapsed triangles dropped");
  add(duplicate_faces, "duplicate triangles dropped");
  add(flipped_cap_faces, "zero-area triangles removed by edge flips");
  add(split_vertices, "pinched vertices split");
  add(reoriented_faces, "triangles reoriented to match their neighbours");
  add(reoriented_components, "components turned outward");
  add(remaining_degenerate_faces, "zero-area triangles left (could not be flipped)");
  if (parts.empty()) return "nothing to repair";
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
  return s;
}
SurfaceMesh repair_surface_mesh(const SurfaceMesh& input, const MeshRepairOptions& options,
                                MeshRepairReport& report, const Reporter& reporter) {
  using namespace repair_steps;
  report = MeshRepairReport{};
  check_vertex_indices(input);
  reporter.progress("repair", 0.0);
  std::vector<Vec3> points = input.points;

  const std::vector<int> rep = merge_map(points, options.merge_tolerance);
  for (std::size_t v = 0; v < rep.size(); ++v)
    report.merged_vertices += rep[v] != static_cast<int>(v);
  std::vector<Triangle> tris = drop_collapsed_and_duplicate_faces(input.triangles, rep, report);
  reporter.progress("repair", 0.2);

  std::vector<EdgeUse> uses = edge_uses(tris);
  census_edges(points, tris, uses, report);
  if (report.non_manifold_edges == 0 && report.boundary_edges == 0 &&
      split_pinched_vertices(points, tris, uses, report)) {
    uses = edge_uses(tris);
  }
  reporter.progress("repair", 0.4);

  const std::vector<std::vector<int>> component_faces =
      orient_components(points, tris, uses, report);
  reporter.progress("repair", 0.6);

  flip_zero_area_caps(points, tris, uses, options.degenerate_ratio, report);
  reporter.progress("repair", 0.7);

  if (options.orient_outward && report.closed_manifold()) {
    orient_outward(points, tris, component_faces, report);
  }
  reporter.progress("repair", 0.9);

  SurfaceMesh out = compact(points, tris, report);
  reporter.progress("repair", 1.0);
  if (options.require_closed_manifold && !report.closed_manifold()) {
    throw Error(
        "the surface mesh is not a closed manifold and cannot be repaired "
        "automatically: " +
        report.problems() + "(repaired so far: " + report.repairs() + ")");
  }
  return out;
}

}  // namespace molmesh
