#include "molmesh/io/hierarchy_hdf5.hpp"

#include <string>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/hdf5_file.hpp"
#include "molmesh/io/hierarchy_layout.hpp"
#include "molmesh/io/hierarchy_probe.hpp"
#include "molmesh/io/hierarchy_xdmf.hpp"

// The entry points. The file's parts each have their home: the HDF5 wrapper (hdf5_file),
// the layout (hierarchy_layout), the checks on read (hierarchy_validate), the child-process
// probe of a file (hierarchy_probe), the XDMF sidecars (hierarchy_xdmf) and the point
// fields (hierarchy_fields.cpp).
namespace molmesh {

void write_hierarchy(const std::filesystem::path& path, const Hierarchy& hierarchy) {
  hdf5::silence_hdf5();
  if (hierarchy.transfers.size() + 1 != hierarchy.levels.size() && !hierarchy.levels.empty()) {
    throw Error("hierarchy has " + std::to_string(hierarchy.levels.size()) + " levels but " +
                std::to_string(hierarchy.transfers.size()) + " transfer operators");
  }
  std::vector<char> image;
  try {
    image = hierarchy_file::hierarchy_image(path, hierarchy);
  } catch (const hdf5::H5Failure& e) {
    throw OutputError(path.string() + ": HDF5: " + e.what());
  }
  hdf5::write_image(path, image);
  try {
    hierarchy_file::write_sidecars(path);
  } catch (const hdf5::H5Failure& e) {
    throw OutputError(path.string() + ": XDMF sidecars: " + e.what());
  }
}

Hierarchy read_hierarchy(const std::filesystem::path& path) {
  hierarchy_file::probe_hierarchy(path);
  return hierarchy_file::read_contents(path);
}

}  // namespace molmesh
