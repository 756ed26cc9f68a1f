#include "tables.hpp"

#include <pybind11/numpy.h>

#include <string>

#include "arrays.hpp"
#include "errors.hpp"
#include "molmesh/core/option_spec.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/tetmesh/tetmesh_option_specs.hpp"

namespace molmesh::python {

std::vector<Sphere> to_spheres(const py::handle& value, const char* name) {
  const InputDoubles a = InputDoubles::ensure(value);
  if (!a) throw py::type_error(std::string(name) + " must be a sphere file or an (n, 4) array");
  check_shape(a, 4, name);
  std::vector<Sphere> spheres(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const double* row = a.data() + 4 * i;
    spheres[i].center = Vec3(row[0], row[1], row[2]);
    spheres[i].radius = row[3];
  }
  return spheres;
}

py::object spheres_array(const std::vector<Sphere>& spheres) {
  if (spheres.empty()) return py::none();
  py::array_t<double> out({static_cast<py::ssize_t>(spheres.size()), py::ssize_t{4}});
  double* p = out.mutable_data();
  for (const Sphere& s : spheres) {
    *p++ = s.center.x();
    *p++ = s.center.y();
    *p++ = s.center.z();
    *p++ = s.radius;
  }
  return out;
}

namespace {

// The docstring line of a library-described option (core/option_spec.hpp): its help text
// with keywords for members, `suffix` (what Python takes beyond the CLI), then its range.
std::string doc_of(const OptionSpec& spec, const std::string& suffix = "") {
  std::string doc = with_keywords(spec.help) + suffix;
  if (spec.range) doc += ", " + range_text(*spec.range);
  return doc;
}

}  // namespace

bool is_path(const py::handle& v) {
  return py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__");
}

const OptionTable<SurfacePipelineOptions>& volume_table() {
  static const auto table = [] {
    OptionTable<SurfacePipelineOptions> t;
    std::vector<std::pair<std::string, SurfaceKind>> kinds;
    for (SurfaceKind kind : kSurfaceKinds) kinds.emplace_back(surface_kind_name(kind), kind);
    t.choice("surface", MOLMESH_FIELD(surface), kinds,
             "which surface of the atoms: the paper's blurred 'gaussian' (blobbyness, "
             "isovalue), or the solvent-excluded 'ses', solvent-accessible 'sas' or van der "
             "Waals 'vdw' surface (docs/surface.md)");
    t.field("probe_radius", MOLMESH_FIELD(probe_radius),
            "solvent probe radius of the ses and sas surfaces, Å (1.4: water)");
    t.field("keep_on_surface", MOLMESH_FIELD(keep_on_surface),
            "project vertices back onto the surface after every processing move; None: on for "
            "'gaussian' (onto Eq. 1, exactly), off for ses, sas, vdw (it costs angle quality "
            "at their creases; docs/processing.md)");
    t.field("spacing", MOLMESH_FIELD(blur.spacing),
            "grid spacing of the blurred volume, Å (smaller: finer surface, more memory)");
    t.field("blobbyness", MOLMESH_FIELD(blur.blobbyness),
            "blobbyness B < 0 of the Gaussian kernel exp(B(|x-c|^2/r^2 - 1)) for atoms without "
            "their own");
    t.field("isovalue", MOLMESH_FIELD(isovalue),
            "level of the blurred volume that is the surface (1 on a lone atom's sphere)");
    t.field("truncation", MOLMESH_FIELD(blur.truncation),
            "kernel cut off below truncation * isovalue");
    t.choice("blur", MOLMESH_FIELD(blur_method),
             std::vector<std::pair<std::string, BlurMethod>>{{"exact", BlurMethod::kExact},
                                                             {"fast", BlurMethod::kFast}},
             "Eq. 1 summed atom by atom, or Eq. 2 with one decay rate and a recursive filter");
    t.field("min_cavity_volume", MOLMESH_FIELD(min_cavity_volume),
            "drop interior cavities enclosing less than this, Å^3 (0 keeps all)");
    return t;
  }();
  return table;
}

const OptionTable<ProcessingOptions>& processing_table() {
  static const auto table = [] {
    OptionTable<ProcessingOptions> t;
    t.field("rings", MOLMESH_FIELD(rings),
            "k-ring of the local structure tensor that detects features");
    t.field("alpha", MOLMESH_FIELD(alpha), "Eq. 6 exponent of the longest incident edge");
    t.field("beta", MOLMESH_FIELD(beta), "Eq. 6 exponent of lambda2/lambda1 (curvature)");
    t.field("sweeps", MOLMESH_FIELD(improve.sweeps),
            "passes of angle-based quality improvement per round");
    t.field("feature_weight", MOLMESH_FIELD(improve.feature_weight),
            "how strongly feature vertices are held in place during improvement");
    t.field("smooth_iterations", MOLMESH_FIELD(smoothing.normal_iterations),
            "normal-diffusion iterations of the smoothing (0: none)");
    t.field("flips", MOLMESH_FIELD(flips), "flip edges to raise angles");
    t.field("cleanup_rounds", MOLMESH_FIELD(cleanup_rounds),
            "final rounds of improvement and flips aimed at the worst triangles");
    return t;
  }();
  return table;
}

const OptionTable<SurfacePipelineOptions>& surface_table() {
  static const auto table = [] {
    OptionTable<SurfacePipelineOptions> t;
    t.nest(
        volume_table(), [](SurfacePipelineOptions & o) -> auto& { return o; });
    t.field("coarsen", MOLMESH_FIELD(processing.t0),
            "coarsening thresholds T0 of Eq. 6, one round each ([] = improve only)");
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.field("raw", MOLMESH_FIELD(raw),
            "stop after marching cubes: no improvement, coarsening or smoothing");
    t.nest(
        keep_spheres_table(), [](SurfacePipelineOptions & o) -> auto& { return o; });
    t.field("keep_volume", MOLMESH_FIELD(keep_volume),
            "also return the blurred volume as report['volume'] (atom input)");
    t.field("measure", MOLMESH_FIELD(measure),
            "per-stage stats, dislocation and level-set distances in .report (what the CLI's "
            "--stats adds); False skips them (~10 % faster, the same surface)");
    return t;
  }();
  return table;
}

const OptionTable<SurfacePipelineOptions>& keep_spheres_table() {
  static const auto table = [] {
    OptionTable<SurfacePipelineOptions> t;
    t.custom(
        "keep_spheres",
        [](SurfacePipelineOptions& o, py::handle v) {
          o.keep_spheres_file.clear();
          o.processing.keep_spheres.clear();
          if (v.is_none()) return;
          if (is_path(v))
            o.keep_spheres_file = py::cast<std::filesystem::path>(v).string();
          else
            o.processing.keep_spheres = to_spheres(v, "keep_spheres");
        },
        [](const SurfacePipelineOptions& o) -> py::object {
          if (!o.keep_spheres_file.empty()) return py::str(o.keep_spheres_file);
          return spheres_array(o.processing.keep_spheres);
        },
        "sphere file or (n, 4) array (x, y, z, r in Å): no vertex inside is removed by "
        "coarsening");
    return t;
  }();
  return table;
}

const OptionTable<ImprovePipelineOptions>& improve_table() {
  static const auto table = [] {
    OptionTable<ImprovePipelineOptions> t;
    t.field("t0", MOLMESH_FIELD(processing.t0),
            "coarsening thresholds T0 of Eq. 6, one round each ([] = no coarsening)");
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.field("repair_only", MOLMESH_FIELD(repair_only), "repair without any processing");
    t.field("merge_tolerance", MOLMESH_FIELD(repair.merge_tolerance),
            "vertices closer than this (Å) are merged during repair");
    return t;
  }();
  return table;
}

const OptionTable<TetMeshOptions>& tetmesh_table() {
  static const auto table = [] {
    const TetMeshOptionSpecs& specs = kTetMeshOptionSpecs;
    OptionTable<TetMeshOptions> t;
    std::vector<std::pair<std::string, Domain>> domains;
    for (Domain d : kDomains) domains.emplace_back(domain_name(d), d);
    t.choice(std::string(specs.domain.name), MOLMESH_FIELD(domain), domains, doc_of(specs.domain));
    t.field(std::string(specs.sphere_ratio.name), MOLMESH_FIELD(sphere_ratio),
            doc_of(specs.sphere_ratio));
    t.field(std::string(specs.outer_radius.name), MOLMESH_FIELD(outer_radius),
            doc_of(specs.outer_radius));
    t.field(std::string(specs.sphere_subdivisions.name), MOLMESH_FIELD(outer_sphere_subdivisions),
            doc_of(specs.sphere_subdivisions));
    t.custom(
        std::string(specs.active_site.name),
        [](TetMeshOptions& o, py::handle v) {
          o.active_site.clear();
          if (v.is_none()) return;
          o.active_site = is_path(v) ? read_spheres(py::cast<std::filesystem::path>(v))
                                     : to_spheres(v, "active_site");
        },
        [](const TetMeshOptions& o) { return spheres_array(o.active_site); },
        doc_of(specs.active_site, "; a sphere file or an (n, 4) array"));
    t.field(std::string(specs.max_radius_edge.name), MOLMESH_FIELD(max_radius_edge_ratio),
            doc_of(specs.max_radius_edge));
    t.field(std::string(specs.min_dihedral.name), MOLMESH_FIELD(min_dihedral_deg),
            doc_of(specs.min_dihedral));
    t.field(std::string(specs.max_volume.name), MOLMESH_FIELD(max_volume),
            doc_of(specs.max_volume));
    t.field(std::string(specs.size_factor.name), MOLMESH_FIELD(size_factor),
            doc_of(specs.size_factor));
    t.field(std::string(specs.tetgen_switches.name), MOLMESH_FIELD(tetgen_switches),
            doc_of(specs.tetgen_switches));
    return t;
  }();
  return table;
}

const OptionTable<HierarchyOptions>& hierarchy_table() {
  static const auto table = [] {
    OptionTable<HierarchyOptions> t;
    t.field("t0", MOLMESH_FIELD(t0), "one level per coarsening threshold T0, finest first");
    t.field("size_growth", MOLMESH_FIELD(size_growth),
            "level L meshes its volume with size_factor * size_growth^L, " +
                range_text({kMinSizeGrowth, kMaxSizeGrowth, false}));
    t.field("renumber", MOLMESH_FIELD(renumber), "reverse Cuthill-McKee on every volume mesh");
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.nest(tetmesh_table(), MOLMESH_FIELD(tetmesh));
    return t;
  }();
  return table;
}

}  // namespace molmesh::python
