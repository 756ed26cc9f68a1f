#include "molmesh/hierarchy/build_hierarchy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/hierarchy/hierarchy_option_specs.hpp"
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

void HierarchyOptions::validate() const {
  if (t0.empty()) throw OptionError("hierarchy: give at least one T0 value (`t0`)");
  for (std::size_t i = 0; i < t0.size(); ++i) {
    check_range(kHierarchyOptionSpecs.t0, t0[i]);
    if (i > 0 && t0[i] < t0[i - 1]) {
      throw OptionError("hierarchy: T0 values (`t0`) must not decrease (level 0 is the finest)");
    }
  }
  check_range(kHierarchyOptionSpecs.size_growth, size_growth);
  // Every level's processing and volume options, before level 0's surface is processed
  // (a bad value would otherwise surface only when the first level reaches it). Each level
  // replaces processing.t0 by its own T0, checked above.
  ProcessingOptions level_processing = processing;
  level_processing.t0 = {t0.front()};
  level_processing.validate();
  tetmesh.validate();
}

namespace {

// Level `level`'s surface, processed from level L-1's (level 0: from the input surface),
// and marked. Progress goes to `reporter` as the level's first share.
void process_level_surface(Hierarchy& hierarchy, HierarchyReport& report, int level,
                           const SurfaceMesh& surface, const HierarchyOptions& options,
                           const TetMeshOptions& tet_options, const Reporter& reporter,
                           double share) {
  const auto L = static_cast<std::size_t>(level);
  HierarchyLevel& out = hierarchy.levels[L];
  const auto tick = std::chrono::steady_clock::now();
  out.t0 = options.t0[L];
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
    throw Error("hierarchy level " + std::to_string(level) + " (T0 = " +
                std::to_string(options.t0[L]) + "): surface processing failed: " + e.what());
  }
  mark_surface(out.surface, tet_options.active_site);
  report.levels[L].surface_seconds = seconds_since(tick);
  reporter.progress("hierarchy", (2.0 * level + 1.0) * share);
}

// Reverse Cuthill-McKee renumbering of a level's volume (when asked for), with the
// bandwidths before and after.
void renumber_level(HierarchyLevel& out, HierarchyLevelReport& level_report, bool renumber) {
  const auto tick = std::chrono::steady_clock::now();
  level_report.bandwidth_before = vertex_bandwidth(out.volume);
  if (renumber) {
    out.volume_permutation = reverse_cuthill_mckee(out.volume);
    out.volume = sort_cells_by_vertex(permute_vertices(out.volume, out.volume_permutation));
  }
  level_report.bandwidth_after = vertex_bandwidth(out.volume);
  level_report.renumber_seconds = seconds_since(tick);
}

// The prolongations from level `level` to the finer level-1.
void build_transfer(Hierarchy& hierarchy, HierarchyLevelReport& level_report, int level) {
  const auto L = static_cast<std::size_t>(level);
  const auto tick = std::chrono::steady_clock::now();
  const HierarchyLevel& out = hierarchy.levels[L];
  const HierarchyLevel& fine = hierarchy.levels[L - 1];
  LevelTransfer& transfer = hierarchy.transfers[L - 1];
  transfer.coarse_level = level;
  transfer.fine_level = level - 1;
  transfer.volume = volume_prolongation(out.volume, fine.volume, &level_report.volume_transfer);
  transfer.surface = surface_prolongation(out.surface, fine.surface, out.surface_provenance,
                                          &level_report.surface_transfer);
  level_report.transfer_seconds = seconds_since(tick);
}

// Level `level`'s volume, then its renumbering and its transfer to level-1 (finished before
// this runs): none needs the next level, so all run on the volume thread, beside the next
// level's surface processing. Warnings are collected, so that only the calling thread
// calls the reporter.
void mesh_level_volume(Hierarchy& hierarchy, HierarchyReport& report, int level, const Atoms& atoms,
                       const HierarchyOptions& options, const TetMeshOptions& tet_options,
                       std::vector<std::string>& warnings) {
  const auto L = static_cast<std::size_t>(level);
  const auto tick = std::chrono::steady_clock::now();
  Reporter tet_sub;
  tet_sub.on_warning = [&warnings](std::string_view w) { warnings.emplace_back(w); };
  try {
    TetMeshOptions level_options = tet_options;
    level_options.size_factor = tet_options.size_factor * std::pow(options.size_growth, level);
    hierarchy.levels[L].volume = tetrahedralize(hierarchy.levels[L].surface, atoms, level_options,
                                                tet_sub, &report.levels[L].tetmesh);
  } catch (const Error& e) {
    throw Error("hierarchy level " + std::to_string(level) +
                ": volume meshing failed: " + e.what());
  }
  report.levels[L].volume_seconds = seconds_since(tick);
  renumber_level(hierarchy.levels[L], report.levels[L], options.renumber);
  if (level > 0) build_transfer(hierarchy, report.levels[L], level);
}

}  // namespace

Hierarchy build_hierarchy(const SurfaceMesh& surface, const Atoms& atoms,
                          const HierarchyOptions& options, const Reporter& reporter,
                          HierarchyReport* report) {
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  const int count = static_cast<int>(options.t0.size());
  // Progress: each level's surface and its volume (with its transfer), as equal shares.
  const double share = 1.0 / (2.0 * count);
  Hierarchy hierarchy;
  HierarchyReport local;
  TetMeshOptions tet_options = options.tetmesh;
  hierarchy.levels.resize(static_cast<std::size_t>(count));
  local.levels.resize(static_cast<std::size_t>(count));

  // TetGen is single-threaded, and level L+1's surface needs only level L's surface, so
  // TetGen meshes level L (then renumbers it and builds its transfer to level L-1) while
  // level L+1's surface is processed on the other core. Each computation is deterministic
  // and reads only finished inputs, so the hierarchy is the same as a sequential run's,
  // whatever the thread count.
  hierarchy.transfers.resize(static_cast<std::size_t>(std::max(0, count - 1)));
  process_level_surface(hierarchy, local, 0, surface, options, tet_options, reporter, share);
  for (int level = 0; level < count; ++level) {
    std::vector<std::string> warnings;
    std::exception_ptr volume_error;
    std::thread volume_thread([&] {
      try {
        mesh_level_volume(hierarchy, local, level, atoms, options, tet_options, warnings);
      } catch (...) {
        volume_error = std::current_exception();
      }
    });
    std::exception_ptr surface_error;
    if (level + 1 < count) {
      try {
        process_level_surface(hierarchy, local, level + 1, surface, options, tet_options, reporter,
                              share);
      } catch (...) {
        surface_error = std::current_exception();
      }
    }
    volume_thread.join();
    for (const std::string& w : warnings) reporter.warn(w);
    if (volume_error) std::rethrow_exception(volume_error);  // the earlier level's failure first
    if (surface_error) std::rethrow_exception(surface_error);

    if (level == 0) {
      // Every level must mesh the same domain: freeze the outer radius level 0 chose.
      local.outer_radius = local.levels[0].tetmesh.outer_radius;
      if (tet_options.domain != Domain::interior && local.outer_radius > 0.0) {
        tet_options.outer_radius = local.outer_radius;
      }
    }
    reporter.progress("hierarchy", (2.0 * level + 2.0) * share);
  }
  reporter.progress("hierarchy", 1.0);
  local.seconds = seconds_since(start);
  if (report) *report = local;
  return hierarchy;
}

}  // namespace molmesh
