#include "volume_options.hpp"

#include <string>
#include <vector>

#include "molmesh/io/sphere_list.hpp"
#include "option_checks.hpp"

namespace molmesh::cli {

void add_volume_options(CLI::App& cmd, VolumeCliOptions& options,
                        const std::string& active_site_help) {
  cmd.add_option("--domain", options.domain,
                 "interior: the molecule (region 1); exterior: the solvent between the "
                 "molecular surface and the outer sphere (region 2); full: both, conforming")
      ->check(CLI::IsMember([] {
        std::vector<std::string> names;
        for (Domain d : kDomains) names.push_back(domain_name(d));
        return names;
      }()))
      ->capture_default_str();
  cmd.add_option("--sphere-ratio", options.tet.sphere_ratio,
                 "Outer sphere radius as a multiple of the molecule size (largest distance of "
                 "an atom centre from their mean; of a surface point for surface input)")
      ->check(finite_above(0, kMaxSphereRatio))
      ->capture_default_str();
  cmd.add_option("--outer-radius", options.outer_radius,
                 "Outer sphere radius in Å (overrides --sphere-ratio; needed for one atom; the "
                 "same on every level of a hierarchy)")
      ->check(finite_above(0, kMaxOuterRadius))
      ->type_name("R");
  // --outer-sphere-subdivisions: the hierarchy command's earlier spelling, still accepted.
  cmd.add_option("--sphere-subdivisions,--outer-sphere-subdivisions",
                 options.tet.outer_sphere_subdivisions,
                 "Outer sphere triangulation: icosahedron subdivided L times (10*4^L+2 "
                 "vertices); coarse keeps the far field coarse")
      ->check(CLI::Range(0, kMaxOuterSphereSubdivisions))
      ->capture_default_str();
  cmd.add_option("--active-site", options.active_site,
                 "Spheres (x y z r per line, Å) marking the active site: molecular-surface "
                 "faces with all three vertices inside get marker 3 (MCSF type 3)" +
                     active_site_help)
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
  cmd.add_option("--max-radius-edge", options.tet.max_radius_edge_ratio,
                 "TetGen -q radius-edge ratio bound (smaller: better tets, more points)")
      ->check(finite_in(kMinRadiusEdgeRatio, kMaxRadiusEdgeRatio))
      ->capture_default_str();
  cmd.add_option("--min-dihedral", options.tet.min_dihedral_deg,
                 "TetGen -q minimum dihedral angle in degrees (sought by its optimiser)")
      ->check(finite_in(0.0, kMaxMinDihedralDeg))
      ->capture_default_str();
  cmd.add_option("--max-volume", options.max_volume,
                 "TetGen -a: largest tetrahedron volume in Å^3 (default: unbounded)")
      ->check(finite_above(0, kLargestValue))
      ->type_name("V");
  cmd.add_option("--size-factor", options.tet.size_factor,
                 "Size grading (TetGen -m): tetrahedra near an input vertex aim at its mean "
                 "edge length times this factor, interpolated between the molecular surface "
                 "and the outer sphere; smaller: finer near the surface; 0: no grading")
      ->check(finite_in(0, kMaxSizeFactor))
      ->capture_default_str();
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
