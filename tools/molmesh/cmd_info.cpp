// `molmesh info FILE.h5`: what a hierarchy file holds, for humans (sizes, T0, quality,
// the parameters that produced it, transfer operators, stored fields).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "command_registry.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"

namespace molmesh::cli {
namespace {

// Smallest and largest triangle angle (degrees).
std::pair<double, double> angle_range(const SurfaceMesh& mesh) {
  double lo = 180.0, hi = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      const Vec3& b =
          mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
      const Vec3& c =
          mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])];
      const double angle =
          std::atan2((b - a).cross(c - a).norm(), (b - a).dot(c - a)) * 180.0 / std::numbers::pi;
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
  }
  return {lo, hi};
}

void run(const std::string& path) {
  const Hierarchy h = read_hierarchy(path);
  std::printf("%s: %s version %d, %zu levels (level 0 finest), lengths in angstrom\n", path.c_str(),
              kHierarchyFormatName, kHierarchyFormatVersion, h.levels.size());
  std::printf("input: %s (sha256 %s)\n", h.input_name.c_str(), h.input_checksum.c_str());
  std::printf(
      "\nlevel     T0  surf verts  surf tris  min/max angle  vol verts       tets"
      "  min/max dihedral  regions (marker:tets)\n");
  for (std::size_t l = 0; l < h.levels.size(); ++l) {
    const auto& level = h.levels[l];
    const auto [amin, amax] = angle_range(level.surface);
    const auto stats = compute_tet_stats(level.volume);
    std::string regions;
    for (const auto& [marker, count] : stats.tets_per_region) {
      regions +=
          (regions.empty() ? "" : " ") + std::to_string(marker) + ":" + std::to_string(count);
    }
    std::printf("%5zu  %5.3f  %10zu  %9zu  %5.1f / %5.1f  %9zu  %9zu   %6.2f / %6.2f  %s\n", l,
                level.t0, level.surface.points.size(), level.surface.triangles.size(), amin, amax,
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
