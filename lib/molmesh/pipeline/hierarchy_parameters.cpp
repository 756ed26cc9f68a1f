#include "molmesh/pipeline/hierarchy_parameters.hpp"

#include <charconv>
#include <vector>

#include "molmesh/core/version.hpp"

namespace molmesh {
namespace {

std::string text(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

std::string join(const std::vector<double>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? "," : "") + text(values[i]);
  return out;
}

}  // namespace

std::map<std::string, std::string> hierarchy_parameters(
    const HierarchyOptions& options, const HierarchyReport& report,
    const std::string& active_site_file, const std::optional<SurfaceSource>& source) {
  std::map<std::string, std::string> p;
  const TetMeshOptions& tet = options.tetmesh;
  p["t0"] = join(options.t0);
  p["domain"] = domain_name(tet.domain);
  p["alpha"] = text(options.processing.alpha);
  p["beta"] = text(options.processing.beta);
  p["rings"] = std::to_string(options.processing.rings);
  if (source) {
    const SurfacePipelineOptions& s = source->surface;
    p["surface"] = surface_kind_name(s.surface);
    p["probe_radius"] = text(s.probe_radius);
    p["keep_on_surface"] = keeps_on_surface(s) ? "yes" : "no";
    p["spacing"] = text(s.blur.spacing);
    p["blobbyness"] = text(s.blur.blobbyness);
    p["isovalue"] = text(s.isovalue);
    p["level"] = text(level_of(s));
    p["blur"] = blur_method_name(s.blur_method);
    p["min_cavity_volume"] = text(s.min_cavity_volume);
    p["keep_spheres"] = s.keep_spheres_file;
    if (source->atoms) {
      const AtomReadOptions& a = *source->atoms;
      p["radii"] = a.radii_file ? a.radii_file->string() : "";
      p["hetatm"] = a.include_hetatm ? "yes" : "no";
      p["waters"] = a.include_waters ? "yes" : "no";
    }
  }
  p["sphere_ratio"] = text(tet.sphere_ratio);
  p["outer_radius"] = text(report.outer_radius);
  p["outer_sphere_subdivisions"] = std::to_string(tet.outer_sphere_subdivisions);
  p["active_site"] = active_site_file;
  p["active_site_spheres"] = std::to_string(tet.active_site.size());
  p["max_radius_edge_ratio"] = text(tet.max_radius_edge_ratio);
  p["min_dihedral_deg"] = text(tet.min_dihedral_deg);
  p["max_volume"] = tet.max_volume ? text(*tet.max_volume) : "none";
  p["size_factor"] = text(tet.size_factor);
  p["surface_size_ratio"] = text(tet.surface_size_ratio);
  p["size_growth"] = text(options.size_growth);
  p["renumbering"] = options.renumber ? "reverse Cuthill-McKee" : "none";
  if (!report.levels.empty()) p["tetgen_switches"] = report.levels.front().tetmesh.tetgen_switches;
  p["molmesh_version"] = version();
  return p;
}

}  // namespace molmesh
