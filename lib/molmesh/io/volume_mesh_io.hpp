#pragma once
// Volume-mesh output chosen by file extension: .m / .mcsf (FETK MCSF), .vtu (VTK XML),
// .msh (Gmsh 2.2; .msh4 for Gmsh 4.1).
#include <filesystem>
#include <string>
#include <vector>

#include "molmesh/io/vtu.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

// Throws molmesh::Error for an unknown extension (naming the known ones).
void write_volume_mesh(const std::filesystem::path& path, const TetMesh& mesh,
                       const std::vector<PointField>& point_fields = {});

// Reads .m / .mcsf files (the only volume format molmesh reads back).
TetMesh read_volume_mesh(const std::filesystem::path& path);

// The extensions write_volume_mesh accepts, for help texts.
std::string volume_mesh_extensions();

}  // namespace molmesh
