#include "molmesh/io/hierarchy_export.hpp"

#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/gmsh.hpp"
#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/sparse_matrix_io.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/vtu.hpp"

namespace molmesh {

std::vector<std::filesystem::path> export_hierarchy(const Hierarchy& hierarchy,
                                                    const std::filesystem::path& prefix,
                                                    const ExportOptions& options) {
  const int levels = static_cast<int>(hierarchy.levels.size());
  // Level -1 (every level) needs level 0.
  require_level(hierarchy, options.level == -1 ? 0 : options.level);
  const std::string stem = prefix.string();
  std::vector<std::filesystem::path> written;
  auto name = [&](const std::string& suffix) {
    written.emplace_back(stem + suffix);
    return written.back();
  };
  auto exported = [&](int level) { return options.level == -1 || options.level == level; };
  for (int l = 0; l < levels; ++l) {
    if (!exported(l) || !options.meshes) continue;
    const HierarchyLevel& level = hierarchy.levels[static_cast<std::size_t>(l)];
    const std::string base = "_L" + std::to_string(l);
    write_mcsf(name(base + "_volume.m"), level.volume);
    write_vtu(name(base + "_volume.vtu"), level.volume);
    write_gmsh(name(base + "_volume.msh"), level.volume);
    if (!level.surface.triangles.empty()) {
      write_vtu(name(base + "_surface.vtu"), level.surface);
      write_surface_mesh(name(base + "_surface.off"), level.surface);
    }
  }
  if (options.prolongations) {
    for (const LevelTransfer& t : hierarchy.transfers) {
      if (!exported(t.fine_level)) continue;
      const std::string base =
          "_P" + std::to_string(t.coarse_level) + "_to_" + std::to_string(t.fine_level);
      const std::string what = "molmesh prolongation level " + std::to_string(t.coarse_level) +
                               " -> " + std::to_string(t.fine_level) +
                               " (fine x coarse vertices; restriction = transpose)";
      write_petsc_binary(name(base + "_volume.petsc"), t.volume);
      write_matrix_market(name(base + "_volume.mtx"), t.volume, what + ", volume");
      if (t.surface.rows() > 0) {
        write_petsc_binary(name(base + "_surface.petsc"), t.surface);
        write_matrix_market(name(base + "_surface.mtx"), t.surface, what + ", surface");
      }
    }
  }
  return written;
}

}  // namespace molmesh
