#pragma once
// XDMF 3 light-data files that point into an HDF5 file's datasets, so ParaView (Xdmf3
// reader) and meshio read meshes stored in a molmesh hierarchy without copying them.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace molmesh {

struct XdmfAttribute {
  std::string name;
  std::string dataset;      // absolute HDF5 path of a 1-D dataset
  bool on_cells = false;    // false: one value per point
  bool is_integer = false;  // int32, else float64
};

struct XdmfMesh {
  std::string name;        // grid name shown by ParaView
  std::string points;      // HDF5 path of an (n, 3) float64 dataset
  std::string cells;       // HDF5 path of an (m, k) int32 dataset
  bool tetrahedra = true;  // k = 4, else triangles (k = 3)
  std::size_t num_points = 0;
  std::size_t num_cells = 0;
  std::vector<XdmfAttribute> attributes;
};

// `h5_reference` is the HDF5 file name as the XDMF file should refer to it (relative to
// the XDMF file's folder, so the pair can be moved together).
std::string xdmf_document(const std::string& h5_reference, const std::vector<XdmfMesh>& meshes,
                          bool as_collection);

// Writes one mesh (as_collection = false) or a spatial collection of meshes, atomically.
void write_xdmf(const std::filesystem::path& path, const std::string& h5_reference,
                const std::vector<XdmfMesh>& meshes, bool as_collection);

}  // namespace molmesh
