#pragma once
// The multilevel hierarchy of GAMer §4.3: level 0 is the input surface processed with the
// first T0; level L+1 is level L's surface coarsened and improved once more with the next
// T0 (so surfaces are nested by provenance, and coarsening several times with growing T0
// preserves features better than one large T0, as the paper observes). Every level's
// volume mesh is built from its own surface with the same domain, markers and outer sphere
// (the outer radius is fixed from level 0 and reused, so all levels cover the same domain),
// renumbered for locality, and consecutive levels are linked by prolongation operators.
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/hierarchy/transfer.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {

// The size_growth range HierarchyOptions::validate() accepts, for the front ends that check
// values while parsing (the CLI's --size-growth) with the same bounds: 1 keeps the far field
// of level 0 on every level; beyond 10 the fourth level's target size is 1000 x level 0's.
inline constexpr double kMinSizeGrowth = 1.0;
inline constexpr double kMaxSizeGrowth = 10.0;

struct HierarchyOptions {
  // One level per value, finest first; must be non-decreasing and non-empty. The paper's
  // Fig. 11 series.
  std::vector<double> t0 = {0.1, 0.3, 0.5, 0.7};
  ProcessingOptions processing;  // processing.t0 is replaced by one T0 per level
  TetMeshOptions tetmesh;
  // Level L meshes its volume with tetmesh.size_factor * size_growth^L (when grading is
  // on). T0 coarsens only the surface; the far field between molecule and outer sphere is
  // the same on every level unless its target size grows too, and on exterior meshes the
  // far field is most of the mesh (docs/hierarchy.md).
  double size_growth = 1.5;
  bool renumber = true;  // reverse Cuthill-McKee on every volume mesh

  // Throws Error naming the option (`t0`, `size_growth`) when the T0 list is empty,
  // negative or decreasing, or size_growth is not a finite number in [kMinSizeGrowth,
  // kMaxSizeGrowth], and what processing.validate() and tetmesh.validate() throw;
  // build_hierarchy() calls it first, before any level is built.
  void validate() const;
};

struct HierarchyLevelReport {
  double surface_seconds = 0.0;
  double volume_seconds = 0.0;
  double renumber_seconds = 0.0;
  double transfer_seconds = 0.0;  // building the operator to the next finer level
  int bandwidth_before = 0;       // vertex bandwidth of TetGen's numbering
  int bandwidth_after = 0;        // after renumbering
  TransferStats volume_transfer;  // to the next finer level (levels > 0)
  TransferStats surface_transfer;
  TetMeshReport tetmesh;
};

struct HierarchyReport {
  std::vector<HierarchyLevelReport> levels;
  double outer_radius = 0.0;  // Å, shared by all levels (0 for interior meshes)
  double seconds = 0.0;
};

// `surface`: the (raw or processed) molecular surface that level 0 is derived from.
// Throws molmesh::Error on invalid options or when a stage fails (the message says which
// level).
Hierarchy build_hierarchy(const SurfaceMesh& surface, const Atoms& atoms,
                          const HierarchyOptions& options, const Reporter& reporter = {},
                          HierarchyReport* report = nullptr);

// Molecular-surface markers for a hierarchy surface: kActiveSite for faces whose three
// vertices lie in an active-site sphere (and those vertices), kMolecularSurface otherwise.
void mark_surface(SurfaceMesh& surface, const std::vector<Sphere>& active_site);

}  // namespace molmesh
