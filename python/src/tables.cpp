#include "tables.hpp"

#include <pybind11/numpy.h>

#include <string>

#include "arrays.hpp"
#include "casters.hpp"
#include "errors.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/option_spec.hpp"
#include "molmesh/hierarchy/hierarchy_option_specs.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/pipeline/improve_option_specs.hpp"
#include "molmesh/pipeline/surface_option_specs.hpp"
#include "molmesh/processing/processing_option_specs.hpp"
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

// The spec's keyword.
std::string key(const OptionSpec& spec) { return std::string(spec.name); }

}  // namespace

void validate_surface_keywords(const SurfacePipelineOptions& options, SurfaceInput input) {
  try {
    options.validate(input);
  } catch (const OptionError& e) {
    throw OptionError(spell_option_names(
        e.what(), OptionSpellings{{"t0", "`" + key(kSurfaceOptionSpecs.coarsen) + "`"}}));
  }
}

bool is_path(const py::handle& v) {
  return py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__");
}

const OptionTable<SurfacePipelineOptions>& volume_table() {
  static const auto table = [] {
    const SurfaceOptionSpecs& specs = kSurfaceOptionSpecs;
    OptionTable<SurfacePipelineOptions> t;
    std::vector<std::pair<std::string, SurfaceKind>> kinds;
    for (SurfaceKind kind : kSurfaceKinds) kinds.emplace_back(surface_kind_name(kind), kind);
    t.choice(key(specs.surface), MOLMESH_FIELD(surface), kinds, doc_of(specs.surface));
    t.field(key(specs.probe_radius), MOLMESH_FIELD(probe_radius), doc_of(specs.probe_radius));
    t.field(key(specs.keep_on_surface), MOLMESH_FIELD(keep_on_surface),
            doc_of(specs.keep_on_surface, "; None: the kind's default"));
    t.field(key(specs.spacing), MOLMESH_FIELD(blur.spacing), doc_of(specs.spacing));
    t.field(key(specs.blobbyness), MOLMESH_FIELD(blur.blobbyness), doc_of(specs.blobbyness));
    // The range is the atoms' (SurfacePipelineOptions::validate()): a Volume's level may be
    // any finite number.
    t.field(key(specs.isovalue), MOLMESH_FIELD(isovalue),
            doc_of(specs.isovalue) + " for atoms; a Volume's level may be any finite number");
    t.field(key(specs.truncation), MOLMESH_FIELD(blur.truncation), doc_of(specs.truncation));
    std::vector<std::pair<std::string, BlurMethod>> blur_methods;
    for (BlurMethod method : kBlurMethods)
      blur_methods.emplace_back(blur_method_name(method), method);
    t.choice(key(specs.blur), MOLMESH_FIELD(blur_method), blur_methods, doc_of(specs.blur));
    t.field(key(specs.min_cavity_volume), MOLMESH_FIELD(min_cavity_volume),
            doc_of(specs.min_cavity_volume));
    return t;
  }();
  return table;
}

const OptionTable<ProcessingOptions>& processing_table() {
  static const auto table = [] {
    const ProcessingOptionSpecs& specs = kProcessingOptionSpecs;
    OptionTable<ProcessingOptions> t;
    t.field(key(specs.rings), MOLMESH_FIELD(rings), doc_of(specs.rings));
    t.field(key(specs.alpha), MOLMESH_FIELD(alpha), doc_of(specs.alpha));
    t.field(key(specs.beta), MOLMESH_FIELD(beta), doc_of(specs.beta));
    t.field(key(specs.sweeps), MOLMESH_FIELD(improve.sweeps), doc_of(specs.sweeps));
    t.field(key(specs.feature_weight), MOLMESH_FIELD(improve.feature_weight),
            doc_of(specs.feature_weight));
    t.field(key(specs.smooth_iterations), MOLMESH_FIELD(smoothing.normal_iterations),
            doc_of(specs.smooth_iterations));
    t.field(key(specs.flips), MOLMESH_FIELD(flips), doc_of(specs.flips));
    t.field(key(specs.cleanup_rounds), MOLMESH_FIELD(cleanup_rounds), doc_of(specs.cleanup_rounds));
    return t;
  }();
  return table;
}

const OptionTable<SurfacePipelineOptions>& surface_table() {
  static const auto table = [] {
    OptionTable<SurfacePipelineOptions> t;
    t.nest(
        volume_table(), [](SurfacePipelineOptions & o) -> auto& { return o; });
    t.field(key(kSurfaceOptionSpecs.coarsen), MOLMESH_FIELD(processing.t0),
            doc_of(kSurfaceOptionSpecs.coarsen, " ([])"));
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.field(key(kSurfaceOptionSpecs.raw), MOLMESH_FIELD(raw), doc_of(kSurfaceOptionSpecs.raw));
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
        key(kSurfaceOptionSpecs.keep_spheres),
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
        doc_of(kSurfaceOptionSpecs.keep_spheres, "; a sphere file or an (n, 4) array"));
    return t;
  }();
  return table;
}

const OptionTable<ImprovePipelineOptions>& improve_table() {
  static const auto table = [] {
    OptionTable<ImprovePipelineOptions> t;
    const ImproveOptionSpecs& specs = kImproveOptionSpecs;
    t.field(key(specs.t0), MOLMESH_FIELD(processing.t0), doc_of(specs.t0, " ([])"));
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.field(key(specs.repair_only), MOLMESH_FIELD(repair_only), doc_of(specs.repair_only));
    t.field(key(specs.merge_tolerance), MOLMESH_FIELD(repair.merge_tolerance),
            doc_of(specs.merge_tolerance));
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
    t.field(std::string(specs.surface_size_ratio.name), MOLMESH_FIELD(surface_size_ratio),
            doc_of(specs.surface_size_ratio));
    t.field(std::string(specs.tetgen_switches.name), MOLMESH_FIELD(tetgen_switches),
            doc_of(specs.tetgen_switches));
    return t;
  }();
  return table;
}

const OptionTable<HierarchyOptions>& hierarchy_table() {
  static const auto table = [] {
    OptionTable<HierarchyOptions> t;
    const HierarchyOptionSpecs& specs = kHierarchyOptionSpecs;
    t.field(key(specs.t0), MOLMESH_FIELD(t0), doc_of(specs.t0));
    t.field(key(specs.size_growth), MOLMESH_FIELD(size_growth), doc_of(specs.size_growth));
    t.field(key(specs.renumber), MOLMESH_FIELD(renumber), doc_of(specs.renumber));
    t.nest(processing_table(), MOLMESH_FIELD(processing));
    t.nest(tetmesh_table(), MOLMESH_FIELD(tetmesh));
    return t;
  }();
  return table;
}

}  // namespace molmesh::python
