#include "surface_options.hpp"

#include <map>
#include <string>

#include "option_checks.hpp"

namespace molmesh::cli {

void add_atom_options(CLI::App& cmd, AtomReadOptions& options) {
  cmd.add_option_function<std::string>(
         "--radii", [&options](const std::string& file) { options.radii_file = file; },
         "Radius table (docs/formats.md) overriding the built-in radii; for PQR input it "
         "replaces the file's radii wherever it has an entry")
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
  cmd.add_flag("--hetatm,!--no-hetatm", options.include_hetatm,
               "Include (default) or exclude HETATM records (ligands, ions)");
  cmd.add_flag("--waters", options.include_waters,
               "Include water molecules (HOH, WAT, ...), which are dropped by default");
}

void add_surface_pipeline_options(CLI::App& cmd, SurfacePipelineOptions& options) {
  cmd.add_option("--surface", options.surface,
                 "Which surface of the atoms: 'ses' solvent-excluded (what a probe rolling "
                 "over the atoms cannot reach; the dielectric boundary of PB solvers), 'sas' "
                 "solvent-accessible (atoms grown by the probe), 'vdw' (union of the atoms), "
                 "'gaussian' the paper's blurred density (--blobbyness, --isovalue). "
                 "docs/surface.md")
      ->transform(CLI::CheckedTransformer(
          [] {
            std::map<std::string, SurfaceKind> names;
            for (SurfaceKind kind : kSurfaceKinds) names[surface_kind_name(kind)] = kind;
            return names;
          }(),
          CLI::ignore_case))
      ->default_str(surface_kind_name(options.surface))
      ->type_name("ses|sas|vdw|gaussian");
  cmd.add_option("--probe-radius", options.probe_radius,
                 "Solvent probe radius in Å of the ses and sas surfaces (1.4: water)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str()
      ->type_name("R");
  cmd.add_flag_function(
      "--keep-on-surface,!--no-keep-on-surface",
      [&options](std::int64_t count) { options.keep_on_surface = count > 0; },
      "Project every vertex back onto the surface after each processing move: onto Eq. 1's "
      "level set, evaluated exactly, for 'gaussian' (default: on); onto the distance field's "
      "for ses, sas, vdw (default: off, it costs angle quality at creases). docs/processing.md");
  cmd.add_option("--spacing", options.blur.spacing,
                 "Grid spacing of the blurred volume in Å (smaller: finer surface, more "
                 "vertices, more memory)")
      ->check(finite_above(0, kLargestValue))
      ->capture_default_str()
      ->type_name("H");
  cmd.add_option(
         "--blobbyness", options.blur.blobbyness,
         "(gaussian) Blobbyness B < 0 of the Gaussian kernel exp(B(|x-c|^2/r^2 - 1)) for atoms "
         "without their own; closer to 0 blurs more, more negative follows the atoms "
         "closely")
      ->check(finite_in(-1e6, -1e-12))
      ->capture_default_str()
      ->type_name("B");
  cmd.add_option(
         "--isovalue", options.isovalue,
         "(gaussian) Level of the blurred volume that is the surface (the volume is 1 on a lone "
         "atom's sphere)")
      ->check(finite_above(0, kLargestValue))
      ->capture_default_str()
      ->type_name("T");
  cmd.add_option("--min-cavity-volume", options.min_cavity_volume,
                 "Drop interior cavities enclosing less than V Å^3 (0 keeps all)")
      ->check(finite_in(0, kLargestValue))
      ->capture_default_str()
      ->type_name("V");
  add_max_memory_option(cmd, options.blur.max_memory_bytes);
  cmd.add_flag("--raw", options.raw,
               "Stop after marching cubes: no quality improvement, coarsening or smoothing");
  cmd.add_option("--blur", options.blur_method,
                 "How the blurred volume is computed: 'exact' sums Eq. 1 atom by atom with each "
                 "atom's own decay B/r_i^2; 'fast' uses one decay rate B/r_mean^2 for all atoms "
                 "(Eq. 2) and a recursive Gaussian filter (§4.1): faster on large molecules, "
                 "surface within a few tenths of an Å of exact (docs/inputs.md)")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, BlurMethod>{{"exact", BlurMethod::kExact},
                                                                    {"fast", BlurMethod::kFast}},
                                  CLI::ignore_case))
      ->capture_default_str()
      ->type_name("exact|fast");
  cmd.add_option("--coarsen", options.processing.t0,
                 "Coarsening thresholds T0 of Eq. 6, comma-separated: one round of improve -> "
                 "coarsen -> smooth -> improve per value (larger T0 deletes more vertices; "
                 "the paper uses 0.2 once)")
      ->delimiter(',')
      ->check(finite_in(0, kLargestValue))
      ->capture_default_str()
      ->type_name("T0[,T0...]");
  cmd.add_option("--rings", options.processing.rings,
                 "Neighbourhood (in edge rings) of the local structure tensor that detects "
                 "features, for coarsening and quality improvement")
      ->check(CLI::Range(1, 10))
      ->capture_default_str()
      ->type_name("K");
  cmd.add_option("--alpha", options.processing.alpha,
                 "Exponent of the longest incident edge in Eq. 6 (weight of sparseness)")
      ->check(finite_in(0, kLargestValue))
      ->capture_default_str()
      ->type_name("A");
  cmd.add_option("--beta", options.processing.beta,
                 "Exponent of lambda2/lambda1 in Eq. 6 (weight of curvature: larger keeps "
                 "curved regions denser)")
      ->check(finite_in(0, kLargestValue))
      ->capture_default_str()
      ->type_name("B");
  cmd.add_option("--keep-spheres", options.keep_spheres_file,
                 "Sphere list (docs/formats.md): no vertex inside any sphere is removed by "
                 "coarsening, so e.g. an active site stays finely meshed")
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
}

void add_surface_options(CLI::App& cmd, SurfaceCliOptions& options) {
  add_atom_options(cmd, options.atoms);
  add_surface_pipeline_options(cmd, options.pipeline);
}

}  // namespace molmesh::cli
