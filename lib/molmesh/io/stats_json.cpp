#include "molmesh/io/stats_json.hpp"

#include <ostream>

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
