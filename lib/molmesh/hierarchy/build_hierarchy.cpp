#include "molmesh/hierarchy/build_hierarchy.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/hierarchy/renumber.hpp"
#include "molmesh/tetmesh/markers.hpp"

namespace molmesh {

void mark_surface(SurfaceMesh& surface, const std::vector<Sphere>& active_site) {
  surface.face_markers.assign(surface.triangles.size(), markers::kMolecularSurface);
  surface.vertex_markers.assign(surface.points.size(), markers::kMolecularSurface);
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const auto& t = surface.triangles[f];
    if (markers::in_active_site(surface.points, t, active_site)) {
      surface.face_markers[f] = markers::kActiveSite;
      for (int v : t) surface.vertex_markers[static_cast<std::size_t>(v)] = markers::kActiveSite;
    }
  }
}

Hierarchy build_hierarchy(const SurfaceMesh& surface, const Atoms& atoms,
                          const HierarchyOptions& options, const Reporter& reporter,
                          HierarchyReport* report) {
  const auto start = std::chrono::steady_clock::now();
  if (options.t0.empty()) throw Error("hierarchy: give at least one T0 value (--t0)");
  for (std::size_t i = 0; i < options.t0.size(); ++i) {
    if (!(options.t0[i] >= 0.0)) throw Error("hierarchy: T0 values must be >= 0");
    if (i > 0 && options.t0[i] < options.t0[i - 1]) {
      throw Error("hierarchy: T0 values must not decrease (level 0 is the finest)");
    }
  }
  if (!(options.size_growth >= 1.0) || !std::isfinite(options.size_growth)) {
    throw Error("hierarchy: the size growth per level must be a number >= 1 (got " +
                std::to_string(options.size_growth) + ")");
  }
  const int count = static_cast<int>(options.t0.size());
  // Progress: each level's surface + volume, then the transfers, as equal shares.
  const double share = 1.0 / (2.0 * count + 1.0);
  Hierarchy hierarchy;
  HierarchyReport local;
  TetMeshOptions tet_options = options.tetmesh;
  for (int level = 0; level < count; ++level) {
    const auto L = static_cast<std::size_t>(level);
    HierarchyLevelReport level_report;
    const std::string name = "level " + std::to_string(level);
    HierarchyLevel out;
    out.t0 = options.t0[L];

    auto tick = std::chrono::steady_clock::now();
    ProcessingOptions processing = options.processing;
    processing.t0 = {options.t0[L]};
    processing.record_stages = false;
    const SurfaceMesh& source = level == 0 ? surface : hierarchy.levels[L - 1].surface;
    Reporter sub;
    sub.on_warning = reporter.on_warning;
    if (reporter.on_progress) {
      sub.on_progress = [&, base = 2.0 * level * share](std::string_view, double f) {
        reporter.progress("hierarchy", base + f * share);
      };
    }
    try {
      auto processed = process_surface(source, processing, sub);
      out.surface = std::move(processed.mesh);
      if (level > 0) out.surface_provenance = std::move(processed.provenance);
    } catch (const Error& e) {
      throw Error("hierarchy " + name + " (T0 = " + std::to_string(options.t0[L]) +
                  "): surface processing failed: " + e.what());
    }
    mark_surface(out.surface, tet_options.active_site);
    level_report.surface_seconds = seconds_since(tick);
    reporter.progress("hierarchy", (2.0 * level + 1.0) * share);

    tick = std::chrono::steady_clock::now();
    Reporter tet_sub;
    tet_sub.on_warning = reporter.on_warning;
    try {
      TetMeshOptions level_options = tet_options;
      level_options.size_factor = tet_options.size_factor * std::pow(options.size_growth, level);
      out.volume =
          tetrahedralize(out.surface, atoms, level_options, tet_sub, &level_report.tetmesh);
    } catch (const Error& e) {
      throw Error("hierarchy " + name + ": volume meshing failed: " + e.what());
    }
    if (level == 0) {
      // Every level must mesh the same domain: freeze the outer radius level 0 chose.
      local.outer_radius = level_report.tetmesh.outer_radius;
      if (tet_options.domain != Domain::interior && local.outer_radius > 0.0) {
        tet_options.outer_radius = local.outer_radius;
      }
    }
    level_report.volume_seconds = seconds_since(tick);

    tick = std::chrono::steady_clock::now();
    level_report.bandwidth_before = vertex_bandwidth(out.volume);
    if (options.renumber) {
      out.volume_permutation = reverse_cuthill_mckee(out.volume);
      out.volume = sort_cells_by_vertex(permute_vertices(out.volume, out.volume_permutation));
    }
    level_report.bandwidth_after = vertex_bandwidth(out.volume);
    level_report.renumber_seconds = seconds_since(tick);
    reporter.progress("hierarchy", (2.0 * level + 2.0) * share);

    hierarchy.levels.push_back(std::move(out));
    local.levels.push_back(level_report);
  }

  for (int fine = 0; fine + 1 < count; ++fine) {
    const auto tick = std::chrono::steady_clock::now();
    const auto& f = hierarchy.levels[static_cast<std::size_t>(fine)];
    const auto& c = hierarchy.levels[static_cast<std::size_t>(fine) + 1];
    auto& level_report = local.levels[static_cast<std::size_t>(fine) + 1];
    LevelTransfer transfer;
    transfer.coarse_level = fine + 1;
    transfer.fine_level = fine;
    transfer.volume = volume_prolongation(c.volume, f.volume, &level_report.volume_transfer);
    transfer.surface = surface_prolongation(c.surface, f.surface, c.surface_provenance,
                                            &level_report.surface_transfer);
    hierarchy.transfers.push_back(std::move(transfer));
    level_report.transfer_seconds = seconds_since(tick);
    reporter.progress("hierarchy", (2.0 * count + (fine + 1.0) / count) * share);
  }
  reporter.progress("hierarchy", 1.0);
  local.seconds = seconds_since(start);
  if (report) *report = local;
  return hierarchy;
}

}  // namespace molmesh
