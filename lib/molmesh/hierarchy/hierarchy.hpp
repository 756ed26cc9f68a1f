#pragma once
// A multilevel family of meshes for multigrid: level 0 is the finest. Each coarser surface
// is derived from the next finer one by further coarsening, so surfaces are nested by
// provenance; each level's volume mesh is built from that level's surface.
#include <Eigen/SparseCore>
#include <map>
#include <string>
#include <vector>

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

}  // namespace molmesh
