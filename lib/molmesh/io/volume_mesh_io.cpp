#include "molmesh/io/volume_mesh_io.hpp"

#include <algorithm>
#include <cctype>

#include "molmesh/core/error.hpp"
#include "molmesh/io/gmsh.hpp"
#include "molmesh/io/mcsf.hpp"

namespace molmesh {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::string volume_mesh_extensions() {
  return ".m .mcsf (FETK MCSF), .vtu (VTK), .msh (Gmsh 2.2), .msh4 (Gmsh 4.1)";
}

void write_volume_mesh(const std::filesystem::path& path, const TetMesh& mesh,
                       const std::vector<PointField>& point_fields) {
  const std::string ext = lower_extension(path);
  if (ext == ".m" || ext == ".mcsf") {
    write_mcsf(path, mesh);
  } else if (ext == ".vtu") {
    write_vtu(path, mesh, point_fields);
  } else if (ext == ".msh") {
    write_gmsh(path, mesh, GmshVersion::v2_2);
  } else if (ext == ".msh4") {
    write_gmsh(path, mesh, GmshVersion::v4_1);
  } else {
    throw Error("cannot tell the volume mesh format of '" + path.string() +
                "' from its extension; use " + volume_mesh_extensions());
  }
}

TetMesh read_volume_mesh(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".m" || ext == ".mcsf") return read_mcsf(path);
  throw InputError(path.string(), "molmesh reads volume meshes only in MCSF (.m, .mcsf)");
}

}  // namespace molmesh
