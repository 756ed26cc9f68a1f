#pragma once
// Every level of a Hierarchy as the files other solvers read (`molmesh export`):
//   PREFIX_L<L>_volume.m      FETK MCSF (MC, APBS `usemesh`, SMOL)
//   PREFIX_L<L>_volume.vtu    VTK XML (ParaView, meshio)
//   PREFIX_L<L>_volume.msh    Gmsh 2.2
//   PREFIX_L<L>_surface.vtu   the level's molecular surface (VTK XML)
//   PREFIX_L<L>_surface.off   the same surface as OFF
//   PREFIX_P<c>_to_<f>_volume.petsc / .mtx    volume prolongation (fine x coarse)
//   PREFIX_P<c>_to_<f>_surface.petsc / .mtx   surface prolongation
// Vertex i of every exported mesh is vertex i of the HDF5 level (its RCM order), so the
// prolongations apply to the exported meshes directly; docs/formats.md has the markers.
#include <filesystem>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh {

struct ExportOptions {
  int level = -1;  // -1: every level; otherwise only this one
  bool meshes = true;
  bool prolongations = true;  // those whose fine level is exported
};

// Returns the files written, in order. Throws molmesh::Error for a level the hierarchy
// does not have, OutputError when a file cannot be written.
std::vector<std::filesystem::path> export_hierarchy(const Hierarchy& hierarchy,
                                                    const std::filesystem::path& prefix,
                                                    const ExportOptions& options = {});

}  // namespace molmesh
