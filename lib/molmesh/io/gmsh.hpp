#pragma once
// Gmsh MSH files (ASCII 2.2 and 4.1). Physical groups come from the markers: volumes are
// the regions (1 molecule, 2 solvent), surfaces the boundary markers (1 molecular surface,
// 2 outer sphere, 3 active site), named in $PhysicalNames.
#include <filesystem>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

enum class GmshVersion { v2_2, v4_1 };

void write_gmsh(const std::filesystem::path& path, const TetMesh& mesh,
                GmshVersion version = GmshVersion::v2_2);

}  // namespace molmesh
