#pragma once
// JSON of what the pipelines report, for `--stats` and the Python module's `.report` alike
// (one writer each; docs/cli.md). Here rather than in io/, which the pipeline sits on.
#include <nlohmann/json.hpp>
#include <vector>

#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh {

// The "stages" array: name, seconds and stats (null when not measured) of each stage.
nlohmann::json to_json(const std::vector<StageRecord>& stages);

// dislocation_max and dislocation_mean (Å) into j: the one spelling for `surface` and
// `improve` (issue 17; `improve` wrote dislocation {max, mean} until session 28).
void add_dislocation(nlohmann::json& j, const Dislocation& dislocation);

// What the surface pipeline measured: stages, dislocation_max, dislocation_mean (Å) and, for
// the Gaussian surface of atoms, levelset_distance_{mean,max} and centroid_distance_{mean,max}.
nlohmann::json surface_result_json(const SurfacePipelineResult& result);

// `molmesh hierarchy --stats`: levels (seconds per step, bandwidths, transfer repairs, the
// tetgen object of `tetmesh --stats`), outer_radius (Å), seconds.
nlohmann::json to_json(const HierarchyReport& report);

}  // namespace molmesh
