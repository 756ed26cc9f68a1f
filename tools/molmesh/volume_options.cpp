#include "volume_options.hpp"

#include <string>
#include <vector>

#include "help_formatter.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/tetmesh/tetmesh_option_specs.hpp"
#include "spec_option.hpp"

namespace molmesh::cli {
void add_volume_options(CLI::App& cmd, VolumeCliOptions& options,
                        const std::string& active_site_help) {
  const TetMeshOptionSpecs& specs = kTetMeshOptionSpecs;
  one_of(add_spec_option(cmd, specs.domain, options.domain),
         [] {
           std::vector<std::string> names;
           for (Domain d : kDomains) names.push_back(domain_name(d));
           return names;
         }())
      ->capture_default_str();
  add_spec_option(cmd, specs.sphere_ratio, options.tet.sphere_ratio)->capture_default_str();
  add_spec_option(cmd, specs.outer_radius, options.outer_radius)->type_name("R");
  // --outer-sphere-subdivisions: the hierarchy command's earlier spelling, still accepted.
  add_spec_option(cmd, specs.sphere_subdivisions, options.tet.outer_sphere_subdivisions,
                  ",--outer-sphere-subdivisions")
      ->capture_default_str();
  add_spec_option(cmd, specs.active_site, options.active_site, "",
                  " (a file of x y z r lines)" + active_site_help)
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
  add_spec_option(cmd, specs.max_radius_edge, options.tet.max_radius_edge_ratio)
      ->capture_default_str();
  add_spec_option(cmd, specs.min_dihedral, options.tet.min_dihedral_deg)->capture_default_str();
  add_spec_option(cmd, specs.max_volume, options.max_volume)->type_name("V");
  add_spec_option(cmd, specs.size_factor, options.tet.size_factor)->capture_default_str();
  add_spec_option(cmd, specs.surface_size_ratio, options.tet.surface_size_ratio)
      ->capture_default_str();
}

void add_tetgen_switches_option(CLI::App& cmd, std::string& switches) {
  add_spec_option(cmd, kTetMeshOptionSpecs.tetgen_switches, switches)->type_name("SW");
}

TetMeshOptions volume_options(const VolumeCliOptions& options, double max_memory_bytes) {
  TetMeshOptions out = options.tet;
  for (Domain d : kDomains)
    if (domain_name(d) == options.domain) out.domain = d;
  if (options.outer_radius > 0.0) out.outer_radius = options.outer_radius;
  if (options.max_volume > 0.0) out.max_volume = options.max_volume;
  if (!options.active_site.empty()) out.active_site = read_spheres(options.active_site);
  out.max_memory_bytes = max_memory_bytes;
  return out;
}

}  // namespace molmesh::cli
