#include "molmesh/pipeline/report_json.hpp"

#include "molmesh/io/stats_json.hpp"

namespace molmesh {
namespace {

nlohmann::json to_json(const TransferStats& s) {
  return {{"fine_outside", s.fine_outside}, {"empty_columns_repaired", s.empty_columns_repaired}};
}

}  // namespace

nlohmann::json to_json(const std::vector<StageRecord>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const StageRecord& stage : stages) {
    out.push_back({{"name", stage.name},
                   {"seconds", stage.seconds},
                   {"stats", stage.stats ? to_json(*stage.stats) : nlohmann::json()}});
  }
  return out;
}

void add_dislocation(nlohmann::json& j, const Dislocation& dislocation) {
  j["dislocation_max"] = dislocation.max;
  j["dislocation_mean"] = dislocation.mean;
}

nlohmann::json surface_result_json(const SurfacePipelineResult& result) {
  nlohmann::json j;
  add_dislocation(j, result.dislocation);
  if (result.level_set_distance) {
    const LevelSetDistance& d = *result.level_set_distance;
    j["levelset_distance_mean"] = d.vertex_mean;
    j["levelset_distance_max"] = d.vertex_max;
    j["centroid_distance_mean"] = d.centroid_mean;
    j["centroid_distance_max"] = d.centroid_max;
  }
  j["stages"] = to_json(result.stages);
  return j;
}

nlohmann::json to_json(const HierarchyReport& report) {
  nlohmann::json levels = nlohmann::json::array();
  for (const HierarchyLevelReport& l : report.levels) {
    levels.push_back({{"surface_seconds", l.surface_seconds},
                      {"volume_seconds", l.volume_seconds},
                      {"renumber_seconds", l.renumber_seconds},
                      {"transfer_seconds", l.transfer_seconds},
                      {"bandwidth_before", l.bandwidth_before},
                      {"bandwidth_after", l.bandwidth_after},
                      {"volume_transfer", to_json(l.volume_transfer)},
                      {"surface_transfer", to_json(l.surface_transfer)},
                      {"tetgen", to_json(l.tetmesh)}});
  }
  return {{"levels", levels}, {"outer_radius", report.outer_radius}, {"seconds", report.seconds}};
}

}  // namespace molmesh
