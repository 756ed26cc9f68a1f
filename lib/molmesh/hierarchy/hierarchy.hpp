#pragma once
// A multilevel family of meshes for multigrid: level 0 is the finest. Each coarser surface
// is derived from the next finer one by further coarsening, so surfaces are nested by
// provenance; each level's volume mesh is built from that level's surface.
#include <Eigen/SparseCore>
#include <map>
#include <string>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

// Row-major so rows (fine vertices) are contiguous, matching the CSR layout in HDF5.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

struct HierarchyLevel {
  double t0 = 0.0;  // coarsening threshold that produced this level
  SurfaceMesh surface;
  // surface_provenance[v] = index of the vertex of level L-1's surface that coarse vertex v
  // came from; empty for level 0.
  std::vector<int> surface_provenance;
  TetMesh volume;
  // Locality renumbering (reverse Cuthill-McKee) applied to `volume`:
  // volume_permutation[new index] = vertex index in the mesher's output. Empty = identity.
  std::vector<int> volume_permutation;
};

// Prolongation from level `coarse` to level `fine` = coarse - 1. Invariants (tested):
// every row sums to 1, linear functions are reproduced at fine vertices inside the coarse
// mesh, no coarse vertex has an empty column. Restriction is the transpose.
struct LevelTransfer {
  int coarse_level = 1;
  int fine_level = 0;
  SparseMatrix volume;   // fine volume vertices x coarse volume vertices
  SparseMatrix surface;  // fine surface vertices x coarse surface vertices
};

struct Hierarchy {
  std::vector<HierarchyLevel> levels;             // levels[0] finest
  std::vector<LevelTransfer> transfers;           // transfers[i]: level i+1 -> level i
  std::map<std::string, std::string> parameters;  // every meshing parameter, as text
  std::string input_name;
  std::string input_checksum;  // SHA-256 (hex) of the input file's bytes
};

// Throws unless `level` is one of the hierarchy's levels: Error when it has none (a damaged
// input, not a bad `level`), OptionError naming `level` otherwise.
inline void require_level(const Hierarchy& hierarchy, int level) {
  const int levels = static_cast<int>(hierarchy.levels.size());
  if (levels == 0) throw Error("the hierarchy has no levels");
  if (level < 0 || level >= levels) {
    throw OptionError("`level` " + std::to_string(level) + ": the hierarchy has " +
                      std::to_string(levels) + " level(s) (0.." + std::to_string(levels - 1) + ")");
  }
}

}  // namespace molmesh
