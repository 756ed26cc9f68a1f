#pragma once
// The names, help texts and ranges of the TetMeshOptions the front ends expose (the CLI's
// volume options of `tetmesh` and `hierarchy`, the Python keywords of molmesh.tetmesh and
// molmesh.hierarchy), written once here. Defaults are TetMeshOptions' own; the ranges are
// the constants validate() checks (tetrahedralize.hpp).
#include <array>
#include <limits>

#include "molmesh/core/option_spec.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {

struct TetMeshOptionSpecs {
  OptionSpec domain;
  OptionSpec sphere_ratio;
  OptionSpec outer_radius;
  OptionSpec sphere_subdivisions;
  OptionSpec active_site;
  OptionSpec max_radius_edge;
  OptionSpec min_dihedral;
  OptionSpec max_volume;
  OptionSpec size_factor;
  OptionSpec surface_size_ratio;
  OptionSpec tetgen_switches;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 11> all() const {
    return {&domain,      &sphere_ratio,       &outer_radius,   &sphere_subdivisions,
            &active_site, &max_radius_edge,    &min_dihedral,   &max_volume,
            &size_factor, &surface_size_ratio, &tetgen_switches};
  }
};

inline constexpr TetMeshOptionSpecs kTetMeshOptionSpecs{
    .domain = {"domain", "domain",
               "interior: the molecule (region 1); exterior: the solvent between the molecular "
               "surface and the outer sphere (region 2); full: both, conforming",
               std::nullopt},
    .sphere_ratio = {"sphere_ratio", "sphere_ratio",
                     "Outer sphere radius as a multiple of the molecule size (largest distance of "
                     "an atom centre from their mean; of a surface point for surface input)",
                     OptionRange{0.0, kMaxSphereRatio, true}},
    .outer_radius = {"outer_radius", "outer_radius",
                     "Outer sphere radius in Å (overrides `sphere_ratio`, the default; needed for "
                     "one atom; the same on every level of a hierarchy)",
                     OptionRange{0.0, kMaxOuterRadius, true}},
    .sphere_subdivisions = {"sphere_subdivisions", "outer_sphere_subdivisions",
                            "Outer sphere triangulation: icosahedron subdivided L times (10*4^L+2 "
                            "vertices); coarse keeps the far field coarse",
                            OptionRange{0.0, kMaxOuterSphereSubdivisions, false}},
    .active_site = {"active_site", "active_site",
                    "Spheres (x, y, z, r in Å) marking the active site: molecular-surface faces "
                    "with all three vertices inside get marker 3 (MCSF type 3)",
                    std::nullopt},
    .max_radius_edge = {"max_radius_edge", "max_radius_edge_ratio",
                        "TetGen -q radius-edge ratio bound (smaller: better tets, more points; "
                        "TetGen may not terminate below 1)",
                        OptionRange{kMinRadiusEdgeRatio, kMaxRadiusEdgeRatio, false}},
    .min_dihedral = {"min_dihedral", "min_dihedral_deg",
                     "TetGen -q minimum dihedral angle in degrees (sought by its optimiser)",
                     OptionRange{0.0, kMaxMinDihedralDeg, false}},
    .max_volume = {"max_volume", "max_volume",
                   "TetGen -a: largest tetrahedron volume in Å^3 (default: unbounded)",
                   OptionRange{0.0, std::numeric_limits<double>::infinity(), true}},
    .size_factor = {"size_factor", "size_factor",
                    "Size field (TetGen -m) times this factor: `surface_size_ratio` edge lengths "
                    "at the molecular surface, 0.09 R (r/R)^1.2 in the solvent (R the "
                    "molecule's volume-equivalent radius); smaller: finer everywhere; 0: no "
                    "grading",
                    OptionRange{0.0, kMaxSizeFactor, false}},
    .surface_size_ratio = {"surface_size_ratio", "surface_size_ratio",
                           "Size field at the molecular surface, in mean edge lengths of each "
                           "vertex's star (before `size_factor`); 0.6 for solvation energies "
                           "of proteins with point charges (docs/surface.md)",
                           OptionRange{0.0, kMaxSurfaceSizeRatio, true}},
    .tetgen_switches = {"tetgen_switches", "tetgen_switches",
                        "Expert: TetGen switches replacing the ones above (e.g. pYq1.5/15); "
                        "molmesh adds p, z, n and Q when missing. Without Y TetGen may split the "
                        "molecular surface",
                        std::nullopt},
};

}  // namespace molmesh
