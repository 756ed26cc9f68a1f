#pragma once
// TetGen's output as a molmesh TetMesh. Internal (TetGen's types are not part of molmesh's
// API): tetrahedralize() is its one caller.
//
// TetGen's tetrahedra are split into regions, tets connected across faces that are not on
// an input facet; each region is classified by the winding number of the molecular surface
// at one tet's centroid, so cavities (inside the surface but outside the molecule) come out
// as solvent. The wanted regions are compacted (kept tets and the points they use, in
// TetGen's order), with cell markers (kMoleculeRegion / kSolventRegion), the boundary faces
// of the kept set and, when both regions are kept, the molecule/solvent interface once,
// oriented out of the molecule, each with its input facet's marker, and vertex markers from
// the faces around them (markers.hpp).
#include <tetgen.h>

#include <cstddef>

#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::detail {

struct TetGenOutputOptions {
  bool keep_molecule = true;
  bool keep_solvent = true;
  // Input points before TetGen's own: a kept point at or beyond this index that carries a
  // molecular-surface marker is a Steiner point TetGen added on the surface.
  int input_points = 0;
};

// `out`: TetGen's result with neighbours (switch n), numbered from 0. Throws Error when
// TetGen produced no tetrahedra or none lies in the kept regions.
TetMesh mesh_from_tetgen(const tetgenio& out, const SurfaceMesh& molecular_surface,
                         const TetGenOutputOptions& options,
                         std::size_t* surface_steiner_points = nullptr);

}  // namespace molmesh::detail
