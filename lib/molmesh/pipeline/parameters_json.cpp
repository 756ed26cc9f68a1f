#include "molmesh/pipeline/parameters_json.hpp"

namespace molmesh {

nlohmann::json surface_parameters_json(const SurfaceSource& source) {
  const SurfacePipelineOptions& s = source.surface;
  nlohmann::json j;
  j["surface"] = surface_kind_name(s.surface);
  j["probe_radius"] = s.probe_radius;
  j["keep_on_surface"] = source.volume_input ? volume_keeps_on_surface(s) : keeps_on_surface(s);
  j["spacing"] = s.blur.spacing;
  j["blobbyness"] = s.blur.blobbyness;
  j["isovalue"] = s.isovalue;
  j["kernel_truncation"] = s.blur.truncation;
  j["min_cavity_volume"] = s.min_cavity_volume;
  j["blur"] = blur_method_name(s.blur_method);
  j["raw"] = s.raw;
  j["coarsen"] = s.processing.t0;
  j["rings"] = s.processing.rings;
  j["alpha"] = s.processing.alpha;
  j["beta"] = s.processing.beta;
  j["keep_spheres"] = s.keep_spheres_file;
  if (source.atoms) {
    const AtomReadOptions& a = *source.atoms;
    j["radii"] = a.radii_file ? a.radii_file->string() : std::string();
    j["hetatm"] = a.include_hetatm;
    j["waters"] = a.include_waters;
  }
  return j;
}

nlohmann::json tetmesh_parameters_json(const TetMeshOptions& options,
                                       const std::optional<SurfaceSource>& source) {
  nlohmann::json j = source ? surface_parameters_json(*source) : nlohmann::json::object();
  j["domain"] = domain_name(options.domain);
  j["sphere_ratio"] = options.sphere_ratio;
  j["outer_sphere_subdivisions"] = options.outer_sphere_subdivisions;
  j["max_radius_edge_ratio"] = options.max_radius_edge_ratio;
  j["min_dihedral_deg"] = options.min_dihedral_deg;
  if (options.outer_radius) j["outer_radius"] = *options.outer_radius;
  if (options.max_volume) j["max_volume"] = *options.max_volume;
  j["size_factor"] = options.size_factor;
  j["surface_size_ratio"] = options.surface_size_ratio;
  j["active_site_spheres"] = options.active_site.size();
  return j;
}

nlohmann::json improve_parameters_json(const ImprovePipelineOptions& options) {
  const ProcessingOptions& p = options.processing;
  nlohmann::json j;
  j["t0"] = p.t0;
  j["rings"] = p.rings;
  j["sweeps"] = p.improve.sweeps;
  j["feature_weight"] = p.improve.feature_weight;
  j["smooth_normal_iterations"] = p.smoothing.normal_iterations;
  j["flips"] = p.flips;
  j["cleanup_rounds"] = p.cleanup_rounds;
  j["merge_tolerance"] = options.repair.merge_tolerance;
  j["repair_only"] = options.repair_only;
  return j;
}

}  // namespace molmesh
