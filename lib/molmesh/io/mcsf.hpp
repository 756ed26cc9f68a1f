#pragma once
// FETK's MCSF ("MC simplex format") volume meshes, as MC's Gem_read, APBS (fe-manual,
// usemesh) and SMOL read them. Face types: 0 interior, odd Dirichlet, even Neumann. The
// material column carries the region marker.
#include <filesystem>

#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

// MCSF face type of each boundary marker. Faces shared by two tetrahedra are always type 0
// (so in a full mesh the molecular surface is interior); only faces on the mesh boundary
// get these. Defaults are what APBS and SMOL expect: the outer sphere Dirichlet (5), the
// molecular surface of an exterior mesh reflective Neumann (4), the active site absorbing
// Dirichlet (3). Unmarked boundary faces get `other`.
struct McsfFaceTypes {
  int molecular_surface = 4;
  int outer_sphere = 5;
  int active_site = 3;
  int other = 1;
};

// Writes vertices and positively oriented simplices (0-based ids in line order). Throws
// OutputError if the file cannot be written.
void write_mcsf(const std::filesystem::path& path, const TetMesh& mesh,
                const McsfFaceTypes& types = {});

// Reads an MCSF file back: points, tetrahedra (reoriented positively if needed), cell
// markers from the material column, and boundary faces (non-zero face types, oriented
// outward) with markers mapped back through `types` (unknown types keep marker = type +
// 100, so nothing is silently lost). Vertex markers: the highest-priority marker of the
// faces around each vertex. Throws InputError (file:line) on malformed input.
TetMesh read_mcsf(const std::filesystem::path& path, const McsfFaceTypes& types = {});

}  // namespace molmesh
