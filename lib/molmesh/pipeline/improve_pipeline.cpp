#include "molmesh/pipeline/improve_pipeline.hpp"

#include <string>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/pipeline/improve_option_specs.hpp"

namespace molmesh {

ProcessingOptions user_mesh_processing() {
  ProcessingOptions options;
  options.improve.feature_weight = 2.0;
  return options;
}

void ImprovePipelineOptions::validate() const {
  check_range(kImproveOptionSpecs.merge_tolerance, repair.merge_tolerance);
  processing.validate();  // T0 included: kT0Range, kImproveOptionSpecs.t0 range
}

ImprovePipelineResult improve_surface(const SurfaceMesh& input, std::string_view name,
                                      const ImprovePipelineOptions& options,
                                      const Reporter& reporter) {
  options.validate();
  const std::string label(name);
  if (input.triangles.empty()) throw InputError(label, "the mesh has no triangles");
  ImprovePipelineResult result;
  const auto start = std::chrono::steady_clock::now();
  try {
    result.repaired = repair_surface_mesh(input, options.repair, result.repair, reporter);
  } catch (const Error& e) {
    throw Error(label + ": " + e.what());
  }
  result.repair_seconds = seconds_since(start);
  if (result.repair.repairs() != "nothing to repair")
    reporter.warn("repaired " + label + ": " + result.repair.repairs());
  if (options.repair_only) {
    result.surface = result.repaired;
    return result;
  }
  ProcessingResult processed = process_surface(result.repaired, options.processing, reporter);
  result.stages = std::move(processed.stages);
  result.surface = std::move(processed.mesh);
  return result;
}

}  // namespace molmesh
