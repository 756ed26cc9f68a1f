#include "molmesh/io/stats_json.hpp"

#include <map>
#include <ostream>
#include <string>

#include "molmesh/core/atomic_file.hpp"

namespace molmesh {

nlohmann::json to_json(const SurfaceStats& s) {
  nlohmann::json j;
  j["vertices"] = s.vertices;
  j["triangles"] = s.triangles;
  j["min_angle_deg"] = s.min_angle_deg;
  j["max_angle_deg"] = s.max_angle_deg;
  j["angle_histogram_percent"] = s.angle_histogram_percent;
  j["fraction_angles_40_80"] = s.fraction_angles_40_80;
  j["area"] = s.area;
  j["volume"] = s.volume;
  j["components"] = s.components;
  j["euler_characteristic"] = s.euler_characteristic;
  j["closed"] = s.closed;
  j["manifold"] = s.manifold;
  return j;
}

nlohmann::json to_json(const TetStats& s) {
  auto keyed = [](const std::map<int, std::size_t>& m) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : m) j[std::to_string(k)] = v;
    return j;
  };
  nlohmann::json j;
  j["vertices"] = s.vertices;
  j["tetrahedra"] = s.tetrahedra;
  j["boundary_faces"] = s.boundary_faces;
  j["tetrahedra_per_region"] = keyed(s.tets_per_region);
  j["faces_per_marker"] = keyed(s.faces_per_marker);
  j["vertices_per_marker"] = keyed(s.vertices_per_marker);
  j["min_dihedral_deg"] = s.min_dihedral_deg;
  j["max_dihedral_deg"] = s.max_dihedral_deg;
  j["dihedral_histogram_10deg"] = s.dihedral_histogram;
  j["min_volume"] = s.min_volume;
  j["max_volume"] = s.max_volume;
  j["inverted_or_flat"] = s.inverted_or_flat;
  j["min_radius_edge"] = s.min_radius_edge;
  j["max_radius_edge"] = s.max_radius_edge;
  j["mean_radius_edge"] = s.mean_radius_edge;
  j["radius_edge_bins"] = TetStats::kRadiusEdgeBins;
  j["radius_edge_histogram"] = s.radius_edge_histogram;
  return j;
}

nlohmann::json to_json(const MeshRepairReport& r) {
  nlohmann::json j;
  j["merged_vertices"] = r.merged_vertices;
  j["unreferenced_vertices"] = r.unreferenced_vertices;
  j["collapsed_faces"] = r.collapsed_faces;
  j["duplicate_faces"] = r.duplicate_faces;
  j["flipped_cap_faces"] = r.flipped_cap_faces;
  j["remaining_degenerate_faces"] = r.remaining_degenerate_faces;
  j["split_vertices"] = r.split_vertices;
  j["reoriented_faces"] = r.reoriented_faces;
  j["reoriented_components"] = r.reoriented_components;
  j["components"] = r.components;
  return j;
}

nlohmann::json to_json(const std::vector<ProcessingStage>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const ProcessingStage& s : stages)
    out.push_back({{"name", s.name}, {"seconds", s.seconds}, {"stats", to_json(s.stats)}});
  return out;
}

nlohmann::json to_json(const TetMeshReport& report) {
  nlohmann::json tetgen;
  tetgen["switches"] = report.tetgen_switches;
  tetgen["seconds"] = report.seconds;
  tetgen["atoms_given"] = report.atoms_given;
  tetgen["atoms_as_nodes"] = report.atoms_as_nodes;
  tetgen["coincident_atoms"] = report.coincident_atoms;
  tetgen["atoms_outside"] = report.atoms_outside;
  tetgen["surface_steiner_points"] = report.surface_steiner_points;
  tetgen["outer_sphere_vertices"] = report.outer_sphere_vertices;
  tetgen["molecule_size"] = report.molecule_size;
  tetgen["outer_radius"] = report.outer_radius;
  return tetgen;
}

SurfaceStats surface_stats_from_json(const nlohmann::json& j) {
  SurfaceStats s;
  s.vertices = j.at("vertices").get<std::size_t>();
  s.triangles = j.at("triangles").get<std::size_t>();
  s.min_angle_deg = j.at("min_angle_deg").get<double>();
  s.max_angle_deg = j.at("max_angle_deg").get<double>();
  s.angle_histogram_percent = j.at("angle_histogram_percent").get<std::array<double, 18>>();
  s.fraction_angles_40_80 = j.at("fraction_angles_40_80").get<double>();
  s.area = j.at("area").get<double>();
  s.volume = j.at("volume").get<double>();
  s.components = j.at("components").get<int>();
  s.euler_characteristic = j.at("euler_characteristic").get<long>();
  s.closed = j.at("closed").get<bool>();
  s.manifold = j.at("manifold").get<bool>();
  return s;
}

nlohmann::json stats_document(const SurfaceStats& stats, const StageTimings& timings_s,
                              const nlohmann::json& input, const nlohmann::json& parameters) {
  nlohmann::json doc = to_json(stats);
  nlohmann::json timings = nlohmann::json::object();
  for (const auto& [stage, seconds] : timings_s) timings[stage] = seconds;
  doc["timings_s"] = timings;
  doc["input"] = input;
  doc["parameters"] = parameters;
  return doc;
}

void write_json_file(const std::filesystem::path& path, const nlohmann::json& document) {
  write_file_atomically(path, [&](std::ostream& out) { out << document.dump(2) << '\n'; });
}

}  // namespace molmesh
