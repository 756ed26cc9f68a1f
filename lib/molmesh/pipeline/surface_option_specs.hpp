#pragma once
// The names, help texts and ranges of the SurfacePipelineOptions the front ends expose (the
// CLI's surface options of `surface`, `tetmesh` and `hierarchy`, the Python keywords of
// molmesh.surface, molmesh.tetmesh and molmesh.hierarchy), written once here; its processing
// options are processing/processing_option_specs.hpp's. Defaults are SurfacePipelineOptions'
// own. The ranges are what SurfacePipelineOptions::validate() accepts (the isovalue's for
// atoms only), the CLI at parse time and Python's docstrings print.
#include <array>
#include <limits>

#include "molmesh/core/option_spec.hpp"
#include "molmesh/processing/processing_option_specs.hpp"

namespace molmesh {

struct SurfaceOptionSpecs {
  OptionSpec surface;
  OptionSpec probe_radius;
  OptionSpec keep_on_surface;
  OptionSpec spacing;
  OptionSpec blobbyness;
  OptionSpec isovalue;
  OptionSpec truncation;
  OptionSpec blur;
  OptionSpec min_cavity_volume;
  OptionSpec raw;
  OptionSpec coarsen;
  OptionSpec keep_spheres;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 12> all() const {
    return {&surface,    &probe_radius, &keep_on_surface,   &spacing, &blobbyness, &isovalue,
            &truncation, &blur,         &min_cavity_volume, &raw,     &coarsen,    &keep_spheres};
  }
};

inline constexpr SurfaceOptionSpecs kSurfaceOptionSpecs{
    .surface = {"surface", "surface",
                "Which surface of the atoms: 'ses' solvent-excluded (what a probe rolling over "
                "the atoms cannot reach; the dielectric boundary of PB solvers), 'sas' "
                "solvent-accessible (atoms grown by the probe), 'vdw' (union of the atoms), "
                "'gaussian' the paper's blurred density (`blobbyness`, `isovalue`). "
                "docs/surface.md",
                std::nullopt},
    .probe_radius = {"probe_radius", "probe_radius",
                     "Solvent probe radius in Å of the ses and sas surfaces (1.4: water)",
                     OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
    .keep_on_surface = {"keep_on_surface", "keep_on_surface",
                        "Project every vertex back onto the surface after each processing "
                        "move: onto Eq. 1's level set, evaluated exactly, for 'gaussian' "
                        "(default: on); onto the distance field's for ses, sas, vdw (default: "
                        "off, it costs angle quality at creases). docs/processing.md",
                        std::nullopt, "--keep-on-surface,!--no-keep-on-surface"},
    .spacing = {"spacing", "spacing",
                "Grid spacing of the blurred volume in Å (smaller: finer surface, more "
                "vertices, more memory)",
                OptionRange{0.0, std::numeric_limits<double>::infinity(), true}},
    .blobbyness = {"blobbyness", "blobbyness",
                   "(gaussian) Blobbyness B < 0 of the Gaussian kernel exp(B(|x-c|^2/r^2 - 1)) "
                   "for atoms without their own; closer to 0 blurs more, more negative follows "
                   "the atoms closely",
                   OptionRange{-1e6, -1e-12, false}},
    .isovalue = {"isovalue", "isovalue",
                 "(gaussian) Level of the blurred volume that is the surface (the volume is 1 "
                 "on a lone atom's sphere)",
                 OptionRange{0.0, std::numeric_limits<double>::infinity(), true}},
    .truncation = {"truncation", "truncation",
                   "(gaussian) The kernel is cut off below truncation times the isovalue",
                   std::nullopt},
    .blur = {"blur", "blur_method",
             "How the blurred volume is computed: 'exact' sums Eq. 1 atom by atom with each "
             "atom's own decay B/r_i^2; 'fast' uses one decay rate B/r_mean^2 for all atoms "
             "(Eq. 2) and a recursive Gaussian filter (§4.1): faster on large molecules, surface "
             "within a few tenths of an Å of exact (docs/inputs.md)",
             std::nullopt},
    .min_cavity_volume = {"min_cavity_volume", "min_cavity_volume",
                          "Drop interior cavities enclosing less than this volume in Å^3 (0 "
                          "keeps all)",
                          OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
    .raw = {"raw", "raw",
            "Stop after marching cubes: no quality improvement, coarsening or smoothing",
            std::nullopt},
    .coarsen = {"coarsen", "t0",
                "Coarsening thresholds T0 of Eq. 6: one round of improve -> coarsen -> smooth "
                "-> improve per value (larger T0 deletes more vertices; the paper uses 0.2 "
                "once; none: improve only)",
                kT0Range},
    .keep_spheres = {"keep_spheres", "keep_spheres_file",
                     "Spheres (x, y, z, r in Å; docs/formats.md): no vertex inside any sphere is "
                     "removed by coarsening, so e.g. an active site stays finely meshed",
                     std::nullopt},
};

}  // namespace molmesh
