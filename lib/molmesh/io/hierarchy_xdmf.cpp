#include "molmesh/io/hierarchy_xdmf.hpp"

#include <string>
#include <vector>

#include "molmesh/io/hdf5_file.hpp"
#include "molmesh/io/hierarchy_layout.hpp"
#include "molmesh/io/xdmf.hpp"

namespace molmesh::hierarchy_file {
namespace {

using hdf5::dataset_rows;

std::string sidecar_name(const std::filesystem::path& h5, int level, const char* kind) {
  return h5.stem().string() + "_L" + std::to_string(level) + "_" + kind + ".xdmf";
}

// One mesh of a level ("volume" or "surface") as the XDMF sidecars describe it: points,
// cells, and the marker arrays whose lengths match them.
XdmfMesh describe_mesh(hid_t file, int level, const std::string& part, const std::string& cells,
                       const std::string& cell_markers, bool tetrahedra) {
  const std::string base = level_path(level) + "/" + part;
  XdmfMesh mesh;
  mesh.name = "level" + std::to_string(level) + "_" + part;
  mesh.points = base + "/points";
  mesh.cells = base + "/" + cells;
  mesh.tetrahedra = tetrahedra;
  mesh.num_points = dataset_rows(file, mesh.points);
  mesh.num_cells = dataset_rows(file, mesh.cells);
  if (dataset_rows(file, base + "/" + cell_markers) == mesh.num_cells) {
    mesh.attributes.push_back({cell_markers, base + "/" + cell_markers, true, true});
  }
  if (dataset_rows(file, base + "/vertex_markers") == mesh.num_points) {
    mesh.attributes.push_back({"vertex_markers", base + "/vertex_markers", false, true});
  }
  return mesh;
}

}  // namespace

void write_sidecars(const std::filesystem::path& h5) {
  auto [file, levels] = open_unprobed(h5, H5F_ACC_RDONLY);
  const std::string reference = h5.filename().string();
  const auto folder = h5.parent_path();
  std::vector<XdmfMesh> all;
  for (int level = 0; level < levels; ++level) {
    XdmfMesh volume =
        describe_mesh(file.get(), level, "volume", "tetrahedra", "cell_markers", true);
    for (const auto& name : field_names(file.get(), level)) {
      volume.attributes.push_back({name, field_path(level, name), false, false});
    }
    XdmfMesh surface =
        describe_mesh(file.get(), level, "surface", "triangles", "face_markers", false);
    write_xdmf(folder / sidecar_name(h5, level, "volume"), reference, {volume}, false);
    write_xdmf(folder / sidecar_name(h5, level, "surface"), reference, {surface}, false);
    all.push_back(std::move(volume));
    all.push_back(std::move(surface));
  }
  write_xdmf(folder / (h5.stem().string() + ".xdmf"), reference, all, true);
}

}  // namespace molmesh::hierarchy_file
