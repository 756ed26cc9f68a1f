// `molmesh stats`: quality and topology metrics of a surface mesh file.
#include <cstdio>
#include <string>

#include "command_registry.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/surface/surface_stats.hpp"

namespace molmesh::cli {
namespace {

struct StatsArgs {
  std::string mesh;
  bool json = false;
};

void print_table(const std::string& path, const SurfaceStats& s) {
  std::printf("%s\n", path.c_str());
  std::printf("  vertices               %zu\n", s.vertices);
  std::printf("  triangles              %zu\n", s.triangles);
  std::printf("  min angle (deg)        %.2f\n", s.min_angle_deg);
  std::printf("  max angle (deg)        %.2f\n", s.max_angle_deg);
  std::printf("  angles in [40,80]      %.1f %%\n", 100.0 * s.fraction_angles_40_80);
  std::printf("  area (A^2)             %.2f\n", s.area);
  std::printf("  volume (A^3)           %.2f\n", s.volume);
  std::printf("  components             %d\n", s.components);
  std::printf("  Euler characteristic   %ld\n", s.euler_characteristic);
  std::printf("  closed                 %s\n", s.closed ? "yes" : "no");
  std::printf("  manifold               %s\n", s.manifold ? "yes" : "no");
  std::printf("  angle histogram (%% of angles per 10 deg)\n");
  for (std::size_t b = 0; b < s.angle_histogram_percent.size(); ++b)
    std::printf("    %3zu-%3zu  %6.2f\n", 10 * b, 10 * b + 10, s.angle_histogram_percent[b]);
}

const CommandRegistration registration{
    "stats", [](CLI::App& app, CliContext&) {
      auto args = std::make_shared<StatsArgs>();
      auto* cmd = app.add_subcommand(
          "stats",
          "Quality and topology metrics of a surface mesh (angles, area, volume, closed, "
          "manifold, components, Euler characteristic)");
      cmd->add_option("MESH", args->mesh, "Surface mesh: .off, .ply, .obj, .stl")
          ->required()
          ->check(CLI::ExistingFile);
      cmd->add_flag("--json", args->json,
                    "Print the metrics as JSON (the keys of the --stats file of `surface`)");
      cmd->callback([args] {
        const SurfaceStats s = compute_surface_stats(read_surface_mesh(args->mesh));
        if (args->json)
          std::printf("%s\n", to_json(s).dump(2).c_str());
        else
          print_table(args->mesh, s);
      });
    }};

}  // namespace
}  // namespace molmesh::cli
