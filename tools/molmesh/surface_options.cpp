#include "surface_options.hpp"

#include <iterator>
#include <map>
#include <string>
#include <type_traits>

#include "molmesh/atoms/atom_option_specs.hpp"
#include "molmesh/pipeline/surface_option_specs.hpp"
#include "molmesh/processing/processing_option_specs.hpp"
#include "option_checks.hpp"
#include "spec_option.hpp"

namespace molmesh::cli {

namespace {

// An option whose value is one of an enum's names (any case), e.g. --surface ses.
template <class Values, class NameOf>
CLI::CheckedTransformer choice_of(const Values& values, NameOf name_of) {
  std::map<std::string, std::decay_t<decltype(*std::begin(values))>> names;
  for (const auto& value : values) names[name_of(value)] = value;
  CLI::CheckedTransformer transformer(names, CLI::ignore_case);
  transformer.description("");  // the choices are the option's type name
  return transformer;
}

}  // namespace

void add_atom_options(CLI::App& cmd, AtomReadOptions& options) {
  const AtomOptionSpecs& specs = kAtomOptionSpecs;
  cmd.add_option_function<std::string>(
         cli_names(specs.radii), [&options](const std::string& file) { options.radii_file = file; },
         cli_help(specs.radii))
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
  add_spec_flag(cmd, specs.hetatm, options.include_hetatm);
  add_spec_flag(cmd, specs.waters, options.include_waters);
}

void add_surface_pipeline_options(CLI::App& cmd, SurfacePipelineOptions& options) {
  const SurfaceOptionSpecs& specs = kSurfaceOptionSpecs;
  const ProcessingOptionSpecs& processing = kProcessingOptionSpecs;
  add_spec_option(cmd, specs.surface, options.surface)
      ->transform(choice_of(kSurfaceKinds, surface_kind_name))
      ->default_str(surface_kind_name(options.surface))
      ->type_name("ses|sas|vdw|gaussian");
  add_spec_option(cmd, specs.probe_radius, options.probe_radius)
      ->capture_default_str()
      ->type_name("R");
  cmd.add_flag_function(
      cli_names(specs.keep_on_surface),
      [&options](std::int64_t count) { options.keep_on_surface = count > 0; },
      cli_help(specs.keep_on_surface));
  add_spec_option(cmd, specs.spacing, options.blur.spacing)->capture_default_str()->type_name("H");
  add_spec_option(cmd, specs.blobbyness, options.blur.blobbyness)
      ->capture_default_str()
      ->type_name("B");
  // Only finite here: a volume input's level may be zero or negative (a potential map), so
  // the atoms' range (0, inf) is checked by SurfacePipelineOptions::validate() once the input
  // is known (docs/cli.md).
  cmd.add_option(cli_names(specs.isovalue), options.isovalue,
                 cli_help(specs.isovalue, "; > 0 for atoms, any finite level for a volume input"))
      ->check(finite_in(-kLargestValue, kLargestValue))
      ->capture_default_str()
      ->type_name("T");
  add_spec_option(cmd, specs.min_cavity_volume, options.min_cavity_volume)
      ->capture_default_str()
      ->type_name("V");
  add_max_memory_option(cmd, options.blur.max_memory_bytes);
  add_spec_flag(cmd, specs.raw, options.raw);
  add_spec_option(cmd, specs.blur, options.blur_method)
      ->transform(choice_of(kBlurMethods, blur_method_name))
      ->default_str(blur_method_name(options.blur_method))
      ->type_name("exact|fast");
  add_spec_option(cmd, specs.coarsen, options.processing.t0)
      ->delimiter(',')
      ->capture_default_str()
      ->type_name("T0[,T0...]");
  add_spec_option(cmd, processing.rings, options.processing.rings)
      ->capture_default_str()
      ->type_name("K");
  add_spec_option(cmd, processing.alpha, options.processing.alpha)
      ->capture_default_str()
      ->type_name("A");
  add_spec_option(cmd, processing.beta, options.processing.beta)
      ->capture_default_str()
      ->type_name("B");
  add_spec_option(cmd, specs.keep_spheres, options.keep_spheres_file, "",
                  " (a file of x y z r lines)")
      ->check(CLI::ExistingFile)
      ->type_name("FILE");
}

void add_surface_options(CLI::App& cmd, SurfaceCliOptions& options) {
  add_atom_options(cmd, options.atoms);
  add_surface_pipeline_options(cmd, options.pipeline);
}

}  // namespace molmesh::cli
