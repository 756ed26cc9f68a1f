// `molmesh info FILE.h5`: what a hierarchy file holds, for humans (sizes, T0, quality,
// the parameters that produced it, transfer operators, stored fields).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>
#include <string>

#include "command_registry.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"

namespace molmesh::cli {
namespace {

// "ses (probe 1.4 A)" / "gaussian (B -0.5, isovalue 1)" from the stored parameters; files
// written before surfaces had kinds were all Gaussian.
std::string surface_description(const std::map<std::string, std::string>& p) {
  auto get = [&](const char* key, const char* fallback) {
    const auto it = p.find(key);
    return it == p.end() ? std::string(fallback) : it->second;
  };
  const std::string kind = get("surface", "gaussian");
  if (kind == "gaussian")
    return kind + " (blobbyness " + get("blobbyness", "?") + ", isovalue " + get("isovalue", "?") +
           ")";
  if (kind == "vdw") return kind;
  return kind + " (probe radius " + get("probe_radius", "?") + " A)";
}

void run(const std::string& path) {
  const Hierarchy h = read_hierarchy(path);
  std::printf("%s: %s version %d, %zu levels (level 0 finest), lengths in angstrom\n", path.c_str(),
              kHierarchyFormatName, kHierarchyFormatVersion, h.levels.size());
  std::printf("input: %s (sha256 %s)\n", h.input_name.c_str(), h.input_checksum.c_str());
  std::printf("surface: %s\n", surface_description(h.parameters).c_str());
  std::printf(
      "\nlevel     T0  surf verts  surf tris  min/max angle   area A^2  volume A^3  vol verts"
      "       tets  min/max dihedral  regions (marker:tets)\n");
  for (std::size_t l = 0; l < h.levels.size(); ++l) {
    const auto& level = h.levels[l];
    const SurfaceStats surface = compute_surface_stats(level.surface);
    const auto stats = compute_tet_stats(level.volume);
    std::string regions;
    for (const auto& [marker, count] : stats.tets_per_region) {
      regions +=
          (regions.empty() ? "" : " ") + std::to_string(marker) + ":" + std::to_string(count);
    }
    std::printf(
        "%5zu  %5.3f  %10zu  %9zu  %5.1f / %5.1f  %9.1f  %10.1f  %9zu  %9zu   %6.2f / %6.2f  %s\n",
        l, level.t0, level.surface.points.size(), level.surface.triangles.size(),
        surface.min_angle_deg, surface.max_angle_deg, surface.area, surface.volume,
        level.volume.points.size(), level.volume.tetrahedra.size(), stats.min_dihedral_deg,
        stats.max_dihedral_deg, regions.c_str());
  }
  if (!h.transfers.empty()) {
    std::printf("\ntransfer   volume P (rows x cols, nnz)     surface P (rows x cols, nnz)\n");
    for (const auto& t : h.transfers) {
      std::printf("%d -> %d    %7ld x %-7ld %9ld     %7ld x %-7ld %9ld\n", t.coarse_level,
                  t.fine_level, static_cast<long>(t.volume.rows()),
                  static_cast<long>(t.volume.cols()), static_cast<long>(t.volume.nonZeros()),
                  static_cast<long>(t.surface.rows()), static_cast<long>(t.surface.cols()),
                  static_cast<long>(t.surface.nonZeros()));
    }
    std::printf("(prolongation P: u_fine = P u_coarse; restriction = P^T)\n");
  }
  for (std::size_t l = 0; l < h.levels.size(); ++l) {
    const auto fields = point_field_names(path, static_cast<int>(l));
    if (fields.empty()) continue;
    std::string names;
    for (const auto& name : fields) names += " " + name;
    std::printf("level %zu point fields:%s\n", l, names.c_str());
  }
  std::printf("\nparameters:\n");
  for (const auto& [key, value] : h.parameters) {
    std::printf("  %-26s %s\n", key.c_str(), value.c_str());
  }
}

const CommandRegistration registration{
    "info", [](CLI::App& app, CliContext&) {
      auto path = std::make_shared<std::string>();
      auto* cmd = app.add_subcommand(
          "info",
          "Summarise a hierarchy file written by `molmesh hierarchy`: levels, sizes, T0, "
          "mesh quality, transfer operators, stored fields and meshing parameters");
      cmd->add_option("file", *path, "Hierarchy HDF5 file (.h5)")->required();
      cmd->callback([path] { run(*path); });
    }};

}  // namespace
}  // namespace molmesh::cli
