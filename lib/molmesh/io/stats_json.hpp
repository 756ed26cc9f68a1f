#pragma once
// The --stats JSON document: the surface metrics as top-level keys (vertices, triangles,
// min_angle_deg, max_angle_deg, angle_histogram_percent, fraction_angles_40_80, area,
// volume, components, euler_characteristic, closed, manifold), plus timings_s
// (stage -> seconds), input and parameters. Described in docs/cli.md.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "molmesh/processing/mesh_repair.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {

nlohmann::json to_json(const SurfaceStats& stats);
// `molmesh tetmesh --stats`: counts per region and marker, dihedral angles, radius-edge
// ratios and volumes (docs/cli.md).
nlohmann::json to_json(const TetStats& stats);
// What `molmesh improve` repaired (the "repair" object of its --stats).
nlohmann::json to_json(const MeshRepairReport& report);
// The "stages" array of molmesh.improve's report: name, seconds, stats of each stage.
nlohmann::json to_json(const std::vector<ProcessingStage>& stages);
// The "tetgen" object of `molmesh tetmesh --stats`: switches, timing, atoms as nodes.
nlohmann::json to_json(const TetMeshReport& report);
SurfaceStats surface_stats_from_json(const nlohmann::json& json);

// Stage timings keep their order (read, blur, marching cubes, ..., write, total).
using StageTimings = std::vector<std::pair<std::string, double>>;

nlohmann::json stats_document(const SurfaceStats& stats, const StageTimings& timings_s,
                              const nlohmann::json& input, const nlohmann::json& parameters);

// Atomic; pretty-printed with a trailing newline.
void write_json_file(const std::filesystem::path& path, const nlohmann::json& document);

}  // namespace molmesh
